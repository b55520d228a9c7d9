// The records of one hole's fill, each fact in one place: what the fake holes showed, why a
// prior has nothing to offer, what was picked and why, how long each stage took. The preview
// (HoleVariations) and the fill's report (HoleFillReport) embed the same records.
#pragma once

#include "candidates/fill_kind.h"

#include <string>
#include <vector>

namespace curvature_inpaint {

/// Stage 8b's evidence: each candidate's error on fake holes cut near the hole, and the one
/// chosen.
struct ValidationRecord {
  std::vector<TriedFill> candidates; ///< validated ways to fill it; empty: not validated
  std::vector<double> errors;        ///< per candidate: RMS over the fake holes / radius
  std::vector<double> detail;        ///< per candidate: detail ratio where it broke a tie, else -1
  /// Per fake hole (those at the mirror place last): each candidate's RMS / radius there.
  std::vector<std::vector<double>> per_fake_hole;
  int chosen = -1; ///< index into candidates
  /// The candidate that did best on the fake holes but not clearly better than the smooth
  /// fill, which the hole then keeps (`chosen`); -1: none.
  int not_clear = -1;
  /// No fake hole could be cut or filled near the hole: with no evidence it keeps the smooth
  /// fill (`note` says why).
  bool no_evidence = false;
  int fake_holes = 0;
  int mirror_fake_holes = 0; ///< of those, cut at the hole's mirror place
  std::string note;          ///< why there are fewer fake holes, or none

  /// Whether a candidate was chosen (`chosen` indexes `candidates`).
  bool HasChoice() const { return chosen >= 0 && size_t(chosen) < candidates.size(); }
  /// The candidate chosen. \pre HasChoice().
  const TriedFill& Chosen() const { return candidates[size_t(chosen)]; }
};

/// What the priors found for a hole: why it has no such variation (empty if it has one), and
/// how well its mirror image fits where it has one.
struct PriorNotes {
  std::string no_symmetry, no_creases;
  /// Crease lines of the known surface reach the hole from two sides or more
  /// (vcg_ext/hole_creases.h): only there are the fill's edges flipped onto creases.
  bool has_creases = false;
  /// The share of the fill that the mirror image covers and the mirrored ring's distance from
  /// the ring after their rigid registration (RMS, hole radii); -1 where it has none.
  double mirror_covered = -1, mirror_ring_residual = -1;
};

/// The pick among a hole's variations and why.
struct HoleChoice {
  std::vector<FillKind> kinds; ///< per variation (never kCoarse)
  std::vector<double> scores;  ///< per variation: ScoreVariation, higher is better
  int pick = 0;                ///< 1-based; 0: the hole keeps its coarse fill
  bool asked = false;          ///< the pick was asked for (a number or a kind), not automatic
  std::string pick_note;       ///< why the kind asked for was not picked; empty if it was
  std::string problem;         ///< why the hole kept its coarse fill; empty if it did not
  ValidationRecord validation;
  PriorNotes priors;

  /// The kind of the variation picked; kCoarse where the hole keeps its coarse fill.
  FillKind PickedKind() const;
};

/// Wall time per stage for one hole, seconds. `validation` is the fake holes' (stage 8b),
/// `inpaint` the rest of stage 8.
struct StageSeconds {
  double coarse = 0, images = 0, validation = 0, inpaint = 0, deform = 0;
};

} // namespace curvature_inpaint
