// The ways to fill one hole's patch that the Fill stage applies and the fake-hole validation
// scores: the coarse fill deformed to a curvature image, the tri-Laplacian continuation, the
// mirror image and the crease fill. Each works on the patch in its unit box, leaves the known
// vertices where they are, and backs its fill off towards the coarse one where it would fold
// a triangle over or make the fill cross the patch.
#pragma once

#include "candidates/symmetry_prior.h"
#include "pipeline/curvature_images.h"
#include "pipeline/hole_fill.h"

#include <vcg_ext/crease_fill.h>
#include <vcg_ext/curvature_deformation.h>
#include <vcg_ext/mirrored_fill.h>

#include <Eigen/Core>
#include <QImage>

#include <array>
#include <string>
#include <vector>

namespace curvature_inpaint {

/// An image edited by hand, at the patch image's size, with the known pixels as they were.
QImage KnownPixelsKept(const QImage& edited, const QImage& image, const QImage& mask);

/// APSS mean curvature of every vertex of a (deformed) patch, from the patch alone.
std::vector<double> PatchCurvature(const std::vector<Eigen::Vector3d>& points,
                                   const std::vector<std::array<int, 3>>& triangles,
                                   const vcg_ext::ApssParams& apss);

/// The curvature of the deformed patch as an image, normalized like the coarse one.
QImage FinalCurvatureImage(const HoleImage& hi, const std::vector<Eigen::Vector3d>& points,
                           const vcg_ext::ApssParams& apss);

/// The colour-map value of `image` at each fill vertex of the patch (0.5 elsewhere).
std::vector<double> TargetValues(const HoleImage& hi, const QImage& image);

/// Stage 9 on one patch: its free vertices moved to the curvature of `target_image`.
struct PatchDeformation {
  std::vector<Eigen::Vector3d> points; ///< the whole patch, unit box
  std::vector<double> target;          ///< colour-map value at each free vertex
  vcg_ext::DeformationResult result;   ///< not solved: it would fold or cross the patch
  int backoffs = 0;
};

/// The patch deformed to the curvature of `target_image` in `params.mode` (direct: rounds
/// that would fold or cross the patch are not taken; paper: the paper's steps), then backed
/// off while it folds or crosses; not `result.solved` where four halvings did not mend it.
PatchDeformation DeformPatch(const HoleImage& hi, const QImage& target_image,
                             const HoleFillParams& params);

/// The mean length of the fill's edges in the hole's image, in pixels: the finest detail its
/// vertices can carry.
double FillSpacingPixels(const HoleImage& hi);

/// The patch's fill from its mirror image (MirrorHole; `frame` the patch's unit box; with
/// `excluded_radius` > 0 the known surface within it of `excluded_centre`, both in the mesh's
/// units, left out: a fake hole's own), backed off where it would fold or cross the patch;
/// empty points with a `problem` where it has none.
vcg_ext::MirroredFill
MirroredPatch(const SymmetryPrior& prior, const HoleImage& hi, const vcg_ext::UnitBox& frame,
              const HoleFillParams& params,
              const Eigen::Vector3d& excluded_centre = Eigen::Vector3d::Zero(),
              double excluded_radius = 0);

/// A prior's surface (the patch with its fill moved) as a variation of the hole's image: its
/// curvature.
QImage SurfaceImage(const HoleImage& hi, const std::vector<Eigen::Vector3d>& points,
                    const HoleFillParams& params);

/// The patch's fill carried across the creases of its context (FillAcrossCreases); empty
/// points with a `problem` where it has none. Where it would fold or cross the patch it is
/// backed off there only (BackOffLocally): the crease fill folds on a corner or where creases
/// crowd, and backed off as a whole every crease of the hole comes back rounded. Only where
/// that does not
/// mend it is the whole fill backed off. The fill with its vertices spread over the faces
/// (ten rounds of umbrella smoothing) is taken where it needs no backing off, or less than the
/// vertices projected one by one: spread, the vertex put on a corner of three faces can fold its
/// triangles (docs/experiments.md, "The figures behind the defaults").
vcg_ext::CreaseFill CreasedPatch(const HoleImage& hi, const HoleFillParams& params);

/// A patch with its fill vertices moved, or why there is none.
struct PatchFill {
  std::vector<Eigen::Vector3d> points; ///< the whole patch, unit box
  std::string problem;
};

/// The patch with its fill faired once more so that it continues the curvature of the known
/// surface around it, not only its tangents (a tri-Laplacian, every known vertex fixed; the
/// patch's context holds the two rings it needs), backed off where it would fold or cross the
/// patch; empty points with a `problem` where the system cannot be solved.
PatchFill TriLaplacianPatch(const HoleImage& hi);

/// The fill triangles of a patch.
std::vector<std::array<int, 3>> FillTriangles(const vcg_ext::PatchMesh& patch);

} // namespace curvature_inpaint
