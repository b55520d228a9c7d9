// The oracle of the benchmark: a hole's curvature image painted from the ground truth (the
// mesh before the hole was cut), as the best any inpainter could paint it. Deforming the
// coarse fill to it measures what the deformation can reach; the gap to the inpainted images
// is the inpainter's.
//
// The ground truth's surface inside the hole is put in place of the coarse fill in the
// hole's patch (the context faces are the same faces in both meshes), parameterized with the
// same mean value coordinates and the same boundary on the square, and its own APSS mean
// curvature is painted with the hole's normalization: a pixel shows the ground truth at the
// place of the patch that the coarse fill's pixel stands for.
#pragma once

#include "pipeline/curvature_images.h"

#include <QImage>

#include <array>
#include <set>
#include <string>
#include <unordered_map>

namespace curvature_inpaint {

/// The fill's vertex density (Liepa's alpha) under the oracle unless one is asked for: finer
/// than the inpainted fills' 2, since the ground truth's image holds detail that a fill of
/// that density cannot carry. Chosen on the tuning half with the oracle (docs/experiments.md, "The
/// figures behind the defaults").
constexpr double kOracleDensity = 2.5;

/// How much of the ground truth's curvature spread (standard deviation over the hole, in
/// unit-box curvature) each stage of the chain carries.
struct GroundTruthSpread {
  double truth = 0; ///< the ground truth's APSS mean curvature at its vertices in the hole
  double image = 0; ///< the hole's pixels (clamped by the colour map's ends)
};

struct GroundTruthImage {
  QImage image; ///< RGB, the hole image's size; empty when `problem` says why
  GroundTruthSpread spread;
  std::string problem;
};

/// Standard deviation of the finite values of `x` (0 for fewer than two): the curvature
/// spread of a region.
double Spread(const std::vector<double>& x);

/// Holds the ground truth once for every hole of one input.
class GroundTruthOracle {
public:
  /// `ground_truth` must outlive the oracle; `input` is the mesh with the holes, before they
  /// are filled (its unit box gives the holes' units). The input's vertices must have exactly
  /// the ground truth's coordinates (the input is the ground truth with faces removed, as
  /// `curvature-inpaint punch` makes it).
  GroundTruthOracle(const CMeshO& ground_truth, const CMeshO& input,
                    const CurvatureImagesParams& params);

  /// The image of hole `hi`; thread-safe. A hole whose context the ground truth does not
  /// contain, or whose missing surface it does not close, gets a `problem` and no image.
  GroundTruthImage Image(const HoleImage& hi) const;

private:
  /// The ground truth's faces in hole `hi` (`gt_of`: its patch's vertices in the ground truth),
  /// from the hole's loop inwards and never across it; empty with a `problem` where it has
  /// none, or they run on into another hole or without end.
  std::vector<int> FacesInHole(const HoleImage& hi, const std::vector<int>& gt_of,
                               std::string* problem) const;

  const CMeshO& gt_;
  vcg_ext::UnitBox box_;
  CurvatureImagesParams params_;
  vcg_ext::VertexFaces vf_;
  std::unordered_map<std::string, int> by_position_; ///< exact unit-box coordinates -> vertex
  std::set<std::array<int, 3>> input_faces_;         ///< the input's, in ground-truth vertices
};

} // namespace curvature_inpaint
