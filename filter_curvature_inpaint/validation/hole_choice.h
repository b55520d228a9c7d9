// Stage 8b: the choice of a hole's fill. Each candidate (the coarse fill, the embedded
// inpainter at each detail amplitude, the priors the hole has) fills fake holes of the hole's
// size cut into known surface near it (fake_holes.h) and is scored against the surface cut
// out; the one that validated best is the hole's choice where it is clearly better than the
// smooth fill, which the hole keeps otherwise, and where no fake hole could be filled. Where
// the validation is off, the variations' scores choose. A prior's variation is picked only
// where it validated best.
#pragma once

#include "candidates/fill_candidate.h"
#include "candidates/symmetry_prior.h"
#include "pipeline/curvature_images.h"
#include "pipeline/hole_fill.h"

#include <vcg_ext/coarse_fill.h>
#include <vcg_ext/hole_segmentation.h>

#include <functional>
#include <string>
#include <vector>

namespace curvature_inpaint {

/// What the validation reads of the mesh being filled (never written while holes run).
struct ValidationContext {
  const CMeshO* mesh = nullptr;
  const vcg_ext::CoarseFillResult* coarse = nullptr; ///< the holes' coarse fills (always given)
  const vcg_ext::VertexFaces* vf = nullptr;          ///< null where no hole is validated
  const SymmetryPrior* symmetry = nullptr;           ///< null where the prior is off
  int threads = 1; ///< for one hole's fake holes: what the holes in parallel leave over
  /// Asked between two candidates' fills, on any thread: true where the user asked to stop
  /// (the hole's path then throws vcg_ext::CancelledError). Null: never.
  std::function<bool()> stop_asked;
};

/// Throws vcg_ext::CancelledError where ctx.stop_asked says the user asked to stop.
void StopIfAsked(const ValidationContext& ctx);

/// Whether FillHoles and InpaintHoles validate each hole on fake holes with these parameters
/// (the embedded backend, fake holes asked for, no oracle and no hand-inpainted folder).
bool ValidatesOnFakeHoles(const HoleFillParams& params);

/// Validates hole `hi` on fake holes near it: every candidate (FillCandidates()) that the
/// parameters turn on and the hole itself has (`hole`: its shared work, MakePatchWork), the
/// continuation at each detail amplitude, fills each fake hole and is scored against the
/// surface cut out. Returns the candidates, their errors and the choice: the best validated
/// where it is clearly better than the smooth fill (ClearlyBetter), else the smooth fill
/// (`not_clear` then names the best); `no_evidence`, with a note and no candidates, where no
/// fake hole could be filled.
/// \pre ctx.mesh, ctx.coarse and ctx.vf are given; ValidatesOnFakeHoles(params).
ValidationRecord ValidateHole(const HoleImage& hi, const HoleFillParams& params,
                              const InpaintParams& inpaint, const ValidationContext& ctx,
                              const PatchWork& hole);

/// Scores a variation without ground truth (higher is better): how continuously the value
/// field crosses the hole's border, how close the hole's colours stay to the palette, and how
/// far its values leave the known ring's range.
double ScoreVariation(const QImage& variation, const QImage& mask);

/// Whether the fake holes show candidate `c` clearly closer than the smooth fill `smooth`
/// (`per_fake_hole`: each candidate's error on each fake hole): closer on the fake holes that
/// hold at least vp.min_win_share of the smooth fill's error. A candidate that wins only where
/// every fill comes close, and loses where the smooth fill is far off, is not trusted with the
/// hole. Fake holes that both fill exactly (a flat face) do not count.
/// \pre every row of per_fake_hole has entries c and smooth.
bool ClearlyBetter(const std::vector<std::vector<double>>& per_fake_hole, size_t c, size_t smooth,
                   const ValidationParams& vp);

/// Whether the fake holes found the hole's coarse fill closest (then the automatic pick is 0).
bool CoarseValidatedBest(const HoleChoice& choice);

/// The automatic pick (1-based; 0: keep the coarse fill): the validated choice where it is a
/// prior's variation or the coarse fill, the coarse fill where the validation had no evidence,
/// else the best-scored continuation.
int AutomaticPick(const HoleChoice& choice);

/// Whether the automatic pick can take a variation of kind `kind` of a hole
/// whose validation, where it ran, is in `choice`: none where it keeps the smooth fill, the
/// validated prior's where it chose a prior, else a continuation. A fill makes only those.
bool AutomaticPickCanTake(const HoleChoice& choice, FillKind kind);

/// Scores every variation of `hole` and picks: variation `pick` (1-based) where given, else the
/// first of kind `pick_kind` where given (not kCoarse) and the hole has one (a note says so
/// where not),
/// else the automatic pick. A variation listed but not made (a null image) scores NaN.
/// \pre pick <= the number of variations; the variation picked is made.
void PickVariation(HoleVariations& hole, int pick, FillKind pick_kind);

} // namespace curvature_inpaint
