#include "candidates/continuation_candidate.h"

namespace curvature_inpaint {

std::vector<CandidateVariation> ContinuationCandidate::Variations(const PatchSite& site,
                                                                  const PatchWork&) const {
  std::vector<CandidateVariation> out;
  for (QImage& image : Inpaint(site.image, site.mask, *site.inpaint))
    out.push_back({std::move(image), {}});
  return out;
}

FakeHoleFill ContinuationCandidate::FillFakeHole(const PatchSite& site, const PatchWork& work,
                                                 size_t amplitude) const {
  return DeformedOrCoarse(site, work.completions.at(amplitude));
}

} // namespace curvature_inpaint
