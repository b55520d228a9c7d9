// Stage 2c: fair a hole's fill (Liepa 2003, section 3.5; Botsch & Kobbelt 2004): the inserted
// vertices solve the bi-Laplace equation  L^2 x = 0  with cotangent weights, L = M^-1 W, while
// the loop and the ring of vertices beyond it stay fixed. Only the patch and those two rings
// enter the sparse system, never the whole mesh, so the cost of a hole does not grow with the
// size of the mesh around it.
#pragma once

#include "hole_patch.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>

#include <cmath>
#include <vector>

namespace vcg_ext {

namespace detail {

/// Cotangent of the angle at `at`, with the angle kept within about 2.6 degrees of 0 and pi
/// (|cot| <= 22) so that the slivers a scan's hole border often has cannot dominate the system.
inline double ClampedCot(const Eigen::Vector3d& at, const Eigen::Vector3d& a,
                         const Eigen::Vector3d& b) {
  const Eigen::Vector3d u = a - at, v = b - at;
  const double len = u.norm() * v.norm();
  if (len <= 0) return 0;
  const double cosine = std::max(-0.999, std::min(0.999, u.dot(v) / len));
  return cosine / std::sqrt(1 - cosine * cosine);
}

} // namespace detail

struct HoleFairingParams {
  /// The cotangent weights depend on the geometry they fair, so the solve is repeated with
  /// weights taken from the previous result (the first uses the flat refined patch, which
  /// underestimates how far the fill should bulge: on the Igea nose, 1 pass leaves 2.1 % of
  /// the diagonal of error, 5 passes 1.5 %).
  int max_iterations = 6;
  /// Stop once no vertex moves more than this fraction of the patch's mean edge length.
  double tolerance = 0.02;
};

/// Fairs the inserted vertices of `patch` in place. Returns false, leaving the patch as it was,
/// when the system cannot be solved (a degenerate neighbourhood). A patch without inserted
/// vertices is already fair.
inline bool FairHolePatch(HolePatch& patch, const HoleCollar& collar,
                          const HoleFairingParams& params = {}) {
  const int nb = patch.boundary_count;
  const int np = int(patch.points.size());
  const int nu = np - nb;
  if (nu <= 0) return true;
  const int n = np + int(collar.outer_points.size());
  std::vector<Eigen::Vector3d> P(patch.points);
  P.insert(P.end(), collar.outer_points.begin(), collar.outer_points.end());
  std::vector<std::array<int, 3>> tris(patch.triangles);
  for (auto t : collar.triangles) {
    for (int& v : t)
      if (v < 0) v = np + (-v - 1);
    tris.push_back(t);
  }
  double mean_edge = 0;
  for (const auto& t : patch.triangles) mean_edge += (P[t[0]] - P[t[1]]).norm();
  mean_edge /= std::max<size_t>(patch.triangles.size(), 1);

  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
  bool analyzed = false;
  for (int iteration = 0; iteration < params.max_iterations; ++iteration) {
    std::vector<Eigen::Triplet<double>> wt;
    wt.reserve(tris.size() * 12);
    std::vector<double> mass(n, 0.0);
    for (const auto& t : tris) {
      for (int k = 0; k < 3; ++k) {
        const int i = t[k], j = t[(k + 1) % 3], o = t[(k + 2) % 3];
        const double w = 0.5 * detail::ClampedCot(P[o], P[i], P[j]);
        wt.emplace_back(i, j, w);
        wt.emplace_back(j, i, w);
        wt.emplace_back(i, i, -w);
        wt.emplace_back(j, j, -w);
      }
      const double area = 0.5 * TriangleNormal(P[t[0]], P[t[1]], P[t[2]]).norm();
      for (int v : t) mass[v] += area / 3.0;
    }
    Eigen::SparseMatrix<double> W(n, n);
    W.setFromTriplets(wt.begin(), wt.end());
    Eigen::VectorXd minv(n);
    for (int i = 0; i < n; ++i) minv[i] = mass[i] > 0 ? 1.0 / mass[i] : 0.0;
    const Eigen::SparseMatrix<double> A = W * minv.asDiagonal() * W;

    // A's rows of the unknowns, split into unknown columns and fixed ones (right-hand side).
    std::vector<Eigen::Triplet<double>> auu;
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(nu, 3);
    for (int col = 0; col < A.outerSize(); ++col)
      for (Eigen::SparseMatrix<double>::InnerIterator it(A, col); it; ++it) {
        const int row = int(it.row());
        if (row < nb || row >= np) continue;
        if (col >= nb && col < np)
          auu.emplace_back(row - nb, col - nb, it.value());
        else
          rhs.row(row - nb) -= it.value() * P[col].transpose();
      }
    Eigen::SparseMatrix<double> Auu(nu, nu);
    Auu.setFromTriplets(auu.begin(), auu.end());

    Eigen::MatrixXd x;
    if (!analyzed) ldlt.analyzePattern(Auu), analyzed = true;
    ldlt.factorize(Auu);
    if (ldlt.info() == Eigen::Success) x = ldlt.solve(rhs);
    if (ldlt.info() != Eigen::Success || !x.allFinite()) {
      Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
      lu.compute(Auu);
      if (lu.info() != Eigen::Success) return iteration > 0;
      x = lu.solve(rhs);
      if (lu.info() != Eigen::Success || !x.allFinite()) return iteration > 0;
    }
    double moved = 0;
    for (int u = 0; u < nu; ++u) {
      const Eigen::Vector3d q = x.row(u).transpose();
      moved = std::max(moved, (q - P[nb + u]).norm());
      P[nb + u] = q;
      patch.points[nb + u] = q;
    }
    if (moved < params.tolerance * mean_edge) break;
  }
  return true;
}

} // namespace vcg_ext
