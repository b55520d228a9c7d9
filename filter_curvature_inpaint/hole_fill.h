// The whole method (stages 0-9): coarse fill, curvature images, inpainting, choice of a
// variation, and deformation of each patch to the chosen image. The mesh changes only when
// every stage has succeeded.
#pragma once

#include "curvature_images.h"
#include "inpaint/inpainter.h"

#include <vcg_ext/curvature_deformation.h>

#include <string>
#include <vector>

namespace curvature_inpaint {

struct HoleFillParams {
  CurvatureImagesParams images;
  InpaintParams inpaint;
  std::string mode = "direct"; ///< "direct" or "paper"
  int pick = 0;                ///< 0: the best score; k >= 1: variation k of every hole
  vcg_ext::DirectDeformationParams direct;
  vcg_ext::PaperDeformationParams paper;
  std::string images_dir; ///< where to write every hole's images; empty: nowhere
  /// Instead of a backend: the folder where the Curvature Images stage wrote hole_<k>.json and
  /// a person (in any image editor) left hole_<k>_inpainted.png. The patches are rebuilt with
  /// the same parameters and must match the JSON files.
  std::string inpainted_dir;
};

struct HoleFillReport {
  int hole = 0; ///< index into the coarse result's holes
  int boundary_edges = 0;
  int new_vertices = 0;
  std::vector<double> scores; ///< per variation: higher is better
  int pick = 0;               ///< 1-based
  int iterations = 0;         ///< deformation solves (direct) or steps (paper)
  std::vector<int> differing; ///< paper mode: differing vertices per step
  double max_move = 0;        ///< unit-box units
  double coarse_s = 0, images_s = 0, inpaint_s = 0, deform_s = 0;
  std::string problem; ///< why the hole kept its coarse fill; empty if none
};

/// One hole's inpainting (stages 3-8) as a person previews it and FillHoles applies it.
struct HoleVariations {
  QImage image, mask;             ///< the coarse curvature image and its hole (white)
  std::vector<QImage> variations; ///< the backend's completions of `image`
  std::vector<double> scores;     ///< ScoreVariation of each
  int pick = 0;                   ///< 1-based; 0: the hole keeps its coarse fill
  std::string problem;            ///< why there is nothing to choose from; empty if none
  double images_s = 0, inpaint_s = 0;
};

struct HoleFillResult {
  vcg_ext::CoarseFillResult coarse;
  std::vector<HoleFillReport> holes;
};

/// Throws vcg_ext::InvalidParameterError naming the first parameter out of its range.
void CheckHoleFillParams(const HoleFillParams& params);

/// Fills the holes of `m` with detail. With `chosen` (from InpaintHoles on a copy of `m` with
/// the same parameters, picks possibly changed) the backend is not asked again: each hole is
/// deformed to its chosen variation, or keeps its coarse fill where the pick is 0. Throws
/// InvalidMeshError, InvalidParameterError (before anything else), InpaintError (a backend
/// failed), CancelledError or std::runtime_error
/// (also when `chosen` does not match the holes), with `m` exactly as it was.
HoleFillResult FillHoles(CMeshO& m, const HoleFillParams& params, vcg::CallBackPos* cb = nullptr,
                         const std::vector<HoleVariations>* chosen = nullptr);

/// Stages 0-8 for a preview: fills the holes of `scratch` coarsely (pass a copy of the mesh;
/// it is changed) and returns every hole's curvature image with its scored variations and the
/// automatic pick (params.pick when given). Throws like FillHoles.
std::vector<HoleVariations> InpaintHoles(CMeshO& scratch, const HoleFillParams& params,
                                         vcg::CallBackPos* cb = nullptr);

/// Asks the backend again for one hole (a "re-roll"): new variations, scores and pick.
void InpaintAgain(HoleVariations& hole, const InpaintParams& params);

/// Scores a variation without ground truth (higher is better): how continuously the value
/// field crosses the hole's border, how close the hole's colours stay to the palette, and how
/// far its values leave the known ring's range.
double ScoreVariation(const QImage& variation, const QImage& mask);

std::vector<std::string> DescribeHoleFill(const HoleFillResult& result);

/// The report as JSON (no keys, no URLs with credentials).
std::string HoleFillReportJson(const HoleFillResult& result, const HoleFillParams& params);

} // namespace curvature_inpaint
