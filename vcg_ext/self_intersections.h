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
#include <utility>
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
/// one triangle flagged in `tested` (e.g. a patch's fill triangles; empty: all). Where `pairs`
/// is given, it receives each crossing pair's triangle indices (the lower first), sorted.
inline int CountSelfIntersections(const std::vector<Eigen::Vector3d>& points,
                                  const std::vector<std::array<int, 3>>& triangles,
                                  const std::vector<char>& tested = {},
                                  std::vector<std::pair<int, int>>* pairs = nullptr) {
  const size_t n = triangles.size();
  // Each triangle's bounding box, once: a pair's boxes are compared many times in the sweep.
  std::vector<Eigen::Vector3d> box_lo(n), box_hi(n);
  Eigen::Vector3d tested_lo = Eigen::Vector3d::Constant(INFINITY), tested_hi = -tested_lo;
  for (size_t f = 0; f < n; ++f) {
    const auto& t = triangles[f];
    box_lo[f] = points[t[0]].cwiseMin(points[t[1]]).cwiseMin(points[t[2]]);
    box_hi[f] = points[t[0]].cwiseMax(points[t[1]]).cwiseMax(points[t[2]]);
    if (tested.empty() || tested[f])
      tested_lo = tested_lo.cwiseMin(box_lo[f]), tested_hi = tested_hi.cwiseMax(box_hi[f]);
  }
  auto box_overlap = [&](const Eigen::Vector3d& a_lo, const Eigen::Vector3d& a_hi,
                         const Eigen::Vector3d& b_lo, const Eigen::Vector3d& b_hi) {
    return (a_lo.array() <= b_hi.array()).all() && (b_lo.array() <= a_hi.array()).all();
  };
  // Only triangles within the tested ones' bounds can cross one of them (a patch's context
  // ring mostly lies outside its fill's).
  std::vector<size_t> order;
  for (size_t f = 0; f < n; ++f)
    if (box_overlap(box_lo[f], box_hi[f], tested_lo, tested_hi)) order.push_back(f);
  // The sweep runs along the widest axis of those, where the extents overlap least (along x, a
  // patch in a plane of constant x would make nearly every pair a candidate).
  int sweep = 0;
  if (!order.empty()) (tested_hi - tested_lo).maxCoeff(&sweep);
  std::sort(order.begin(), order.end(),
            [&](size_t a, size_t b) { return box_lo[a][sweep] < box_lo[b][sweep]; });
  int crossings = 0;
  for (size_t i = 0; i < order.size(); ++i) {
    const size_t fa = order[i];
    for (size_t j = i + 1; j < order.size() && box_lo[order[j]][sweep] <= box_hi[fa][sweep]; ++j) {
      const size_t fb = order[j];
      if (!tested.empty() && !tested[fa] && !tested[fb]) continue;
      if (!box_overlap(box_lo[fa], box_hi[fa], box_lo[fb], box_hi[fb])) continue;
      const auto& a = triangles[fa];
      const auto& b = triangles[fb];
      int shared = 0;
      for (int x = 0; x < 3; ++x)
        for (int y = 0; y < 3; ++y) shared += a[x] == b[y];
      const bool cross = shared < 2 && detail::TrianglesCross(points, a, b);
      crossings += cross;
      if (cross && pairs) pairs->emplace_back(int(std::min(fa, fb)), int(std::max(fa, fb)));
    }
  }
  if (pairs) std::sort(pairs->begin(), pairs->end());
  return crossings;
}

} // namespace vcg_ext
