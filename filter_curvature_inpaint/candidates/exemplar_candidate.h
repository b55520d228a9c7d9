// Patches of the scan's own curvature copied into the hole, ridges and valleys first
// (vcg_ext/exemplar_inpainting.h); the embedded backend only, when asked for.
#pragma once

#include "candidates/fill_candidate.h"

namespace curvature_inpaint {

class ExemplarCandidate final : public FillCandidate {
public:
  FillKind KindAt(const PatchWork&) const override { return FillKind::kExemplar; }
  bool Enabled(const HoleFillParams& params) const override {
    return params.exemplar && params.inpaint.backend == Backend::kEmbedded;
  }
  bool Seeded() const override { return true; }
  /// Fewer than asked for where the known region has no patch to copy.
  int VariationCount(const PatchSite&) const override { return -1; }
  std::vector<CandidateVariation> Variations(const PatchSite& site,
                                             const PatchWork&) const override;
  FakeHoleFill FillFakeHole(const PatchSite& site, const PatchWork&, size_t) const override;
};

} // namespace curvature_inpaint
