// Stages 8-9 for one hole, top-down: its variations (the inpainter's continuations and the
// priors' fills), the choice among them (stage 8b, hole_choice.h), and the patch deformed to
// the pick. FillHoles and InpaintHoles schedule the holes; each hole's path is here.
#pragma once

#include "pipeline/hole_fill.h"
#include "validation/hole_choice.h"

#include <string>
#include <vector>

namespace curvature_inpaint {

/// What one hole's path reads; shared by every hole of a run, never written while they run.
struct HoleContext {
  const HoleFillParams* params = nullptr;
  const InpaintParams* inpaint = nullptr; ///< params->inpaint with the run's pool and cancel hook
  ValidationContext validation;           ///< validation.coarse is always given
  /// The variations of a preview to apply instead of asking the backend; null: ask it.
  const std::vector<HoleVariations>* chosen = nullptr;
  /// Make every variation of a hole (a preview, a fill that writes pictures). False: where the
  /// pick is automatic, only those it can take; the others are listed with a null image.
  bool every_variation = true;
};

/// One hole's fill: the record of what it became and why, its variations (for the pictures),
/// and its deformed patch.
struct HoleOutcome {
  HoleFillReport report;
  HoleVariations variations;
  std::vector<Eigen::Vector3d>
      points;         ///< the deformed patch (unit box); empty: keep the coarse fill
  QImage final_image; ///< the deformed patch's curvature image, where params.images_dir is set
};

/// Stages 8-8b for hole `k` (its image `hi`): the variations from the backend, the oracle or
/// the folder a person inpainted in, the fake-hole validation and the pick.
/// Throws std::invalid_argument (a pick the hole does not have, hole_picks of another size),
/// std::runtime_error (the folder's files describe another patch) or InpaintError.
HoleVariations InpaintHole(const HoleImage& hi, size_t k, const HoleContext& ctx);

/// Stages 8-9 for hole `k`: its variations (InpaintHole, or the preview's in ctx.chosen), the
/// pick, and its patch deformed to it or given a prior's surface. Touches nothing shared, so
/// holes can run in parallel. Throws like InpaintHole, and std::runtime_error where a preview
/// does not match the mesh.
HoleOutcome FillOneHole(const HoleImage& hi, size_t k, const HoleContext& ctx);

/// Asks the backend again for one hole (a "re-roll"): new continuations (the embedded backend at
/// the hole's own amplitude, `hole.detail`) and exemplars; the priors' variations stay after
/// them; new scores and the automatic pick.
void InpaintAgain(HoleVariations& hole, const InpaintParams& params);

} // namespace curvature_inpaint
