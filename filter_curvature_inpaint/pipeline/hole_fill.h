// The whole method (stages 0-9): coarse fill, curvature images, inpainting, choice of a
// variation, and deformation of each patch to the chosen image. The mesh changes only when
// every stage has succeeded.
#pragma once

#include "candidates/symmetry_prior.h"
#include "inpaint/inpainter.h"
#include "pipeline/curvature_images.h"
#include "pipeline/ground_truth_image.h"
#include "pipeline/hole_records.h"
#include "report/hole_words.h"

#include <vcg_ext/crease_fill.h>
#include <vcg_ext/curvature_deformation.h>

#include <string>
#include <vector>

namespace curvature_inpaint {

/// The crease prior's settings in the pipeline: a hole with no crease near it still gets the
/// one smooth face around it extended, where there is one ("face"): inside one curved face it
/// validates best (docs/experiments.md, "The figures behind the defaults").
inline vcg_ext::CreaseFillParams PipelineCreaseFill() {
  vcg_ext::CreaseFillParams p;
  p.face_without_crease = true;
  return p;
}

/// How a patch is deformed to its curvature image (stage 9).
enum class DeformationMode {
  kDirect, ///< "direct": a few solves; a round that would fold the patch is not taken
  kPaper,  ///< "paper": the paper's steps
};

/// The mode's name at the edges (the command line, the dialog, the report).
const char* DeformationModeName(DeformationMode mode);

/// The mode a name stands for; false for a name no mode has.
bool DeformationModeFromName(const std::string& name, DeformationMode* mode);

/// Fake-hole validation (embedded backend): each hole is filled the way that came closest to
/// the surface cut out of fake holes of its size near it.
struct ValidationParams {
  int fake_holes = 4;                        ///< per hole; 0: the variation score chooses alone
  bool coarse = true;                        ///< the coarse fill as it is is a candidate
  std::vector<double> details{0, 0.5, 1, 2}; ///< detail amplitudes of the embedded inpainter
  /// Of the fake holes' images (at most the holes'): the smallest that chooses as well as 256,
  /// for less time (docs/experiments.md, "The figures behind the defaults").
  int image_size = 128;
  /// Where the surface around a hole is this many times flatter than around its fake holes
  /// (the spread of the known ring's mean curvature, times the hole's radius, against the
  /// fake holes' median), they do not show how it fills: it keeps its smooth coarse fill
  /// (docs/experiments.md, "The figures behind the defaults"). 0: never.
  double max_flatter = 8;
  /// Candidates whose mean error is within this fraction of the lowest tie with it; among
  /// them the detail ratio decides: four fake holes cannot tell a few per cent apart
  /// (docs/experiments.md, "The figures behind the defaults").
  double tie = 0.1;
  /// A candidate other than the smooth fill replaces it only where it is closer on the fake
  /// holes that hold at least this share of the smooth fill's error: where the smooth fill
  /// does well, any fill does, and a win there says little about the hole (docs/experiments.md,
  /// "2026-12-07: A choice that knows how sure it is").
  double min_win_share = 0.5;
};

struct HoleFillParams {
  /// The fill's detail amplitude where no validation chooses it: 0, the best fixed amplitude
  /// on the tuning half (docs/experiments.md, "The figures behind the defaults").
  HoleFillParams() { inpaint.detail = 0; }
  CurvatureImagesParams images;
  InpaintParams inpaint;
  DeformationMode mode = DeformationMode::kDirect;
  /// -1: every hole keeps its coarse fill; 0: the best score; k >= 1: variation k of every hole
  int pick = 0;
  /// The first variation of this kind of every hole that has one, the automatic pick
  /// elsewhere (benchmarks: what a prior does where it applies). kCoarse: no kind asked (the
  /// coarse fill is `pick` -1).
  FillKind pick_kind = FillKind::kCoarse;
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
  /// Off by default: where the validation chose it, it filled further from the truth than the
  /// fill without it (docs/experiments.md, "The figures behind the defaults").
  bool exemplar = false;
  /// Embedded backend: one more variation, the continuation corrected by the network trained on
  /// public meshes ("learned", inpaint/learned_inpainter.h), validated like the rest. Off by
  /// default: offered to the validation, it left the fills of the corpus's check part a little
  /// farther from the truth (docs/experiments.md, "The learned inpainter as a candidate").
  bool learned = false;
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

/// Stage 9's record for one hole.
struct DeformationRecord {
  int iterations = 0;         ///< deformation solves (direct) or steps (paper)
  int backoffs = 0;           ///< halvings towards the coarse fill that undid a fold or crossing
  std::vector<int> differing; ///< paper mode: differing vertices per step
  double max_move = 0;        ///< unit-box units
};

/// What the fill did with one hole, and why.
struct HoleFillReport {
  int hole = 0; ///< index into the coarse result's holes
  int boundary_edges = 0;
  int new_vertices = 0;
  HoleChoice choice;
  /// The kind of the variation its patch took (also where the deformation then failed and the
  /// hole kept its coarse fill); kCoarse where it never got that far.
  FillKind kind = FillKind::kCoarse;
  DeformationRecord deformation;
  int crease_flips = 0; ///< fill edges flipped onto the fill's creases
  StageSeconds seconds;
  /// Curvature spread (standard deviation over the fill, unit-box curvature) of what the
  /// chain carries, when measured: the ground truth and its image (oracle only, else 0), the
  /// target at the fill's vertices and the deformed fill's APSS curvature.
  GroundTruthSpread truth_spread;
  double target_spread = 0, result_spread = 0;
};

/// One hole's inpainting (stages 3-8b) as a person previews it and FillHoles applies it.
struct HoleVariations {
  QImage image, mask; ///< the coarse curvature image and its hole (white)
  /// The backend's completions of `image` ("continuation"), then the priors' variations; their
  /// kinds, scores and the pick are in `choice`. A null image: listed, not made (a fill makes
  /// only what its automatic pick can take).
  std::vector<QImage> variations;
  /// Per variation: empty where the patch is deformed to the image's curvature, else the
  /// patch (unit box) the hole takes as it is ("symmetry surface").
  std::vector<std::vector<Eigen::Vector3d>> surfaces;
  HoleChoice choice;              ///< pick 0 also where the coarse fill validated best
  GroundTruthSpread truth_spread; ///< with the oracle: the ground truth's and its image's
  double detail_scale = 0;        ///< the fill's vertex spacing in the image, pixels
  double detail = 0;      ///< embedded: the amplitude the variations have (validated, or given)
  StageSeconds seconds;   ///< images, validation and inpaint
  int boundary_edges = 0; ///< of the hole
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
  FillKind kind = FillKind::kContinuation;
};
std::vector<VariationRun> VariationRuns(const HoleVariations& hole);

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

/// Asks the backend again for one hole (a "re-roll"): new variations (the embedded backend at
/// the hole's own amplitude, `hole.detail`), scores and the automatic pick.
void InpaintAgain(HoleVariations& hole, const InpaintParams& params);

} // namespace curvature_inpaint
