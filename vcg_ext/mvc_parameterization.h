// Stage 6: map a disk patch onto the unit square (paper, section 3.4) with Floater's mean
// value coordinates: the boundary on the square's border by arc length, so the image is
// filled to its edges; every interior vertex the mean-value average of its neighbours, one
// sparse solve. On a convex boundary the weights guarantee an embedding (no flipped
// triangles); the result reports any degenerate ones anyway.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseLU>

#include <array>
#include <cmath>
#include <vector>

namespace vcg_ext {

struct MvcParameterization {
  std::vector<Eigen::Vector2d> uv;
  int flipped = 0;    ///< triangles with negative area in UV
  int degenerate = 0; ///< triangles with (near) zero area in UV
  bool solved = false;
};

namespace detail {

/// The point at arc-length fraction s in [0,1) around the unit square's border,
/// counter-clockwise from (0,0).
inline Eigen::Vector2d SquareBorder(double s) {
  s = 4.0 * (s - std::floor(s));
  if (s < 1) return {s, 0};
  if (s < 2) return {1, s - 1};
  if (s < 3) return {3 - s, 1};
  return {0, 4 - s};
}

inline double SignedArea(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                         const Eigen::Vector2d& c) {
  return 0.5 * ((b - a).x() * (c - a).y() - (c - a).x() * (b - a).y());
}

} // namespace detail

/// Parameterizes the disk (`points`, `triangles`) whose boundary loop is `boundary` (in the
/// triangles' orientation). Precondition: a topological disk whose boundary has at least four
/// vertices.
inline MvcParameterization ParameterizeMvc(const std::vector<Eigen::Vector3d>& points,
                                           const std::vector<std::array<int, 3>>& triangles,
                                           const std::vector<int>& boundary) {
  const int n = int(points.size());
  MvcParameterization out;
  out.uv.assign(n, Eigen::Vector2d::Zero());
  std::vector<int> unknown(n, 0);
  std::vector<char> on_boundary(n, 0);
  for (int v : boundary) on_boundary[v] = 1;
  // The boundary goes round the square by arc length, with the four vertices nearest the
  // quarter lengths pinned to the corners: otherwise each corner of the image would be cut
  // off by a boundary edge and stay empty.
  const int nb = int(boundary.size());
  std::vector<double> arc(nb + 1, 0.0);
  for (int i = 0; i < nb; ++i)
    arc[i + 1] = arc[i] + (points[boundary[(i + 1) % nb]] - points[boundary[i]]).norm();
  const double perimeter = arc[nb] > 0 ? arc[nb] : 1.0;
  std::array<int, 5> corner{{0, 0, 0, 0, nb}};
  for (int c = 1; c < 4; ++c) {
    int best = corner[c - 1] + 1;
    for (int i = best; i <= nb - (4 - c); ++i)
      if (std::abs(arc[i] - c * perimeter / 4) < std::abs(arc[best] - c * perimeter / 4)) best = i;
    corner[c] = best;
  }
  for (int c = 0; c < 4; ++c) {
    const double from = arc[corner[c]], span = std::max(arc[corner[c + 1]] - from, 1e-300);
    for (int i = corner[c]; i < corner[c + 1]; ++i)
      out.uv[boundary[i]] = detail::SquareBorder((c + (arc[i] - from) / span) / 4.0);
  }
  int nu = 0;
  for (int v = 0; v < n; ++v) unknown[v] = on_boundary[v] ? -1 : nu++;

  // Floater's weights from each triangle's angles: w_ij += tan(angle at i / 2) / |p_j - p_i|.
  std::vector<Eigen::Triplet<double>> a;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(nu, 2);
  std::vector<double> diag(n, 0.0);
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) {
      const int i = t[k], j = t[(k + 1) % 3], l = t[(k + 2) % 3];
      if (unknown[i] < 0) continue;
      const Eigen::Vector3d e1 = points[j] - points[i], e2 = points[l] - points[i];
      const double angle = std::atan2(e1.cross(e2).norm(), e1.dot(e2));
      const double h = std::tan(0.5 * angle);
      for (int other : {j, l}) {
        const double len = (points[other] - points[i]).norm();
        const double w = len > 0 ? h / len : 0.0;
        diag[i] += w;
        if (unknown[other] >= 0)
          a.emplace_back(unknown[i], unknown[other], -w);
        else
          rhs.row(unknown[i]) += w * out.uv[other].transpose();
      }
    }
  for (int v = 0; v < n; ++v)
    if (unknown[v] >= 0) a.emplace_back(unknown[v], unknown[v], diag[v] > 0 ? diag[v] : 1.0);
  if (nu > 0) {
    Eigen::SparseMatrix<double> A(nu, nu);
    A.setFromTriplets(a.begin(), a.end());
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
    lu.compute(A);
    if (lu.info() != Eigen::Success) return out;
    const Eigen::MatrixXd x = lu.solve(rhs);
    if (lu.info() != Eigen::Success || !x.allFinite()) return out;
    for (int v = 0; v < n; ++v)
      if (unknown[v] >= 0) out.uv[v] = x.row(unknown[v]).transpose();
  }
  out.solved = true;
  // The boundary runs counter-clockwise on the square; the triangles follow it.
  for (const auto& t : triangles) {
    const double area = detail::SignedArea(out.uv[t[0]], out.uv[t[1]], out.uv[t[2]]);
    if (area < 0)
      ++out.flipped;
    else if (area < 1e-14)
      ++out.degenerate;
  }
  return out;
}

} // namespace vcg_ext
