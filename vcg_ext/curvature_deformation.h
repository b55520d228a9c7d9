// Stage 9: deform a hole's patch until its mean curvature matches the inpainted curvature
// image (paper, section 3.8), in two modes.
//
// Direct (ours): the mean-curvature normal is the Laplace-Beltrami of position, so the free
// vertices solve  M^-1 W x = 2 H n  (cotangent Laplacian, H signed convex < 0 as everywhere
// in the product) with the rest of the patch fixed; normals and weights are re-estimated from
// the result a few times. A few sparse solves instead of hundreds of small steps.
//
// Paper: a vertex whose colour differs from the target colour by more than the similitude in
// any channel is a control vertex and moves by the transformation constant along its normal,
// inwards towards red (concave), outwards towards blue (convex); a bi-Laplacian (cotangent)
// spreads the control moves over the other free vertices; repeat until no vertex differs.
#pragma once

#include "apss_curvature.h"
#include "curvature_colormap.h"
#include "hole_fairing.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <array>
#include <cmath>
#include <vector>

namespace vcg_ext {

struct DeformationResult {
  int iterations = 0;
  int last_differing = 0;     ///< paper mode: vertices still over the similitude
  std::vector<int> differing; ///< paper mode: differing vertices per iteration
  double max_move = 0;        ///< largest displacement of any vertex
  bool solved = true;
};

namespace detail {

inline std::vector<Eigen::Vector3d> VertexNormals(const std::vector<Eigen::Vector3d>& p,
                                                  const std::vector<std::array<int, 3>>& tris) {
  std::vector<Eigen::Vector3d> n(p.size(), Eigen::Vector3d::Zero());
  for (const auto& t : tris) {
    const Eigen::Vector3d f = TriangleNormal(p[t[0]], p[t[1]], p[t[2]]);
    for (int v : t) n[v] += f;
  }
  for (auto& x : n)
    if (x.norm() > 0) x.normalize();
  return n;
}

/// Cotangent matrix W (negative semi-definite) and lumped masses of a triangle set.
inline Eigen::SparseMatrix<double> CotanMatrix(const std::vector<Eigen::Vector3d>& p,
                                               const std::vector<std::array<int, 3>>& tris,
                                               std::vector<double>& mass) {
  std::vector<Eigen::Triplet<double>> t;
  mass.assign(p.size(), 0.0);
  for (const auto& tri : tris) {
    for (int k = 0; k < 3; ++k) {
      const int i = tri[k], j = tri[(k + 1) % 3], o = tri[(k + 2) % 3];
      const double w = 0.5 * ClampedCot(p[o], p[i], p[j]);
      t.emplace_back(i, j, w), t.emplace_back(j, i, w), t.emplace_back(i, i, -w),
          t.emplace_back(j, j, -w);
    }
    const double area = 0.5 * TriangleNormal(p[tri[0]], p[tri[1]], p[tri[2]]).norm();
    for (int v : tri) mass[v] += area / 3;
  }
  Eigen::SparseMatrix<double> W(p.size(), p.size());
  W.setFromTriplets(t.begin(), t.end());
  return W;
}

/// Solves A_ff x_f = rhs_f - A_fk x_k for the free rows of a symmetric A (negated when
/// `negative`, so the factorization sees a positive definite matrix).
inline bool SolveFree(const Eigen::SparseMatrix<double>& A, const std::vector<char>& free,
                      const Eigen::MatrixXd& rhs, std::vector<Eigen::Vector3d>& x, bool negative) {
  const int n = int(x.size());
  std::vector<int> index(n, -1);
  int nf = 0;
  for (int i = 0; i < n; ++i)
    if (free[i]) index[i] = nf++;
  if (nf == 0) return true;
  std::vector<Eigen::Triplet<double>> t;
  Eigen::MatrixXd b(nf, 3);
  for (int i = 0; i < n; ++i)
    if (index[i] >= 0) b.row(index[i]) = rhs.row(i);
  const double s = negative ? -1.0 : 1.0;
  for (int col = 0; col < A.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, col); it; ++it) {
      const int r = int(it.row());
      if (index[r] < 0) continue;
      if (index[col] >= 0)
        t.emplace_back(index[r], index[col], s * it.value());
      else
        b.row(index[r]) -= it.value() * x[col].transpose();
    }
  b *= s;
  Eigen::SparseMatrix<double> Aff(nf, nf);
  Aff.setFromTriplets(t.begin(), t.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(Aff);
  if (ldlt.info() != Eigen::Success) return false;
  const Eigen::MatrixXd sol = ldlt.solve(b);
  if (!sol.allFinite()) return false;
  for (int i = 0; i < n; ++i)
    if (index[i] >= 0) x[i] = sol.row(index[i]).transpose();
  return true;
}

} // namespace detail

/// Signed mean curvature of every vertex as the direct mode measures it: half the cotangent
/// Laplacian of position along the normal (meaningful where the vertex's ring is complete).
inline std::vector<double> DiscreteMeanCurvature(const std::vector<Eigen::Vector3d>& points,
                                                 const std::vector<std::array<int, 3>>& triangles) {
  std::vector<double> mass;
  const Eigen::SparseMatrix<double> W = detail::CotanMatrix(points, triangles, mass);
  const auto normals = detail::VertexNormals(points, triangles);
  Eigen::MatrixXd x(points.size(), 3);
  for (size_t i = 0; i < points.size(); ++i) x.row(i) = points[i].transpose();
  const Eigen::MatrixXd lx = W * x;
  std::vector<double> h(points.size(), 0.0);
  for (size_t i = 0; i < points.size(); ++i)
    if (mass[i] > 0) h[i] = 0.5 * lx.row(i).dot(normals[i].transpose()) / mass[i];
  return h;
}

struct DirectDeformationParams {
  int iterations = 4; ///< solves, each with normals and weights from the previous result
  /// DeformToCurvatureImage: rounds after the first, each asking for `apss_gain` times what
  /// the last result's APSS curvature still lacks of the image's. None by default: they bring
  /// a fill further from the truth on some holes (docs/experiments.md, "The figures behind the
  /// defaults").
  int apss_passes = 0;
  double apss_gain = 0.5;
};

/// Direct mode. `points` (in place) and `triangles` form a consistently oriented disk; vertices
/// with free[i] move, the others stay; target_h[i] is the wanted signed mean curvature of
/// each free vertex (in the units of `points`).
inline DeformationResult DeformToCurvatureDirect(std::vector<Eigen::Vector3d>& points,
                                                 const std::vector<std::array<int, 3>>& triangles,
                                                 const std::vector<char>& free,
                                                 const std::vector<double>& target_h,
                                                 const DirectDeformationParams& params = {}) {
  DeformationResult result;
  const std::vector<Eigen::Vector3d> start = points;
  for (int it = 0; it < params.iterations; ++it) {
    std::vector<double> mass;
    const Eigen::SparseMatrix<double> W = detail::CotanMatrix(points, triangles, mass);
    const auto normals = detail::VertexNormals(points, triangles);
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(points.size(), 3);
    for (size_t i = 0; i < points.size(); ++i)
      if (free[i]) rhs.row(i) = (2.0 * target_h[i] * mass[i] * normals[i]).transpose();
    if (!detail::SolveFree(W, free, rhs, points, true)) {
      points = start;
      result.solved = false;
      return result;
    }
    result.iterations = it + 1;
  }
  for (size_t i = 0; i < points.size(); ++i)
    result.max_move = std::max(result.max_move, (points[i] - start[i]).norm());
  return result;
}

/// Direct mode towards a curvature image: target_value[i] is the image's colour-map value at
/// free vertex i, value[i] the patch's own as the image was painted (APSS `apss`; value =
/// 0.5 + 0.5 H / scale, clamped to [0, 1]). The first round asks each free vertex for its
/// discrete curvature plus the change the image asks for, so an unchanged image leaves the
/// patch unchanged. APSS fits several rings wide smooth away part of what a cotangent solve
/// puts in, so each further round measures the result as the image was painted and asks for
/// a share of what is still missing (clamped like the colour map: a saturated pixel asks for
/// nothing more). A round is kept only where it brings the measured curvature closer to the
/// image's (RMS over the free vertices) and `acceptable` (if given) takes its result; the
/// first one that does not ends the rounds. `solved` is false only when the first round could
/// not be solved.
template <class Acceptable>
DeformationResult
DeformToCurvatureImage(std::vector<Eigen::Vector3d>& points,
                       const std::vector<std::array<int, 3>>& triangles,
                       const std::vector<char>& free, const std::vector<double>& target_value,
                       const std::vector<double>& value, double scale, const ApssParams& apss,
                       const DirectDeformationParams& params, Acceptable acceptable) {
  const std::vector<Eigen::Vector3d> start = points;
  std::vector<double> h = DiscreteMeanCurvature(points, triangles);
  for (size_t i = 0; i < h.size(); ++i)
    if (free[i]) h[i] += 2 * scale * (target_value[i] - value[i]);
  DeformationResult result = DeformToCurvatureDirect(points, triangles, free, h, params);
  std::vector<int> query;
  for (size_t i = 0; i < free.size(); ++i)
    if (free[i]) query.push_back(int(i));
  // What the image still asks of each free vertex, in colour-map units, and its RMS.
  std::vector<double> missing(query.size(), 0.0);
  auto measure = [&](const std::vector<Eigen::Vector3d>& p) {
    const std::vector<double> h_now =
        ApssMeanCurvature(p, detail::VertexNormals(p, triangles), query, apss);
    double sum = 0;
    for (size_t q = 0; q < query.size(); ++q) {
      const double now = std::isfinite(h_now[q]) ? CurvatureColormap::Value(h_now[q], scale)
                                                 : target_value[size_t(query[q])];
      missing[q] = target_value[size_t(query[q])] - now;
      sum += missing[q] * missing[q];
    }
    return query.empty() ? 0.0 : std::sqrt(sum / double(query.size()));
  };
  double residual = params.apss_passes > 0 && result.solved ? measure(points) : 0.0;
  for (int pass = 0; result.solved && pass < params.apss_passes; ++pass) {
    std::vector<double> h_next = h;
    for (size_t q = 0; q < query.size(); ++q)
      h_next[size_t(query[q])] += params.apss_gain * 2 * scale * missing[q];
    const std::vector<Eigen::Vector3d> last = points;
    const DeformationResult round =
        DeformToCurvatureDirect(points, triangles, free, h_next, params);
    const double now = round.solved ? measure(points) : residual;
    if (!round.solved || !(now < residual) || !acceptable(points)) {
      points = last;
      break;
    }
    h = h_next;
    residual = now;
    result.iterations += round.iterations;
  }
  result.max_move = 0;
  for (size_t i = 0; i < points.size(); ++i)
    result.max_move = std::max(result.max_move, (points[i] - start[i]).norm());
  return result;
}

/// DeformToCurvatureImage taking every round's result that comes closer to the image.
inline DeformationResult DeformToCurvatureImage(std::vector<Eigen::Vector3d>& points,
                                                const std::vector<std::array<int, 3>>& triangles,
                                                const std::vector<char>& free,
                                                const std::vector<double>& target_value,
                                                const std::vector<double>& value, double scale,
                                                const ApssParams& apss,
                                                const DirectDeformationParams& params = {}) {
  return DeformToCurvatureImage(points, triangles, free, target_value, value, scale, apss, params,
                                [](const std::vector<Eigen::Vector3d>&) { return true; });
}

struct PaperDeformationParams {
  double similitude = 30; ///< colour difference (0-255, any channel) that marks a control vertex
  double transformation_constant = 0.00005; ///< move per iteration, unit-box units
  int max_iterations = 400;
  ApssParams apss;
};

/// Paper mode. As DeformToCurvatureDirect, with target_value[i] the colour-map value of the
/// inpainted image at free vertex i and `scale` the curvature that maps to the ends of the
/// colour map (value = 0.5 + 0.5 H / scale). `points` are unit-box coordinates.
inline DeformationResult DeformToCurvaturePaper(std::vector<Eigen::Vector3d>& points,
                                                const std::vector<std::array<int, 3>>& triangles,
                                                const std::vector<char>& free,
                                                const std::vector<double>& target_value,
                                                double scale,
                                                const PaperDeformationParams& params = {}) {
  DeformationResult result;
  const std::vector<Eigen::Vector3d> start = points;
  std::vector<int> query(points.size());
  for (size_t i = 0; i < query.size(); ++i) query[i] = int(i);
  // A free vertex next to a fixed one sits on the seam between the moving fill and the scan,
  // where the curvature is the seam's, not the surface's: it follows the spreading instead of
  // steering (as a control it would push the seam further at every step, without end).
  std::vector<char> steers(free);
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k)
      if (!free[t[k]]) steers[t[(k + 1) % 3]] = steers[t[(k + 2) % 3]] = 0;
  for (int it = 0; it < params.max_iterations; ++it) {
    const auto normals = detail::VertexNormals(points, triangles);
    const std::vector<double> h = ApssMeanCurvature(points, normals, query, params.apss);
    std::vector<Eigen::Vector3d> move(points.size(), Eigen::Vector3d::Zero());
    std::vector<char> control(points.size(), 0);
    int differing = 0;
    for (size_t i = 0; i < points.size(); ++i) {
      if (!steers[i] || !std::isfinite(h[i])) continue;
      const double value = CurvatureColormap::Value(h[i], scale);
      const Eigen::Vector3d diff =
          CurvatureColormap::Color(target_value[i]) - CurvatureColormap::Color(value);
      if (diff.cwiseAbs().maxCoeff() <= params.similitude) continue;
      ++differing;
      control[i] = 1;
      // Towards red (more concave) the surface goes in, towards blue (convex) it comes out.
      move[i] =
          (target_value[i] > value ? -1.0 : 1.0) * params.transformation_constant * normals[i];
    }
    result.differing.push_back(differing);
    result.last_differing = differing;
    if (differing == 0) break;
    // Spread the control moves: bi-Laplacian displacement with the controls and the fixed
    // part of the patch as constraints.
    std::vector<double> mass;
    const Eigen::SparseMatrix<double> W = detail::CotanMatrix(points, triangles, mass);
    Eigen::VectorXd minv(points.size());
    for (size_t i = 0; i < mass.size(); ++i) minv[i] = mass[i] > 0 ? 1 / mass[i] : 0;
    const Eigen::SparseMatrix<double> A = W * minv.asDiagonal() * W;
    std::vector<char> spread(points.size(), 0);
    for (size_t i = 0; i < points.size(); ++i) spread[i] = free[i] && !control[i];
    std::vector<Eigen::Vector3d> d = move;
    if (!detail::SolveFree(A, spread, Eigen::MatrixXd::Zero(points.size(), 3), d, false)) {
      result.solved = false;
      break;
    }
    for (size_t i = 0; i < points.size(); ++i)
      if (free[i]) points[i] += d[i];
    result.iterations = it + 1;
  }
  for (size_t i = 0; i < points.size(); ++i)
    result.max_move = std::max(result.max_move, (points[i] - start[i]).norm());
  return result;
}

} // namespace vcg_ext
