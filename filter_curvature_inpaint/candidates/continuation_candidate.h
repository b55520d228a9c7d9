// The backend's completions of the curvature image (stage 8; the embedded inpainter, a service,
// the oracle or a person's image): the paper's own variations. Validated as the embedded
// inpainter at each detail amplitude, one candidate each ("detail 0.5").
#pragma once

#include "candidates/fill_candidate.h"

namespace curvature_inpaint {

class ContinuationCandidate final : public FillCandidate {
public:
  FillKind KindAt(const PatchWork&) const override { return FillKind::kContinuation; }
  bool Enabled(const HoleFillParams&) const override { return true; }
  std::vector<double> ValidatedAmplitudes(const HoleFillParams& params) const override {
    return params.validation.details;
  }
  bool Seeded() const override { return true; }
  /// The embedded inpainter's, as many as asked for; a service's, as many as it sends.
  int VariationCount(const PatchSite& site) const override {
    return site.inpaint->backend == Backend::kEmbedded ? site.inpaint->variations : -1;
  }
  std::vector<CandidateVariation> Variations(const PatchSite& site,
                                             const PatchWork&) const override;
  FakeHoleFill FillFakeHole(const PatchSite& site, const PatchWork& work,
                            size_t amplitude) const override;
};

} // namespace curvature_inpaint
