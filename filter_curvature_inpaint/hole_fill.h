// The whole method (stages 0-9): coarse fill, curvature images, inpainting, choice of a
// variation, and deformation of each patch to the chosen image. The mesh changes only when
// every stage has succeeded.
#pragma once

#include "curvature_images.h"
#include "ground_truth_image.h"
#include "hole_words.h"
#include "inpaint/inpainter.h"
#include "symmetry_prior.h"

#include <vcg_ext/crease_fill.h>
#include <vcg_ext/curvature_deformation.h>

#include <string>
#include <vector>

namespace curvature_inpaint {

/// The crease prior's settings in the pipeline: a hole with no crease near it still gets the
/// one smooth face around it extended, where there is one ("face"). On the fandisk's
/// development holes inside one curved face (seeds 9019, 9029) that fill validated best and came
/// out at 0.73 and 0.53 of CGAL's RMS, against 1.85 and 1.09; no other of 88 holes changed.
inline vcg_ext::CreaseFillParams PipelineCreaseFill() {
  vcg_ext::CreaseFillParams p;
  p.face_without_crease = true;
  return p;
}

/// Fake-hole validation (embedded backend): each hole is filled the way that came closest to
/// the surface cut out of fake holes of its size near it.
struct ValidationParams {
  int fake_holes = 4;                        ///< per hole; 0: the variation score chooses alone
  bool coarse = true;                        ///< the coarse fill as it is is a candidate
  std::vector<double> details{0, 0.5, 1, 2}; ///< detail amplitudes of the embedded inpainter
  /// Of the fake holes' images (at most the holes'). On the tuning half and 48 development
  /// holes 128 chose as well as 256 (54 of 64 closer than CGAL either way, median RMS ratio
  /// 0.634 against 0.652) at two thirds of the whole process's time on ten holes.
  int image_size = 128;
  /// Where the surface around a hole is this many times flatter than around its fake holes
  /// (the spread of the known ring's mean curvature, times the hole's radius, against the
  /// fake holes' median), they do not show how it fills: it keeps its smooth coarse fill. On
  /// the tuning half and the development holes one hole lies above 4 (rocker_arm_603 at 17,
  /// where the tri-Laplacian validated best and came out 8 times CGAL's RMS); 0: never.
  double max_flatter = 8;
  /// Candidates whose mean error is within this fraction of the lowest tie with it; among
  /// them the detail ratio decides. On the tuning half 0 to 0.1 choose alike (15 of 16 closer
  /// than CGAL); on the 48 development holes 0.1 chose better than 0.02 (41 against 40 closer
  /// than CGAL, median RMS ratio 0.639 against 0.644); 0.15 lost a tuning hole.
  double tie = 0.1;
};

struct HoleFillParams {
  /// The fill's detail amplitude where no validation chooses it: 0, the best fixed amplitude
  /// on the tuning half of bench/holes.tsv (0.5 and 2 were further from the ground truth).
  HoleFillParams() { inpaint.detail = 0; }
  CurvatureImagesParams images;
  InpaintParams inpaint;
  std::string mode = "direct"; ///< "direct" or "paper"
  /// -1: every hole keeps its coarse fill; 0: the best score; k >= 1: variation k of every hole
  int pick = 0;
  /// Non-empty: the first variation of this kind ("creases", ...) of every hole that has one,
  /// the automatic pick elsewhere (benchmarks: what a prior does where it applies).
  std::string pick_kind;
  /// Per hole, by the holes' numbers (those of `preview` and the report), instead of `pick` and
  /// `pick_kind`: 0 the automatic pick, -1 the coarse fill, k >= 1 variation k. Empty, or one
  /// entry per hole (FillHoles throws std::invalid_argument otherwise).
  std::vector<int> hole_picks;
  vcg_ext::DirectDeformationParams direct;
  vcg_ext::PaperDeformationParams paper;
  ValidationParams validation;
  /// The object's mirror image as a prior: each hole whose mirror image is known surface gets
  /// two more variations, its mirrored curvature ("symmetry") and the mirrored surface itself
  /// ("symmetry surface"), which the fake-hole validation weighs against the rest.
  SymmetryPriorParams symmetry;
  /// Embedded backend: as many more variations from the exemplar inpainter ("exemplar",
  /// patches of the known region copied in, ridges and valleys first), validated like the rest.
  /// Off by default: on the tuning half of bench/holes.tsv the validation chose it on one hole
  /// (koala_503), which it filled 1.3 times as far from the truth as the fill without it.
  bool exemplar = false;
  /// Each hole that creases of its context run into gets one more variation: the context's
  /// smooth faces extended across it until they meet ("creases", vcg_ext/crease_fill.h); a
  /// hole with no crease near it, inside one smooth face, that face extended ("face").
  bool creases = true;
  /// Each hole gets one more variation: its fill faired to continue the curvature of the
  /// surface around it, not only its tangents ("tri-laplacian"; validated like the rest).
  bool tri_laplacian = true;
  vcg_ext::CreaseFillParams crease_fill = PipelineCreaseFill();
  std::string images_dir; ///< where to write every hole's images; empty: nowhere
  /// Instead of a backend: the folder where the Curvature Images stage wrote hole_<k>.json and
  /// a person (in any image editor) left hole_<k>_inpainted.png. The patches are rebuilt with
  /// the same parameters and must match the JSON files.
  std::string inpainted_dir;
  /// Instead of a backend: the ground truth's own curvature image of every hole (the
  /// benchmark's oracle, see ground_truth_image.h). Not owned.
  const GroundTruthOracle* oracle = nullptr;
  /// Measure the curvature spread of each hole's target and result (for the report).
  bool measure_detail = false;
};

struct HoleFillReport {
  int hole = 0; ///< index into the coarse result's holes
  int boundary_edges = 0;
  int new_vertices = 0;
  std::vector<double> scores;     ///< per variation: higher is better
  std::vector<std::string> kinds; ///< per variation (see HoleVariations::kinds)
  int pick = 0;                   ///< 1-based
  int iterations = 0;             ///< deformation solves (direct) or steps (paper)
  int backoffs = 0;           ///< halvings towards the coarse fill that undid a fold or crossing
  std::string kind;           ///< of the variation picked (see HoleVariations::kinds)
  int crease_flips = 0;       ///< fill edges flipped onto the fill's creases
  std::vector<int> differing; ///< paper mode: differing vertices per step
  double max_move = 0;        ///< unit-box units
  /// Wall time per stage; `validation_s` is the fake holes' (stage 8's choice), `inpaint_s`
  /// the rest of stage 8.
  double coarse_s = 0, images_s = 0, validation_s = 0, inpaint_s = 0, deform_s = 0;
  /// Curvature spread (standard deviation over the fill, unit-box curvature) of what the
  /// chain carries, when measured: the ground truth and its image (oracle only, else 0), the
  /// target at the fill's vertices and the deformed fill's APSS curvature.
  GroundTruthSpread truth_spread;
  double target_spread = 0, result_spread = 0;
  std::vector<std::string> candidates;   ///< validated ways to fill it; empty: not validated
  std::vector<double> validation_errors; ///< per candidate: RMS over the fake holes / radius
  /// per candidate: detail ratio on the fake holes where it breaks a tie, else -1
  std::vector<double> validation_detail;
  int choice = -1; ///< index into candidates
  int fake_holes = 0;
  int mirror_fake_holes = 0; ///< of those, cut at the hole's mirror place
  /// Per fake hole (those at the mirror place last): each candidate's RMS / radius there.
  std::vector<std::vector<double>> fake_hole_errors;
  std::string validation_note;            ///< why there are fewer fake holes, or none
  std::string symmetry_note, crease_note; ///< why it has no such variation; empty if it has
  std::string pick_note; ///< why the kind asked for was not picked; empty if it was
  /// Where the hole has a mirror image: the share of its fill that the image covers and the
  /// mirrored ring's distance from the ring after their rigid registration (RMS, hole radii);
  /// -1 where it has none.
  double mirror_covered = -1, mirror_ring_residual = -1;
  std::string problem; ///< why the hole kept its coarse fill; empty if none
  bool asked = false;  ///< the pick was asked for (a number or a kind), not automatic
};

/// One hole's inpainting (stages 3-8) as a person previews it and FillHoles applies it.
struct HoleVariations {
  QImage image, mask; ///< the coarse curvature image and its hole (white)
  /// The backend's completions of `image` ("continuation"), then the priors' variations.
  std::vector<QImage> variations;
  /// Per variation: "continuation", "exemplar", "symmetry", "symmetry surface", "creases",
  /// "face" or "tri-laplacian".
  std::vector<std::string> kinds;
  /// Per variation: empty where the patch is deformed to the image's curvature, else the
  /// patch (unit box) the hole takes as it is ("symmetry surface").
  std::vector<std::vector<Eigen::Vector3d>> surfaces;
  std::vector<double> scores;     ///< ScoreVariation of each
  int pick = 0;                   ///< 1-based; 0: the hole keeps its coarse fill
  std::string problem;            ///< why there is nothing to choose from; empty if none
  GroundTruthSpread truth_spread; ///< with the oracle: the ground truth's and its image's
  double detail_scale = 0;        ///< the fill's vertex spacing in the image, pixels
  double detail = 0; ///< embedded: the amplitude the variations have (validated, or given)
  /// Fake-hole validation, as in HoleFillReport; pick is 0 where "coarse" validated best.
  std::vector<std::string> candidates;
  std::vector<double> validation_errors, validation_detail;
  int choice = -1;
  int fake_holes = 0, mirror_fake_holes = 0;
  std::vector<std::vector<double>> fake_hole_errors;
  std::string validation_note;
  std::string symmetry_note; ///< why the hole has no symmetry variation; empty if it has
  std::string crease_note;   ///< why the hole has no crease variation; empty if it has
  std::string pick_note;     ///< why the kind asked for was not picked; empty if it was
  double mirror_covered = -1, mirror_ring_residual = -1; ///< as in HoleFillReport
  double images_s = 0, validation_s = 0, inpaint_s = 0;  ///< as in HoleFillReport
  int boundary_edges = 0;                                ///< of the hole
  bool asked = false; ///< the pick was asked for (a number or a kind), not automatic
};

struct HoleFillResult {
  vcg_ext::CoarseFillResult coarse;
  std::vector<HoleFillReport> holes;
  bool symmetry_detected = false;                       ///< the prior ran (some hole needed it)
  std::vector<vcg_ext::SymmetryPlane> symmetry;         ///< the planes it found
  std::vector<vcg_ext::SymmetryPlane> symmetry_partial; ///< the partial symmetries it found
  vcg_ext::SymmetryPlane symmetry_best;                 ///< the best-covering plane, found or not
  double symmetry_s = 0;
};

/// Throws vcg_ext::InvalidParameterError naming the first parameter out of its range.
void CheckHoleFillParams(const HoleFillParams& params);

/// A run of variations of one kind with the same picture (the continuations at detail 0),
/// which the montage and the dialog show once.
struct VariationRun {
  int first = 0, last = 0; ///< 0-based
  std::string kind;
};
std::vector<VariationRun> VariationRuns(const HoleVariations& hole);

/// Whether FillHoles and InpaintHoles validate each hole on fake holes with these parameters
/// (the embedded backend, fake holes asked for, no oracle and no hand-inpainted folder).
bool ValidatesOnFakeHoles(const HoleFillParams& params);

/// Whether the fake holes found the hole's coarse fill closest (then the automatic pick is 0).
bool CoarseValidatedBest(const HoleVariations& hole);

/// The automatic pick (1-based; 0: keep the coarse fill): the validated choice where it is a
/// prior's variation or the coarse fill, else the best-scored continuation.
int AutomaticPick(const HoleVariations& hole);

/// Fills the holes of `m` with detail. With `chosen` (from InpaintHoles on a copy of `m` with
/// the same parameters, picks possibly changed) the backend is not asked again: each hole is
/// deformed to its chosen variation, or keeps its coarse fill where the pick is 0. Throws
/// InvalidMeshError, InvalidParameterError (before anything else), InpaintError (a backend
/// failed), CancelledError or std::runtime_error
/// (also when `chosen` does not match the holes), with `m` exactly as it was. `cb` (MeshLab's
/// callback: progress, and a stop asked for) is called on this thread only.
HoleFillResult FillHoles(CMeshO& m, const HoleFillParams& params, vcg::CallBackPos* cb = nullptr,
                         const std::vector<HoleVariations>* chosen = nullptr);

/// Stages 0-8 for a preview: fills the holes of `scratch` coarsely (pass a copy of the mesh;
/// it is changed) and returns every hole's curvature image with its scored variations and the
/// automatic pick (params.pick when given). The holes run in parallel as FillHoles runs them
/// (the same bytes for any thread count); `cb` is called on this thread only. Throws like
/// FillHoles.
std::vector<HoleVariations> InpaintHoles(CMeshO& scratch, const HoleFillParams& params,
                                         vcg::CallBackPos* cb = nullptr);

/// Writes a preview's pictures into `dir` (made if missing), under the names `fill --images`
/// uses: per hole with variations hole_<k>_coarse.png, hole_<k>_mask.png and
/// hole_<k>_variation_<j>.png, and montage.png with a row per hole, its pick framed. Throws
/// std::runtime_error naming a file that cannot be written. `threads`: holes written at once
/// (0: one per core).
void SaveVariationImages(const std::vector<HoleVariations>& holes, const std::string& dir,
                         int threads = 0);

/// Per hole of a preview: its validation line (as in the fill's log), then its variations by
/// number and kind with their scores and the pick fill makes with the same options, or why it
/// has none.
std::vector<std::string> DescribeVariations(const std::vector<HoleVariations>& holes);

/// Asks the backend again for one hole (a "re-roll"): new variations (the embedded backend at
/// the hole's own amplitude, `hole.detail`), scores and the automatic pick.
void InpaintAgain(HoleVariations& hole, const InpaintParams& params);

/// Scores a variation without ground truth (higher is better): how continuously the value
/// field crosses the hole's border, how close the hole's colours stay to the palette, and how
/// far its values leave the known ring's range.
double ScoreVariation(const QImage& variation, const QImage& mask);

/// One line on a hole's fake-hole validation: the candidates' errors and the choice, or why
/// it was not validated.
std::string DescribeValidation(const std::vector<std::string>& candidates,
                               const std::vector<double>& errors, int choice, int fake_holes,
                               int mirror_fake_holes, const std::string& note);

std::vector<std::string> DescribeHoleFill(const HoleFillResult& result);

/// One line per hole in words, "hole 3 (61 edges): the mirror image of the other side, better
/// than the smooth fill on 4 of 4 test cuts"; the numbers are DescribeHoleFill's.
std::vector<std::string> DescribeHolesInWords(const HoleFillResult& result);

/// The facts of a hole's choice, for the words of hole_words.h.
ChoiceFacts FactsOf(const HoleFillReport& hole);
ChoiceFacts FactsOf(const HoleVariations& hole);

/// The report as JSON (no keys, no URLs with credentials).
std::string HoleFillReportJson(const HoleFillResult& result, const HoleFillParams& params);

} // namespace curvature_inpaint
