// Stages 3-7 of the pipeline on a MeshLab mesh: per hole, the disk patch around its coarse
// fill, the patch's APSS mean curvature, its mean-value parameterization and its curvature
// image with the hole's mask: what an inpainter is given.
#pragma once

#include "pipeline/meshlab_mesh.h"

#include <QImage>
#include <vcg_ext/apss_curvature.h>
#include <vcg_ext/coarse_fill.h>
#include <vcg_ext/curvature_image.h>
#include <vcg_ext/mvc_parameterization.h>
#include <vcg_ext/patch_extraction.h>

#include <functional>
#include <string>
#include <vector>

namespace curvature_inpaint {

struct CurvatureImagesParams {
  /// The patches' fills are refined finer than their surroundings (Liepa's alpha 2, the coarse
  /// fill's own default is 1.41): their vertices sample the image, and a fill as dense as the
  /// scan cannot carry the detail of its curvature (deformed to the ground truth's own image,
  /// the public cases' Igea, armadillo and Nefertiti holes kept 0.48-0.88 of the truth's
  /// curvature spread at 1.41, 0.65-0.98 at 2).
  CurvatureImagesParams() { coarse.density_alpha = 2; }
  vcg_ext::CoarseFillParams coarse;
  vcg_ext::HoleSegmentationParams segmentation;
  vcg_ext::ApssParams apss;
  int image_size = 1024; ///< pixels per side (DALL-E 2: 1024, Stable Diffusion: 512)
  int apss_rings = 3;    ///< rings of vertices beyond the patch that support the fits
  double low_percentile = 0.05, high_percentile = 0.95; ///< of the known ring's curvature
  /// The colour map's ends at this many times the larger of the two percentiles: a hole often
  /// holds more curvature than its ring (a nose tip), which an image clamped at the ring's
  /// range cannot show (the ground truth's image of the armadillo belly kept 0.60 of its spread at
  /// 1, 0.70 at 2).
  double headroom = 2;
  bool color_vertices = true; ///< paint the patch vertices with their curvature colours
};

/// One hole's patch and image.
struct HoleImage {
  int hole = 0; ///< index into CurvatureImagesResult::coarse.holes
  vcg_ext::PatchMesh patch;
  /// Per patch vertex: added by the coarse fill, so the deformation may move it. Every other
  /// vertex is the scan's, also a loop vertex that no context face touches (where two holes
  /// meet at one vertex).
  std::vector<char> is_new;
  std::vector<double> curvature; ///< signed mean curvature per patch vertex (unit box)
  std::vector<double> value;     ///< colour-map value in [0,1] per patch vertex
  double scale = 1;              ///< curvature that maps to the ends of the colour map
  double low = 0, high = 0;      ///< the known ring's curvature percentiles
  int rings = 0, target_rings = 0;
  vcg_ext::MvcParameterization uv;
  vcg_ext::CurvatureImage image;
  double seconds = 0;  ///< stages 3-7 for this hole
  std::string problem; ///< why there is no image; empty if there is one
};

struct CurvatureImagesResult {
  vcg_ext::CoarseFillResult coarse;
  std::vector<HoleImage> holes;
  double adjacency_seconds = 0; ///< the one pass over the mesh all holes share
};

/// Throws vcg_ext::InvalidParameterError naming the first parameter out of its range.
void CheckCurvatureImagesParams(const CurvatureImagesParams& params);

/// Receives hole k's image as soon as it is built, with the coarse fill it belongs to, on the
/// thread that built it (holes in any order, several at once; it may throw, which stops the
/// rest): a caller that uses each image and drops it never holds them all at the same time.
using HoleImageSink =
    std::function<void(const vcg_ext::CoarseFillResult& coarse, int k, HoleImage& hole)>;

/// Fills the holes of `m` (stages 0-2), then builds every filled hole's image, hands it to
/// `sink` if given, and colours the patch vertices with their curvature colours. Throws
/// vcg_ext::InvalidMeshError, InvalidParameterError, CancelledError or what `sink` throws, with
/// `m` exactly as it was.
CurvatureImagesResult ComputeCurvatureImages(CMeshO& m, const CurvatureImagesParams& params,
                                             vcg::CallBackPos* cb = nullptr,
                                             const HoleImageSink& sink = {});

/// Writes hole_<k>_curvature.png, hole_<k>_rgba.png, hole_<k>_mask.png and hole_<k>.json for
/// every hole with an image (k from 1). Throws std::runtime_error naming the file it could
/// not write.
void WriteHoleImages(const std::string& dir, const CurvatureImagesResult& result);

/// The image as RGB (or RGBA with the hole transparent), and its mask (white on the hole).
QImage ToQImage(const vcg_ext::CurvatureImage& img, bool with_alpha);
QImage MaskImage(const vcg_ext::CurvatureImage& img);

/// Writes montage.png: one row per hole (curvature, RGBA over a checkerboard, mask).
void WriteMontage(const std::string& path, const CurvatureImagesResult& result);

/// The point set the APSS fits of the curvature images run on: points with area-weighted
/// normals from their faces, in unit-box coordinates.
struct ApssSupport {
  std::vector<Eigen::Vector3d> points, normals;
};

/// The vertices `patch_vertices` of `m` first, then `rings` rings around them.
ApssSupport ApssNeighbourhood(const CMeshO& m, const vcg_ext::VertexFaces& vf,
                              const vcg_ext::UnitBox& box, const std::vector<int>& patch_vertices,
                              int rings);

std::vector<std::string> DescribeCurvatureImages(const CurvatureImagesResult& result);

} // namespace curvature_inpaint
