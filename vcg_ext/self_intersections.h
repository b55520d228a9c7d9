// Self-intersections of a patch: pairs of triangles that cross each other, for the check that
// a deformation introduced none.
//
// Two triangles cross when an edge of one passes through the interior of the other (Moeller
// and Trumbore's segment test); coplanar pairs only touch. Pairs sharing an edge are left to
// the fold test (a flipped triangle), which is what a crossing between neighbours across an
// edge amounts to. Candidate pairs come from a sweep over the triangles' extents along the
// widest axis, so a few thousand triangles take milliseconds.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <vector>

namespace vcg_ext {

namespace detail {

/// Whether segment (s0, s1) passes through the interior of triangle (a, b, c). A segment in the
/// triangle's plane does not: coplanar neighbours around a vertex only touch.
inline bool SegmentCrossesTriangle(const Eigen::Vector3d& s0, const Eigen::Vector3d& s1,
                                   const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                   const Eigen::Vector3d& c) {
  const Eigen::Vector3d d = s1 - s0, e1 = b - a, e2 = c - a;
  const Eigen::Vector3d q = d.cross(e2);
  const double det = e1.dot(q);
  if (std::abs(det) <= 1e-9 * d.norm() * e1.norm() * e2.norm()) return false;
  const Eigen::Vector3d s = s0 - a;
  const double u = s.dot(q) / det;
  const Eigen::Vector3d r = s.cross(e1);
  const double v = d.dot(r) / det, t = e2.dot(r) / det;
  return u > 0 && v > 0 && u + v < 1 && t > 0 && t < 1;
}

/// Whether triangles a and b cross: when an edge of one passes through the other. Edges from
/// a vertex they share are skipped: they meet the other triangle at that corner, where
/// rounding could make a touch look like a crossing.
inline bool TrianglesCross(const std::vector<Eigen::Vector3d>& p, const std::array<int, 3>& a,
                           const std::array<int, 3>& b) {
  auto shared = [](int v, const std::array<int, 3>& t) {
    return v == t[0] || v == t[1] || v == t[2];
  };
  auto pierces = [&](const std::array<int, 3>& e, const std::array<int, 3>& t) {
    for (int k = 0; k < 3; ++k) {
      const int v0 = e[k], v1 = e[(k + 1) % 3];
      if (!shared(v0, t) && !shared(v1, t) &&
          SegmentCrossesTriangle(p[v0], p[v1], p[t[0]], p[t[1]], p[t[2]]))
        return true;
    }
    return false;
  };
  return pierces(a, b) || pierces(b, a);
}

} // namespace detail

/// Counts the pairs of triangles of (points, triangles) that cross, among pairs with at least
/// one triangle flagged in `tested` (e.g. a patch's fill triangles; empty: all).
inline int CountSelfIntersections(const std::vector<Eigen::Vector3d>& points,
                                  const std::vector<std::array<int, 3>>& triangles,
                                  const std::vector<char>& tested = {}) {
  const size_t n = triangles.size();
  // The sweep runs along the points' widest axis, where the extents overlap least (along x, a
  // patch in a plane of constant x would make nearly every pair a candidate).
  Eigen::Vector3d low = Eigen::Vector3d::Constant(INFINITY), high = -low;
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k)
      low = low.cwiseMin(points[t[k]]), high = high.cwiseMax(points[t[k]]);
  int sweep = 0;
  if (n > 0) (high - low).maxCoeff(&sweep);
  std::vector<double> lo(n), hi(n);
  for (size_t f = 0; f < n; ++f) {
    const auto& t = triangles[f];
    lo[f] = std::min({points[t[0]][sweep], points[t[1]][sweep], points[t[2]][sweep]});
    hi[f] = std::max({points[t[0]][sweep], points[t[1]][sweep], points[t[2]][sweep]});
  }
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), size_t(0));
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return lo[a] < lo[b]; });
  auto box_overlap = [&](const std::array<int, 3>& a, const std::array<int, 3>& b) {
    for (int axis = 0; axis < 3; ++axis) {
      if (axis == sweep) continue;
      const double a_lo = std::min({points[a[0]][axis], points[a[1]][axis], points[a[2]][axis]});
      const double a_hi = std::max({points[a[0]][axis], points[a[1]][axis], points[a[2]][axis]});
      const double b_lo = std::min({points[b[0]][axis], points[b[1]][axis], points[b[2]][axis]});
      const double b_hi = std::max({points[b[0]][axis], points[b[1]][axis], points[b[2]][axis]});
      if (a_hi < b_lo || b_hi < a_lo) return false;
    }
    return true;
  };
  int crossings = 0;
  for (size_t i = 0; i < n; ++i) {
    const size_t fa = order[i];
    for (size_t j = i + 1; j < n && lo[order[j]] <= hi[fa]; ++j) {
      const size_t fb = order[j];
      if (!tested.empty() && !tested[fa] && !tested[fb]) continue;
      const auto& a = triangles[fa];
      const auto& b = triangles[fb];
      if (!box_overlap(a, b)) continue;
      int shared = 0;
      for (int x = 0; x < 3; ++x)
        for (int y = 0; y < 3; ++y) shared += a[x] == b[y];
      const bool cross = shared < 2 && detail::TrianglesCross(points, a, b);
      crossings += cross;
    }
  }
  return crossings;
}

} // namespace vcg_ext
