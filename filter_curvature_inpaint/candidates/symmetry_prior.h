// The symmetry prior on a MeshLab mesh: the object's reflective symmetry planes, found once
// from its scan vertices, and for a hole the fill its mirror image predicts (a candidate the
// fake-hole validation weighs against the continuation; nothing is forced on a hole).
#pragma once

#include "pipeline/meshlab_mesh.h"
#include <vcg_ext/coarse_fill.h>
#include <vcg_ext/mirrored_fill.h>
#include <vcg_ext/patch_extraction.h>
#include <vcg_ext/reflective_symmetry.h>

#include <memory>
#include <string>
#include <vector>

namespace curvature_inpaint {

struct SymmetryPriorParams {
  bool enabled = true;
  vcg_ext::SymmetryParams detection;
  vcg_ext::MirroredFillParams fill;
};

/// What the holes read of the mesh's symmetry (never written once built).
struct SymmetryPrior {
  vcg_ext::UnitBox box;                         ///< the mesh's; the points are in it
  std::vector<Eigen::Vector3d> points, normals; ///< the scan's vertices (no fill)
  std::unique_ptr<vcg_ext::PointIndex> index;
  std::vector<vcg_ext::SymmetryPlane> planes;  ///< accepted, best first; may be empty
  std::vector<vcg_ext::SymmetryPlane> partial; ///< partial symmetries, best first; may be empty
  vcg_ext::SymmetryPlane best;                 ///< the best-covering plane, accepted or not
  double seconds = 0;
};

/// Detects the symmetry of the scan part of `m` after its coarse fill (`coarse` says which
/// vertices and faces the fill added).
std::unique_ptr<SymmetryPrior> DetectSymmetry(const CMeshO& m,
                                              const vcg_ext::CoarseFillResult& coarse,
                                              const vcg_ext::SymmetryParams& params);

/// The object's accepted planes, then its partial ones, in the mesh's units (the prior's are
/// in its unit box).
std::vector<vcg_ext::SymmetryPlane> MirrorPlanesInMeshUnits(const SymmetryPrior& prior);

/// "symmetry: ..." for the log: the planes found with their coverage and residual, or none,
/// and the partial symmetries.
std::string DescribeSymmetry(const std::vector<vcg_ext::SymmetryPlane>& planes,
                             const vcg_ext::SymmetryPlane& best,
                             const std::vector<vcg_ext::SymmetryPlane>& partial);

/// The fill of a hole's patch (in the unit box `frame`) from its mirror image across the
/// best-covering plane that has one, a partial symmetry's where no accepted plane has; with
/// `excluded_radius` > 0 the known surface within it of `excluded_centre` (both in the mesh's
/// units) is left out. A `problem` when no plane gives one.
vcg_ext::MirroredFill MirrorHole(const SymmetryPrior& prior, const vcg_ext::PatchMesh& patch,
                                 const std::vector<char>& free, const vcg_ext::UnitBox& frame,
                                 const vcg_ext::MirroredFillParams& params,
                                 const Eigen::Vector3d& excluded_centre = Eigen::Vector3d::Zero(),
                                 double excluded_radius = 0);

} // namespace curvature_inpaint
