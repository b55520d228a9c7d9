// The creases of a hole's context carried across it: the smooth faces around it extended until
// they meet ("creases"), or inside one smooth face, that face extended ("face";
// vcg_ext/crease_fill.h). A surface prior: on a fake hole without creases it says nothing.
#pragma once

#include "candidates/fill_candidate.h"

namespace curvature_inpaint {

class CreaseCandidate final : public FillCandidate {
public:
  /// Faces meeting at creases, or where no crease runs into the hole, the one face around it.
  FillKind KindAt(const PatchWork& work) const override {
    return work.crease && work.crease->crease_edges == 0 ? FillKind::kFace : FillKind::kCreases;
  }
  bool Enabled(const HoleFillParams& params) const override { return params.creases; }
  CandidateNeeds Needs() const override { return {false, true, false}; }
  bool Applies(const PatchWork& work) const override {
    return work.crease && work.crease->problem.empty();
  }
  bool IsSurfacePrior() const override { return true; }
  std::vector<CandidateVariation> Variations(const PatchSite& site,
                                             const PatchWork& work) const override {
    return {{SurfaceImage(*site.patch, work.crease->points, *site.params), work.crease->points}};
  }
  FakeHoleFill FillFakeHole(const PatchSite&, const PatchWork& work, size_t) const override {
    if (!Applies(work)) return {{}, false};
    return {work.crease->points, true};
  }
};

} // namespace curvature_inpaint
