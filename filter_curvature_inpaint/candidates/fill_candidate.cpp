#include "candidates/fill_candidate.h"

#include "candidates/coarse_candidate.h"
#include "candidates/continuation_candidate.h"
#include "candidates/crease_candidate.h"
#include "candidates/exemplar_candidate.h"
#include "candidates/learned_candidate.h"
#include "candidates/symmetry_candidates.h"
#include "candidates/tri_laplacian_candidate.h"

namespace curvature_inpaint {

const std::vector<const FillCandidate*>& FillCandidates() {
  static const CoarseCandidate coarse;
  static const ContinuationCandidate continuation;
  static const ExemplarCandidate exemplar;
  static const LearnedCandidate learned;
  static const TriLaplacianCandidate tri_laplacian;
  static const SymmetryCandidate symmetry;
  static const SymmetrySurfaceCandidate symmetry_surface;
  static const CreaseCandidate creases;
  static const std::vector<const FillCandidate*> all{&coarse,           &continuation,  &exemplar,
                                                     &learned,          &tri_laplacian, &symmetry,
                                                     &symmetry_surface, &creases};
  return all;
}

PatchWork MakePatchWork(const PatchSite& site,
                        const std::vector<const FillCandidate*>& candidates) {
  CandidateNeeds needs;
  for (const FillCandidate* c : candidates) {
    const CandidateNeeds n = c->Needs();
    needs.mirror = needs.mirror || n.mirror;
    needs.crease = needs.crease || n.crease;
    needs.faired = needs.faired || n.faired;
  }
  const HoleFillParams& params = *site.params;
  PatchWork work;
  if (needs.mirror && site.symmetry)
    work.mirror = std::make_unique<vcg_ext::MirroredFill>(
        MirroredPatch(*site.symmetry, *site.patch, site.frame, params, site.excluded_centre,
                      site.excluded_radius));
  if (needs.crease)
    work.crease = std::make_unique<vcg_ext::CreaseFill>(CreasedPatch(*site.patch, params));
  if (needs.faired) work.faired = std::make_unique<PatchFill>(TriLaplacianPatch(*site.patch));
  return work;
}

std::vector<Eigen::Vector3d> Deformed(const PatchSite& site, const QImage& image) {
  PatchDeformation d = DeformPatch(*site.patch, image, *site.params);
  if (!d.result.solved) return {};
  return std::move(d.points);
}

FakeHoleFill DeformedOrCoarse(const PatchSite& site, const QImage& image) {
  FakeHoleFill f{Deformed(site, image), true};
  if (f.points.empty()) f.points = site.patch->patch.points;
  return f;
}

} // namespace curvature_inpaint
