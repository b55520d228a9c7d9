// Stage 2b: refine a hole's triangulation to the density of the mesh around it, after
// Liepa 2003, section 3.4: split a triangle at its centroid while the centroid is farther than
// sigma/alpha from its corners (sigma interpolated from the loop's edge lengths), and restore
// the Delaunay property with edge flips after every round of splits.
#pragma once

#include "hole_patch.h"

#include <cmath>
#include <unordered_map>
#include <vector>

namespace vcg_ext {

struct HoleRefinementParams {
  double alpha = std::sqrt(2.0); ///< Liepa's density control; larger = denser
  int max_new_vertices = 200000; ///< safety bound for holes far larger than their surroundings
  int max_flip_rounds = 100;     ///< bound on each relaxation; it converges long before
};

namespace detail {

/// Edge -> the (at most two) patch triangles that use it.
class PatchEdgeMap {
public:
  explicit PatchEdgeMap(const std::vector<std::array<int, 3>>& tris) {
    for (int t = 0; t < int(tris.size()); ++t) Add(tris[t], t);
  }
  void Add(const std::array<int, 3>& tri, int t) {
    for (int k = 0; k < 3; ++k) {
      auto& slot =
          map_.emplace(Key(tri[k], tri[(k + 1) % 3]), std::array<int, 2>{{-1, -1}}).first->second;
      (slot[0] < 0 ? slot[0] : slot[1]) = t;
    }
  }
  void Remove(const std::array<int, 3>& tri, int t) {
    for (int k = 0; k < 3; ++k) {
      auto it = map_.find(Key(tri[k], tri[(k + 1) % 3]));
      if (it == map_.end()) continue;
      for (int& s : it->second)
        if (s == t) s = -1;
      if (it->second[0] < 0 && it->second[1] < 0) map_.erase(it);
    }
  }
  bool Has(int a, int b) const { return map_.count(Key(a, b)) > 0; }
  std::array<int, 2> Faces(int a, int b) const {
    auto it = map_.find(Key(a, b));
    return it == map_.end() ? std::array<int, 2>{{-1, -1}} : it->second;
  }
  template <class F>
  void ForEachEdge(F f) const {
    for (const auto& kv : map_) f(int(kv.first >> 32), int(kv.first & 0xffffffffu));
  }

private:
  static uint64_t Key(int a, int b) {
    const auto lo = uint64_t(std::min(a, b)), hi = uint64_t(std::max(a, b));
    return (lo << 32) | hi;
  }
  std::unordered_map<uint64_t, std::array<int, 2>> map_;
};

inline double Angle(const Eigen::Vector3d& at, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d u = a - at, v = b - at;
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

/// Flips interior edges until every one is locally Delaunay (opposite angles sum to at most
/// pi) and none duplicates a forbidden mesh edge. Returns the number of flips.
inline int RelaxPatch(HolePatch& patch, int max_rounds) {
  auto& tris = patch.triangles;
  int flips = 0;
  for (int round = 0; round < max_rounds; ++round) {
    PatchEdgeMap edges(tris);
    std::vector<LocalEdge> candidates;
    edges.ForEachEdge([&](int a, int b) {
      if (!patch.IsBoundaryEdge(a, b)) candidates.push_back(MakeLocalEdge(a, b));
    });
    int round_flips = 0;
    for (const LocalEdge& e : candidates) {
      const auto ft = edges.Faces(e.first, e.second);
      if (ft[0] < 0 || ft[1] < 0) continue;
      // Orient: t1 runs a -> b, t2 runs b -> a.
      const int t1 = ft[0], t2 = ft[1];
      int a = e.first, b = e.second;
      auto corner = [&](int t, int from) {
        for (int k = 0; k < 3; ++k)
          if (tris[t][k] == from) return k;
        return -1;
      };
      int k1 = corner(t1, a);
      if (tris[t1][(k1 + 1) % 3] != b) {
        std::swap(a, b);
        k1 = corner(t1, a);
      }
      if (k1 < 0 || tris[t1][(k1 + 1) % 3] != b) continue;
      const int k2 = corner(t2, b);
      if (k2 < 0 || tris[t2][(k2 + 1) % 3] != a) continue;
      const int c = tris[t1][(k1 + 2) % 3], d = tris[t2][(k2 + 2) % 3];
      if (c == d || edges.Has(c, d) || patch.forbidden_edges.count(MakeLocalEdge(c, d))) continue;
      const auto& P = patch.points;
      const bool forced = patch.forbidden_edges.count(MakeLocalEdge(a, b)) > 0;
      const bool delaunay_violated =
          Angle(P[c], P[a], P[b]) + Angle(P[d], P[a], P[b]) > M_PI + 1e-9;
      if (!forced && !delaunay_violated) continue;
      // The flipped pair must not fold over: both new normals agree with the old ones.
      const Eigen::Vector3d n_old = TriangleNormal(P[a], P[b], P[c]).normalized() +
                                    TriangleNormal(P[b], P[a], P[d]).normalized();
      const std::array<int, 3> n1{a, d, c}, n2{b, c, d};
      if (TriangleNormal(P[a], P[d], P[c]).dot(n_old) <= 0 ||
          TriangleNormal(P[b], P[c], P[d]).dot(n_old) <= 0)
        continue;
      edges.Remove(tris[t1], t1);
      edges.Remove(tris[t2], t2);
      tris[t1] = n1;
      tris[t2] = n2;
      edges.Add(tris[t1], t1);
      edges.Add(tris[t2], t2);
      ++round_flips;
    }
    flips += round_flips;
    if (round_flips == 0) break;
  }
  return flips;
}

} // namespace detail

/// Refines `patch` in place. `edge_scale[i]` is the target edge length around loop vertex i.
/// Inserted vertices are appended to patch.points with their parents recorded; loop vertices
/// and loop edges never change. Returns the number of inserted vertices.
inline int RefineHolePatch(HolePatch& patch, const std::vector<double>& edge_scale,
                           const HoleRefinementParams& params = {}) {
  std::vector<double> sigma(edge_scale.begin(), edge_scale.begin() + patch.boundary_count);
  sigma.resize(patch.points.size(), 0.0);
  const double alpha = params.alpha;
  int inserted = 0;
  detail::RelaxPatch(patch, params.max_flip_rounds);
  for (;;) {
    bool split_any = false;
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
      patch.triangles[t] = {tri[0], tri[1], v};
      patch.triangles.push_back({tri[1], tri[2], v});
      patch.triangles.push_back({tri[2], tri[0], v});
      ++inserted;
      split_any = true;
    }
    if (!split_any) break;
    detail::RelaxPatch(patch, params.max_flip_rounds);
    if (inserted >= params.max_new_vertices) break;
  }
  return inserted;
}

} // namespace vcg_ext
