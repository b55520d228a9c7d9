// Fake holes for validation: holes of a real hole's size cut into known surface near it, so
// that every way of filling it can be scored against the surface that was cut out, and the
// real hole filled the way that validated best (the choice learned "self-prior" fillers make
// without ground truth).
#pragma once

#include "pipeline/meshlab_mesh.h"
#include <vcg_ext/coarse_fill.h>
#include <vcg_ext/hole_segmentation.h>
#include <vcg_ext/reflective_symmetry.h>

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace curvature_inpaint {

/// One fake hole: a piece of known surface around it (`truth`), the same piece with the hole
/// cut (`holed`: the hole and the piece's own outer border are its only loops), and the cut
/// surface in `holed`'s unit box.
struct FakeHole {
  CMeshO truth, holed;
  std::vector<std::array<Eigen::Vector3d, 3>> cut;  ///< the removed triangles, unit box of holed
  std::vector<int> cut_vertices;                    ///< vertices of truth the hole removed
  double radius = 0;                                ///< of the hole, unit box of holed
  Eigen::Vector3d centre = Eigen::Vector3d::Zero(); ///< of the hole, the mesh's units
  bool at_mirror_place = false;                     ///< cut where the real hole's mirror image lies
};

struct FakeHoleParams {
  int count = 4; ///< fake holes per real hole
  /// Radius of the piece around a fake hole, in hole radii: the hole and the context ring
  /// its patch takes (1 + the segmentation's context), no more.
  double piece = 2;
  /// Fake holes lie within this many hole radii of the real one: the surface just beyond the
  /// hole's context is the most like the surface missing (docs/experiments.md, "The figures behind
  /// the defaults").
  double farthest = 5;
  int max_attempts = 48; ///< places tried per real hole
  uint32_t seed = 1;
  /// The object's mirror planes (the mesh's units): where the real hole's mirror image in one
  /// is known surface, one fake hole is cut there besides `count` near the hole (none if there
  /// is no room near it). On a symmetric object the twin of the missing surface is the fake
  /// hole most like it.
  std::vector<vcg_ext::SymmetryPlane> mirror_planes;
};

/// Cuts up to `params.count` fake holes of the size of hole `hole` of `coarse` into the scan
/// faces of `m` (after its coarse fill; `vf` its vertex-face adjacency), and one at its
/// mirror place in each mirror plane. A fake hole and the piece around it never overlap a real hole
/// (filled or not), the mesh's border, or another near fake's piece (a mirror place's may overlap
/// those). Places near it are tried in an order fixed by the seed and the hole (so the result
/// does not depend on threads), then the mirror places. Fewer (or none) where there is no
/// room: `why` says so.
std::vector<std::unique_ptr<FakeHole>> CutFakeHoles(const CMeshO& m, const vcg_ext::VertexFaces& vf,
                                                    const vcg_ext::CoarseFillResult& coarse,
                                                    int hole, const FakeHoleParams& params,
                                                    std::string* why);

namespace detail {
class TriangleGrid;
} // namespace detail

/// Scores fills of one fake hole against the surface cut out. Every candidate is measured
/// against the same cut surface, so its search grid is built once, not once per candidate.
/// Not thread-safe (the grid marks what a query visits): one scorer per thread.
class FakeHoleScorer {
public:
  /// \pre `fake` outlives the scorer.
  explicit FakeHoleScorer(const FakeHole& fake);
  ~FakeHoleScorer();
  FakeHoleScorer(const FakeHoleScorer&) = delete;
  FakeHoleScorer& operator=(const FakeHoleScorer&) = delete;

  /// The hole-region RMS distance (both directions, from triangle centres) between a fill
  /// (`points`, with `triangles` the fill's) and the surface cut out, in the units of the
  /// points; infinite for a fill with a point off to infinity, and where the fill or the
  /// surface cut out is empty.
  double Error(const std::vector<Eigen::Vector3d>& points,
               const std::vector<std::array<int, 3>>& triangles);

private:
  const FakeHole& fake_;
  std::unique_ptr<detail::TriangleGrid> cut_; ///< of fake_.cut; null where it is empty
};

/// FakeHoleScorer(fake).Error(points, triangles), for one fill.
double FakeHoleError(const FakeHole& fake, const std::vector<Eigen::Vector3d>& points,
                     const std::vector<std::array<int, 3>>& triangles);

} // namespace curvature_inpaint
