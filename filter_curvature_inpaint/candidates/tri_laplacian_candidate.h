// The fill faired once more so that it continues the curvature of the surface around it, not
// only its tangents (TriLaplacianPatch).
#pragma once

#include "candidates/fill_candidate.h"

namespace curvature_inpaint {

class TriLaplacianCandidate final : public FillCandidate {
public:
  FillKind KindAt(const PatchWork&) const override { return FillKind::kTriLaplacian; }
  bool Enabled(const HoleFillParams& params) const override { return params.tri_laplacian; }
  CandidateNeeds Needs() const override { return {false, false, true}; }
  bool Applies(const PatchWork& work) const override {
    return work.faired && work.faired->problem.empty();
  }
  std::vector<CandidateVariation> Variations(const PatchSite& site,
                                             const PatchWork& work) const override {
    return {{SurfaceImage(*site.patch, work.faired->points, *site.params), work.faired->points}};
  }
  /// Where the system cannot be solved on a fake hole, the coarse fill.
  FakeHoleFill FillFakeHole(const PatchSite& site, const PatchWork& work, size_t) const override {
    return {Applies(work) ? work.faired->points : site.patch->patch.points, true};
  }
};

} // namespace curvature_inpaint
