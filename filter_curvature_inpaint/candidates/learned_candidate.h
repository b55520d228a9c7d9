// The learned inpainter's completion (inpaint/learned_inpainter.h): the embedded continuation
// corrected by the network trained on curvature images of public meshes. Offline, and the same
// for every seed; the embedded backend only.
#pragma once

#include "candidates/fill_candidate.h"

namespace curvature_inpaint {

class LearnedCandidate final : public FillCandidate {
public:
  FillKind KindAt(const PatchWork&) const override { return FillKind::kLearned; }
  /// Off where the build ships no network (the one line that says why is ShippedUNet's).
  bool Enabled(const HoleFillParams& params) const override;
  std::vector<CandidateVariation> Variations(const PatchSite& site,
                                             const PatchWork&) const override;
  /// From the validation's continuation at amplitude 0 where it made one.
  FakeHoleFill FillFakeHole(const PatchSite& site, const PatchWork& work, size_t) const override;
};

} // namespace curvature_inpaint
