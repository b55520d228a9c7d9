// The ways to fill a patch, behind one interface: the coarse fill, the inpainter's
// continuations and exemplars, and the priors (the tri-Laplacian fill, the mirror image's
// curvature and surface, the creases). A hole's variations, its fake-hole validation
// (hole_choice.h), the dialog's list, the report and `--pick` go through FillCandidates()
// without knowing them. A new way to fill is one class in one file of this folder and one
// line in FillCandidates().
#pragma once

#include "candidates/fill_kind.h"
#include "candidates/patch_fills.h"
#include "candidates/symmetry_prior.h"
#include "pipeline/curvature_images.h"
#include "pipeline/hole_fill.h"

#include <QImage>

#include <memory>
#include <string>
#include <vector>

namespace curvature_inpaint {

/// Where a candidate fills: a hole of the mesh, or a fake hole cut near one.
struct PatchSite {
  const HoleImage* patch = nullptr;
  const HoleFillParams* params = nullptr;  ///< a fake hole's: deformed in direct mode
  const InpaintParams* inpaint = nullptr;  ///< at the patch's vertex spacing
  QImage image, mask;                      ///< the patch's curvature image and its hole
  const SymmetryPrior* symmetry = nullptr; ///< null: the run looks for no mirror image
  vcg_ext::UnitBox frame;                  ///< the patch's unit box
  /// A fake hole: its own surface (mesh units), left out of its mirror image.
  Eigen::Vector3d excluded_centre = Eigen::Vector3d::Zero();
  double excluded_radius = 0;
};

/// What the candidates of one patch share, each made once where a candidate reads it.
struct PatchWork {
  std::unique_ptr<vcg_ext::MirroredFill> mirror; ///< where the run has mirror planes
  std::unique_ptr<vcg_ext::CreaseFill> crease;
  std::unique_ptr<PatchFill> faired;
  /// A fake hole's: the embedded inpainter's completion at each validated amplitude (made by the
  /// validation, which knows the amplitudes).
  std::vector<QImage> completions;
};

/// What a candidate reads of PatchWork.
struct CandidateNeeds {
  bool mirror = false, crease = false, faired = false;
};

/// One variation a candidate offers a hole: the curvature to deform its patch to, and where
/// the hole takes a surface as it is, that surface (unit box; its curvature is the image).
struct CandidateVariation {
  QImage image;
  std::vector<Eigen::Vector3d> surface;
};

/// A candidate's fill of a fake hole.
struct FakeHoleFill {
  std::vector<Eigen::Vector3d> points; ///< the whole patch, unit box
  bool applies = true; ///< false: a surface prior with nothing to say there (points unset)
};

/// One way to fill a patch.
class FillCandidate {
public:
  virtual ~FillCandidate() = default;
  /// Its kind at a patch (the crease prior's depends on the patch: creases, or one face).
  virtual FillKind KindAt(const PatchWork& work) const = 0;
  /// Whether these parameters turn it on.
  virtual bool Enabled(const HoleFillParams& params) const = 0;
  virtual CandidateNeeds Needs() const { return {}; }
  /// Whether the patch has this fill (a prior where its fill could be made).
  virtual bool Applies(const PatchWork&) const { return true; }
  /// A prior that says nothing where it does not apply: on such a fake hole the validation
  /// lets it stand for the best of the other candidates.
  virtual bool IsSurfacePrior() const { return false; }
  /// Whether its variations change with the inpainter's seed: a re-roll asks it again. Its
  /// Variations then read only the site's image, mask and inpaint.
  virtual bool Seeded() const { return false; }
  /// Whether a hole gets it as a variation (the coarse fill is pick 0 instead).
  virtual bool IsVariation() const { return true; }
  /// The amplitudes it is validated at, one candidate each (the continuation's detail
  /// amplitudes); empty: once.
  virtual std::vector<double> ValidatedAmplitudes(const HoleFillParams&) const { return {}; }
  /// How many variations Variations() makes of a hole, known without making them; -1 where only
  /// making them tells. A fill that lists the variations its pick cannot take, without making
  /// them, needs it.
  virtual int VariationCount(const PatchSite&) const { return 1; }
  /// Its variations of a hole (images from `inpaint`, at the hole's amplitude and spacing).
  /// \pre Applies(work).
  virtual std::vector<CandidateVariation> Variations(const PatchSite& site,
                                                     const PatchWork& work) const = 0;
  /// Its fill of a fake hole, at amplitude index `amplitude` where it has amplitudes. A fill
  /// that fails falls back to the coarse fill.
  virtual FakeHoleFill FillFakeHole(const PatchSite& site, const PatchWork& work,
                                    size_t amplitude) const = 0;
};

/// Every candidate, in the order of the variations and of the validation's report.
const std::vector<const FillCandidate*>& FillCandidates();

/// The shared work of a patch for `candidates` (PatchWork), each piece made once.
PatchWork MakePatchWork(const PatchSite& site, const std::vector<const FillCandidate*>& candidates);

/// The patch deformed to `image` (site.params' mode); empty where that would fold or cross it.
std::vector<Eigen::Vector3d> Deformed(const PatchSite& site, const QImage& image);

/// The patch deformed to `image`, or the coarse fill where that would fold or cross it.
FakeHoleFill DeformedOrCoarse(const PatchSite& site, const QImage& image);

} // namespace curvature_inpaint
