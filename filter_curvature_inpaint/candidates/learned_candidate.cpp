#include "candidates/learned_candidate.h"

#include "inpaint/learned_inpainter.h"

#include <algorithm>

namespace curvature_inpaint {

bool LearnedCandidate::Enabled(const HoleFillParams& params) const {
  if (!params.learned || params.inpaint.backend != Backend::kEmbedded) return false;
  try {
    ShippedUNet();
    return true;
  } catch (const NetworkFileError&) {
    return false;
  }
}

std::vector<CandidateVariation> LearnedCandidate::Variations(const PatchSite& site,
                                                             const PatchWork&) const {
  return {{InpaintLearned(site.image, site.mask, *site.inpaint), {}}};
}

FakeHoleFill LearnedCandidate::FillFakeHole(const PatchSite& site, const PatchWork& work,
                                            size_t) const {
  const std::vector<double>& details = site.params->validation.details;
  const size_t zero = size_t(std::find(details.begin(), details.end(), 0.0) - details.begin());
  const QImage continued =
      zero < work.completions.size()
          ? work.completions[zero]
          : InpaintEmbeddedAmplitudes(site.image, site.mask, *site.inpaint, {0.0}).front();
  return DeformedOrCoarse(site, InpaintLearned(site.image, site.mask, continued));
}

} // namespace curvature_inpaint
