// The coarse fill as it is (stage 2): the smooth cap every other candidate must beat on the
// fake holes. Never a variation: a hole keeps it with pick 0.
#pragma once

#include "candidates/fill_candidate.h"

namespace curvature_inpaint {

class CoarseCandidate final : public FillCandidate {
public:
  FillKind KindAt(const PatchWork&) const override { return FillKind::kCoarse; }
  bool Enabled(const HoleFillParams& params) const override { return params.validation.coarse; }
  bool IsVariation() const override { return false; }
  std::vector<CandidateVariation> Variations(const PatchSite&, const PatchWork&) const override {
    return {};
  }
  FakeHoleFill FillFakeHole(const PatchSite& site, const PatchWork&, size_t) const override {
    return {site.patch->patch.points, true};
  }
};

} // namespace curvature_inpaint
