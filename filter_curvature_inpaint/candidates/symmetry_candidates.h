// The object's mirror image as a prior (symmetry_prior.h): where a hole's mirror image is
// known surface, its curvature ("symmetry", the patch deformed to it) and the mirrored surface
// itself ("symmetry surface"). Surface priors: on a fake hole without a mirror image they say
// nothing.
#pragma once

#include "candidates/fill_candidate.h"

namespace curvature_inpaint {

/// Whether the patch has a mirror image.
inline bool HasMirror(const PatchWork& work) {
  return work.mirror && work.mirror->problem.empty();
}

/// What both mirror candidates share: the mirror image they read, and where they apply.
class MirrorCandidate : public FillCandidate {
public:
  bool Enabled(const HoleFillParams&) const override { return true; }
  CandidateNeeds Needs() const override { return {true, false, false}; }
  bool Applies(const PatchWork& work) const override { return HasMirror(work); }
  bool IsSurfacePrior() const override { return true; }
};

class SymmetryCandidate final : public MirrorCandidate {
public:
  FillKind KindAt(const PatchWork&) const override { return FillKind::kSymmetry; }
  std::vector<CandidateVariation> Variations(const PatchSite& site,
                                             const PatchWork& work) const override {
    return {{SurfaceImage(*site.patch, work.mirror->points, *site.params), {}}};
  }
  /// Where the deformation would fold or cross the patch, it does not apply either.
  FakeHoleFill FillFakeHole(const PatchSite& site, const PatchWork& work, size_t) const override {
    if (!HasMirror(work)) return {{}, false};
    FakeHoleFill f{Deformed(site, SurfaceImage(*site.patch, work.mirror->points, *site.params))};
    f.applies = !f.points.empty();
    return f;
  }
};

class SymmetrySurfaceCandidate final : public MirrorCandidate {
public:
  FillKind KindAt(const PatchWork&) const override { return FillKind::kSymmetrySurface; }
  std::vector<CandidateVariation> Variations(const PatchSite& site,
                                             const PatchWork& work) const override {
    return {{SurfaceImage(*site.patch, work.mirror->points, *site.params), work.mirror->points}};
  }
  FakeHoleFill FillFakeHole(const PatchSite&, const PatchWork& work, size_t) const override {
    if (!HasMirror(work)) return {{}, false};
    return {work.mirror->points, true};
  }
};

} // namespace curvature_inpaint
