// Stage 2b: refine a hole's triangulation to the density of the mesh around it, after
// Liepa 2003, section 3.4: split a triangle at its centroid while the centroid is farther than
// sigma/alpha from its corners (sigma interpolated from the loop's edge lengths), and restore
// the Delaunay property with edge flips after every round of splits.
#pragma once

#include "hole_patch.h"

#include <cmath>
#include <vector>

namespace vcg_ext {

struct HoleRefinementParams {
  double alpha = std::sqrt(2.0); ///< Liepa's density control; larger = denser
  int max_new_vertices = 200000; ///< safety bound for holes far larger than their surroundings
};

namespace detail {

/// Corner-table topology of a patch: corner 3t+k starts edge k of triangle t, which runs
/// tri[k] -> tri[k+1]; opposite[c] is the corner of the same edge in the other triangle, or
/// -1 on the loop. Splits and flips update it in O(1), so refinement never rebuilds maps.
class PatchTopology {
public:
  explicit PatchTopology(HolePatch& patch) : patch_(patch) {
    auto& tris = patch_.triangles;
    opposite_.assign(3 * tris.size(), -1);
    corner_of_.assign(patch_.points.size(), -1);
    std::vector<std::pair<uint64_t, int>> keyed;
    keyed.reserve(3 * tris.size());
    for (int t = 0; t < int(tris.size()); ++t)
      for (int k = 0; k < 3; ++k) {
        keyed.emplace_back(Key(tris[t][k], tris[t][(k + 1) % 3]), 3 * t + k);
        corner_of_[tris[t][k]] = 3 * t + k;
      }
    std::sort(keyed.begin(), keyed.end());
    for (size_t i = 0; i + 1 < keyed.size(); ++i)
      if (keyed[i].first == keyed[i + 1].first) {
        opposite_[keyed[i].second] = keyed[i + 1].second;
        opposite_[keyed[i + 1].second] = keyed[i].second;
        ++i;
      }
  }

  int Vertex(int corner) const { return patch_.triangles[corner / 3][corner % 3]; }
  static int Next(int corner) { return corner / 3 * 3 + (corner + 1) % 3; }
  static int Prev(int corner) { return corner / 3 * 3 + (corner + 2) % 3; }
  int Opposite(int corner) const { return opposite_[corner]; }
  int CornerCount() const { return int(opposite_.size()); }

  /// Whether vertices a and b share an edge in the patch (walks a's fan both ways).
  bool HasEdge(int a, int b) const {
    const int start = corner_of_[a];
    if (start < 0) return false;
    for (int dir = 0; dir < 2; ++dir) {
      int c = start;
      for (;;) {
        if (Vertex(Next(c)) == b || Vertex(Prev(c)) == b) return true;
        // Rotate around a: across the edge entering a (dir 0) or leaving a (dir 1).
        const int o = dir == 0 ? opposite_[Prev(c)] : opposite_[c];
        if (o < 0) break; // reached the loop: walk the other way round
        c = dir == 0 ? o : Next(o);
        if (c == start) return false; // a closed fan, walked completely
      }
    }
    return false;
  }

  /// Splits triangle t at new vertex v into (a,b,v), (b,c,v), (c,a,v).
  void Split(int t, int v) {
    auto& tris = patch_.triangles;
    const auto tri = tris[t];
    const int t1 = int(tris.size()), t2 = t1 + 1;
    tris[t] = {tri[0], tri[1], v};
    tris.push_back({tri[1], tri[2], v});
    tris.push_back({tri[2], tri[0], v});
    const int p0 = opposite_[3 * t], p1 = opposite_[3 * t + 1], p2 = opposite_[3 * t + 2];
    opposite_.resize(3 * tris.size(), -1);
    Link(3 * t, p0);
    Link(3 * t1, p1);
    Link(3 * t2, p2);
    Link(3 * t + 1, 3 * t1 + 2);
    Link(3 * t1 + 1, 3 * t2 + 2);
    Link(3 * t2 + 1, 3 * t + 2);
    corner_of_.resize(patch_.points.size(), -1);
    corner_of_[tri[1]] = 3 * t + 1;
    corner_of_[tri[2]] = 3 * t1 + 1;
    corner_of_[v] = 3 * t + 2;
  }

