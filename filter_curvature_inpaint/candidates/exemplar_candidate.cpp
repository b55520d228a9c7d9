#include "candidates/exemplar_candidate.h"

namespace curvature_inpaint {

std::vector<CandidateVariation> ExemplarCandidate::Variations(const PatchSite& site,
                                                              const PatchWork&) const {
  // As many as the continuations.
  std::vector<CandidateVariation> out;
  for (QImage& image :
       InpaintExemplarVariations(site.image, site.mask, *site.inpaint, site.inpaint->variations))
    out.push_back({std::move(image), {}});
  return out;
}

FakeHoleFill ExemplarCandidate::FillFakeHole(const PatchSite& site, const PatchWork&,
                                             size_t) const {
  const std::vector<QImage> copied =
      InpaintExemplarVariations(site.image, site.mask, *site.inpaint, 1);
  if (copied.empty()) return {site.patch->patch.points, true};
  return DeformedOrCoarse(site, copied[0]);
}

} // namespace curvature_inpaint
