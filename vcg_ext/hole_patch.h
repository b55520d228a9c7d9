// The working representation of one hole's fill between stages 2a (triangulate), 2b (refine)
// and 2c (fair): a small indexed triangle set in unit-box coordinates, detached from the
// caller's mesh so that a failed hole never leaves half-written faces behind.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstdint>
#include <set>
#include <utility>
#include <vector>

namespace vcg_ext {

using LocalEdge = std::pair<int, int>; ///< (smaller, larger) local vertex indices

inline LocalEdge MakeLocalEdge(int a, int b) {
  return {std::min(a, b), std::max(a, b)};
}

struct HolePatch {
  /// Local vertices [0, boundary_count) are the hole's loop vertices in loop order; the rest
  /// are vertices the refinement inserted.
  int boundary_count = 0;
  std::vector<Eigen::Vector3d> points;
  /// Oriented like the faces around the hole, so they can be added to the mesh as they are.
  std::vector<std::array<int, 3>> triangles;
  /// For each inserted vertex (local index - boundary_count): the three vertices of the
  /// triangle it split, so colour and quality can be interpolated from them.
  std::vector<std::array<int, 3>> parents;
  /// Chords between loop vertices that are already edges of the mesh outside the hole: a
  /// fill triangle using one would make that edge non-manifold.
  std::set<LocalEdge> forbidden_edges;

  int NewVertexCount() const { return int(points.size()) - boundary_count; }
  bool IsBoundaryEdge(int a, int b) const {
    if (a >= boundary_count || b >= boundary_count) return false;
    const int d = std::abs(a - b);
    return d == 1 || d == boundary_count - 1;
  }
};

/// The faces of the mesh around a hole, for the stages that need the hole's surroundings:
/// every face with a vertex on the loop ("two fixed rings": the loop and the vertices beyond).
struct HoleCollar {
  /// Outer vertices, referenced from `triangles` as -(k+1) for outer_points[k].
  std::vector<Eigen::Vector3d> outer_points;
  /// Faces around the loop: indices >= 0 are loop (local) vertices, < 0 outer vertices.
  std::vector<std::array<int, 3>> triangles;
  /// Unit normal of the face beside each loop edge i -> i+1.
  std::vector<Eigen::Vector3d> side_normals;
  /// Per loop vertex: the mean length of its edges in the mesh (Liepa's density sigma).
  std::vector<double> edge_scale;
};

inline Eigen::Vector3d TriangleNormal(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                      const Eigen::Vector3d& c) {
  return (b - a).cross(c - a);
}

} // namespace vcg_ext