  /// Flips the edge starting at corner e: triangles (a,b,c) and (b,a,d) become (a,d,c) and
  /// (b,c,d). Precondition: the edge is interior.
  void Flip(int e) {
    auto& tris = patch_.triangles;
    const int o = opposite_[e];
    const int t1 = e / 3, t2 = o / 3;
    const int a = Vertex(e), b = Vertex(Next(e)), c = Vertex(Prev(e)), d = Vertex(Prev(o));
    const int x1 = opposite_[Next(e)], x2 = opposite_[Prev(e)];
    const int y1 = opposite_[Next(o)], y2 = opposite_[Prev(o)];
    tris[t1] = {a, d, c};
    tris[t2] = {b, c, d};
    Link(3 * t1, y1);
    Link(3 * t1 + 2, x2);
    Link(3 * t2, x1);
    Link(3 * t2 + 2, y2);
    Link(3 * t1 + 1, 3 * t2 + 1);
    corner_of_[a] = 3 * t1;
    corner_of_[b] = 3 * t2;
    corner_of_[c] = 3 * t1 + 2;
    corner_of_[d] = 3 * t1 + 1;
  }

private:
  static uint64_t Key(int a, int b) {
    return (uint64_t(std::min(a, b)) << 32) | uint64_t(std::max(a, b));
  }
  void Link(int c, int o) {
    opposite_[c] = o;
    if (o >= 0) opposite_[o] = c;
  }
  HolePatch& patch_;
  std::vector<int> opposite_;
  std::vector<int> corner_of_;
};

inline double Angle(const Eigen::Vector3d& at, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d u = a - at, v = b - at;
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

/// Lawson's flips from the edges in `stack` until every edge reached is locally Delaunay
/// (opposite angles sum to at most pi) and none duplicates a forbidden mesh edge. A flip that
/// would fold the pair over, or create an edge that exists, is skipped. Returns the flips.
inline int RelaxEdges(HolePatch& patch, PatchTopology& topo, std::vector<int>& stack) {
  const auto& P = patch.points;
  int flips = 0;
  const int budget = 50 * topo.CornerCount() + 1000; // Lawson terminates; this only guards
  while (!stack.empty() && flips < budget) {
    const int e = stack.back();
    stack.pop_back();
    const int o = topo.Opposite(e);
    if (o < 0) continue;
    const int a = topo.Vertex(e), b = topo.Vertex(PatchTopology::Next(e));
    const int c = topo.Vertex(PatchTopology::Prev(e)), d = topo.Vertex(PatchTopology::Prev(o));
    const bool forced = patch.forbidden_edges.count(MakeLocalEdge(a, b)) > 0;
    if (!forced && Angle(P[c], P[a], P[b]) + Angle(P[d], P[a], P[b]) <= M_PI + 1e-9) continue;
    if (c == d || patch.forbidden_edges.count(MakeLocalEdge(c, d)) || topo.HasEdge(c, d)) continue;
    const Eigen::Vector3d n_old = TriangleNormal(P[a], P[b], P[c]).normalized() +
                                  TriangleNormal(P[b], P[a], P[d]).normalized();
    if (TriangleNormal(P[a], P[d], P[c]).dot(n_old) <= 0 ||
        TriangleNormal(P[b], P[c], P[d]).dot(n_old) <= 0)
      continue;
    topo.Flip(e);
    ++flips;
    // The four edges of the quad may have stopped being Delaunay.
    const int t1 = e / 3, t2 = o / 3;
    for (int corner : {3 * t1, 3 * t1 + 2, 3 * t2, 3 * t2 + 2}) stack.push_back(corner);
  }
  stack.clear();
  return flips;
}

inline std::vector<int> AllCorners(const PatchTopology& topo) {
  std::vector<int> corners(topo.CornerCount());
  for (int c = 0; c < topo.CornerCount(); ++c) corners[c] = c;
  return corners;
}

} // namespace detail

/// Flips the edges of `patch` until it is locally Delaunay (for a fill that is not refined).
inline int RelaxHolePatch(HolePatch& patch) {
  detail::PatchTopology topo(patch);
  std::vector<int> stack = detail::AllCorners(topo);
  return detail::RelaxEdges(patch, topo, stack);
}

/// Refines `patch` in place. `edge_scale[i]` is the target edge length around loop vertex i.
/// Inserted vertices are appended to patch.points with their parents recorded; loop vertices
/// and loop edges never change. Returns the number of inserted vertices.
inline int RefineHolePatch(HolePatch& patch, const std::vector<double>& edge_scale,
                           const HoleRefinementParams& params = {}) {
  std::vector<double> sigma(edge_scale.begin(), edge_scale.begin() + patch.boundary_count);
  sigma.resize(patch.points.size(), 0.0);
  const double alpha = params.alpha;
  detail::PatchTopology topo(patch);
  std::vector<int> stack = detail::AllCorners(topo);
  detail::RelaxEdges(patch, topo, stack);
  int inserted = 0;
  for (;;) {
    const int count = int(patch.triangles.size());
    for (int t = 0; t < count && inserted < params.max_new_vertices; ++t) {
      const auto tri = patch.triangles[t];
      const Eigen::Vector3d c =
          (patch.points[tri[0]] + patch.points[tri[1]] + patch.points[tri[2]]) / 3.0;
      const double sc = (sigma[tri[0]] + sigma[tri[1]] + sigma[tri[2]]) / 3.0;
      bool split = true;
      for (int k = 0; k < 3 && split; ++k) {
        const double d = alpha * (c - patch.points[tri[k]]).norm();
        split = d > sc && d > sigma[tri[k]];
      }
      if (!split) continue;
      const int v = int(patch.points.size());
      patch.points.push_back(c);
      patch.parents.push_back(tri);
      sigma.push_back(sc);
      topo.Split(t, v);
      const int t1 = int(patch.triangles.size()) - 2;
      for (int corner : {3 * t, 3 * t1, 3 * (t1 + 1)}) stack.push_back(corner);
      ++inserted;
    }
    if (stack.empty()) break; // no split in this round
    detail::RelaxEdges(patch, topo, stack);
    if (inserted >= params.max_new_vertices) break;
  }
  return inserted;
}

} // namespace vcg_ext
