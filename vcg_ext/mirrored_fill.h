// A hole's fill from the object's mirror image: every fill vertex is reflected across a
// symmetry plane, put on the known surface there, and reflected back; the mirrored context
// ring is registered onto the hole's own ring (rigid, then a smooth non-rigid correction that
// is exact on the ring), so the mirrored shape meets the hole's border where the two halves
// of a real object differ a little. Before it is read, the mirror image is moved towards the
// counterpart by iterative closest points on the ring (a posed limb's twin lies beside the
// limb's mirror place).
#pragma once

#include "reflective_symmetry.h"

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <array>
#include <string>
#include <vector>

namespace vcg_ext {

/// The known surface the mirror images are put on: oriented points (the scan's vertices, no
/// fill), in the same frame as the patch, with one ball of them left out (a fake hole's own
/// surface, which its fill must not see).
struct KnownSurface {
  const PointIndex* index = nullptr;
  const std::vector<Eigen::Vector3d>* normals = nullptr;
  Eigen::Vector3d excluded_centre = Eigen::Vector3d::Zero();
  double excluded_radius = 0;
};

struct MirroredFillParams {
  /// A vertex's mirror image lies on the known surface when the nearest known point is within
  /// this many hole radii of it along its normal (the coarse fill the image starts from is that
  /// far from the truth at most) and within `max_beside` across: beyond a known surface's edge
  /// (in another hole) its tangent plane says nothing.
  double max_gap = 0.5;
  double max_beside = 0.15;
  double min_covered = 0.8; ///< of the fill's vertices, for the fill to be offered
  int neighbours = 4;       ///< known points whose tangent planes the image is put on
  /// Rounds of iterative closest points that move the mirror image onto the known surface
  /// before it is read (0: the reflection as it is); the motion is kept within
  /// `max_registration` hole radii. Chosen on the tuning holes (docs/experiments.md, "The figures
  /// behind the defaults").
  int registration_rounds = 30;
  double max_registration = 1.0;
};

struct MirroredFill {
  std::vector<Eigen::Vector3d> points; ///< the whole patch, fill vertices moved
  double covered = 0;                  ///< fraction of the fill's vertices with a mirror image
  /// RMS distance of the rigidly registered mirrored ring to the real one, in hole radii: how
  /// far the two halves differ around the hole.
  double ring_residual = 0;
  std::string problem; ///< why there is no fill; empty if there is one
};

namespace detail {

/// Solves the graph Laplacian's harmonic interpolation of `values` (3-vectors) from the
/// vertices with `fixed` set to the others, on the patch's edges.
inline void HarmonicInterpolation(const std::vector<std::array<int, 3>>& triangles,
                                  const std::vector<char>& fixed,
                                  std::vector<Eigen::Vector3d>& values) {
  const int n = int(values.size());
  std::vector<int> unknown(size_t(n), -1);
  int count = 0;
  for (int i = 0; i < n; ++i)
    if (!fixed[size_t(i)]) unknown[size_t(i)] = count++;
  if (count == 0) return;
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(count, 3);
  std::vector<double> degree(size_t(count), 0);
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) {
      // Each edge is seen from both of its triangles (once from a border triangle): the
      // weights stay symmetric either way.
      const int a = t[size_t(k)], b = t[size_t((k + 1) % 3)];
      for (const auto& uv : {std::pair<int, int>{a, b}, std::pair<int, int>{b, a}}) {
        const int u = uv.first, v = uv.second;
        const int row = unknown[size_t(u)];
        if (row < 0) continue;
        degree[size_t(row)] += 1;
        if (unknown[size_t(v)] >= 0)
          entries.emplace_back(row, unknown[size_t(v)], -1.0);
        else
          rhs.row(row) += values[size_t(v)].transpose();
      }
    }
  // A little mass keeps a part with no fixed vertex solvable (its values go to zero there).
  for (int r = 0; r < count; ++r) entries.emplace_back(r, r, degree[size_t(r)] + 1e-9);
  Eigen::SparseMatrix<double> a(count, count);
  a.setFromTriplets(entries.begin(), entries.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(a);
  if (solver.info() != Eigen::Success) return;
  const Eigen::MatrixXd x = solver.solve(rhs);
  for (int i = 0; i < n; ++i)
    if (unknown[size_t(i)] >= 0) values[size_t(i)] = x.row(unknown[size_t(i)]).transpose();
}

/// A rotation and a translation.
struct RigidMotion {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
};

/// The rigid motion that takes `from` closest to `to` in the least-squares sense (Kabsch).
inline RigidMotion Kabsch(const std::vector<Eigen::Vector3d>& from,
                          const std::vector<Eigen::Vector3d>& to) {
  RigidMotion m;
  if (from.empty()) return m;
  Eigen::Vector3d ca = Eigen::Vector3d::Zero(), cb = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < from.size(); ++i) ca += from[i], cb += to[i];
  ca /= double(from.size()), cb /= double(from.size());
  Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
  for (size_t i = 0; i < from.size(); ++i) h += (from[i] - ca) * (to[i] - cb).transpose();
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  d(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0 ? -1 : 1;
  m.rotation = svd.matrixV() * d * svd.matrixU().transpose();
  m.translation = cb - m.rotation * ca;
  return m;
}

/// The point of the known surface at `y`, on the tangent planes of the `neighbours` known
/// points nearest it (smooth between points, unlike the points themselves); false where the
/// nearest lies more than `gap` off y along its normal or `beside` off it across.
inline bool KnownSurfaceAt(const KnownSurface& known, int neighbours, double gap, double beside,
                           const Eigen::Vector3d& y, Eigen::Vector3d& at) {
  const auto& surface = known.index->Points();
  const auto& normals = *known.normals;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double weights = 0;
  int used = 0;
  for (int j : known.index->NearestK(y, 2 * neighbours)) {
    const Eigen::Vector3d& v = surface[size_t(j)];
    if (known.excluded_radius > 0 && (v - known.excluded_centre).norm() < known.excluded_radius)
      continue;
    const double d2 = (v - y).squaredNorm();
    const Eigen::Vector3d& nv = normals[size_t(j)];
    const double along = (y - v).dot(nv);
    if (used == 0 && (std::abs(along) > gap || d2 - along * along > beside * beside)) break;
    const double w = 1 / (d2 + 1e-12);
    sum += w * (y - (y - v).dot(nv) * nv);
    weights += w;
    if (++used == neighbours) break;
  }
  if (weights <= 0) return false;
  at = sum / weights;
  return true;
}

/// The two halves of a real object differ by more than noise (a limb posed differently, a
/// head turned a little): the reflection alone puts the ring beside its counterpart, and
/// the image read there is the counterpart's shape shifted. A rigid motion after the
/// reflection, found by iterative closest points on the ring (each round registers the
/// ring's images onto their feet on the known surface, `on_surface`), moves it towards the
/// counterpart. The feet lie along the normals, so each round slides only part of the way
/// along the surface: the rounds are few enough to stop short of a full registration, which
/// slides onto neighbouring features more often than it helps. `reflected`: the patch's
/// points reflected; the ring is where `free` is 0.
template <class OnSurface>
RigidMotion RegisterReflection(const std::vector<Eigen::Vector3d>& reflected,
                               const std::vector<char>& free, const OnSurface& on_surface,
                               const MirroredFillParams& params, double radius) {
  const size_t n = reflected.size();
  Eigen::Matrix3d motion = Eigen::Matrix3d::Identity();
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();
  for (int round = 0; round < params.registration_rounds; ++round) {
    std::vector<Eigen::Vector3d> from, to;
    for (size_t i = 0; i < n; ++i) {
      Eigen::Vector3d at;
      if (free[i]) continue;
      const Eigen::Vector3d y = motion * reflected[i] + shift;
      if (on_surface(y, at)) from.push_back(y), to.push_back(at);
    }
    if (from.size() < 10) break;
    const RigidMotion step = Kabsch(from, to);
    const Eigen::Matrix3d next_motion = step.rotation * motion;
    const Eigen::Vector3d next_shift = step.rotation * shift + step.translation;
    // The motion's largest displacement of the ring, kept within bounds: beyond them it has
    // slid onto another part.
    double farthest = 0;
    for (size_t i = 0; i < n; ++i)
      if (!free[i])
        farthest =
            std::max(farthest, (next_motion * reflected[i] + next_shift - reflected[i]).norm());
    if (farthest > params.max_registration * radius) break;
    motion = next_motion, shift = next_shift;
    if (step.translation.norm() < 1e-4 * radius) break;
  }
  return {motion, shift};
}

} // namespace detail

/// The mirrored fill of a hole's patch (`points`, `triangles`; `free` marks the fill's
/// vertices, the rest is the known context around it) across `plane`, on `known`, for a hole
/// of radius `radius` (the patch's units). Fill vertices whose mirror image is not on the
/// known surface (a hole across the plane, its image in the hole itself) follow their
/// neighbours smoothly. A `problem` and no points when fewer than `min_covered` of the fill's
/// vertices, or fewer than ten of the ring's, have an image.
inline MirroredFill MirrorFill(const std::vector<Eigen::Vector3d>& points,
                               const std::vector<std::array<int, 3>>& triangles,
                               const std::vector<char>& free, const SymmetryPlane& plane,
                               const KnownSurface& known, double radius,
                               const MirroredFillParams& params) {
  MirroredFill out;
  const size_t n = points.size();
  std::vector<Eigen::Vector3d> image(n);
  std::vector<char> has_image(n, 0);
  const double gap = params.max_gap * radius, beside = params.max_beside * radius;
  auto on_surface = [&](const Eigen::Vector3d& y, Eigen::Vector3d& at) {
    return detail::KnownSurfaceAt(known, params.neighbours, gap, beside, y, at);
  };
  // The two halves of a real object differ by more than noise (a limb posed differently, a
  // head turned a little): the reflection alone puts the ring beside its counterpart, and
  // the image read there is the counterpart's shape shifted. A rigid motion after the
  // reflection, found by iterative closest points on the ring (each round registers the
  // ring's images onto their feet on the known surface), moves it towards the counterpart.
  // The feet lie along the normals, so each round slides only part of the way along the
  // surface: the rounds are few enough to stop short of a full registration, which slides onto
  // neighbouring features more often than it helps.
  std::vector<Eigen::Vector3d> reflected(n);
  for (size_t i = 0; i < n; ++i) reflected[i] = plane.Reflect(points[i]);
  const detail::RigidMotion after =
      detail::RegisterReflection(reflected, free, on_surface, params, radius);
  const Eigen::Matrix3d& motion = after.rotation;
  const Eigen::Vector3d& shift = after.translation;
  auto mirrored = [&](size_t i) { return Eigen::Vector3d(motion * reflected[i] + shift); };
  for (size_t i = 0; i < n; ++i) {
    Eigen::Vector3d at;
    if (!on_surface(mirrored(i), at)) continue;
    image[i] = plane.Reflect(motion.transpose() * (at - shift));
    has_image[i] = 1;
  }
  int ring = 0, fill = 0, fill_imaged = 0;
  for (size_t i = 0; i < n; ++i) {
    if (free[i])
      ++fill, fill_imaged += has_image[i];
    else
      ring += has_image[i];
  }
  out.covered = fill ? double(fill_imaged) / fill : 0;
  if (fill == 0 || out.covered < params.min_covered) {
    out.problem = "its mirror image is on the known surface for " +
                  std::to_string(int(std::lround(100 * out.covered))) + " % of the fill";
    return out;
  }
  if (ring < 10) {
    out.problem = "its ring's mirror image is not on the known surface";
    return out;
  }
  // Rigid registration of the mirrored ring onto the ring.
  std::vector<Eigen::Vector3d> from, to;
  for (size_t i = 0; i < n; ++i)
    if (!free[i] && has_image[i]) from.push_back(image[i]), to.push_back(points[i]);
  const detail::RigidMotion onto = detail::Kabsch(from, to);
  auto registered = [&](size_t i) {
    return Eigen::Vector3d(onto.rotation * image[i] + onto.translation);
  };
  // The non-rigid correction: the ring's residuals, interpolated harmonically over the fill.
  std::vector<Eigen::Vector3d> correction(n, Eigen::Vector3d::Zero());
  std::vector<char> fixed(n, 0);
  double sum2 = 0;
  for (size_t i = 0; i < n; ++i)
    if (!free[i] && has_image[i]) {
      correction[i] = points[i] - registered(i);
      fixed[i] = 1;
      sum2 += correction[i].squaredNorm();
    }
  out.ring_residual = std::sqrt(sum2 / ring) / radius;
  detail::HarmonicInterpolation(triangles, fixed, correction);
  // The fill's displacements: the registered image where there is one, interpolated from
  // those (and from the ring, which stays) where there is none.
  std::vector<Eigen::Vector3d> move(n, Eigen::Vector3d::Zero());
  std::vector<char> known_move(n, 1);
  for (size_t i = 0; i < n; ++i) {
    if (!free[i]) continue;
    if (has_image[i])
      move[i] = registered(i) + correction[i] - points[i];
    else
      known_move[i] = 0;
  }
  detail::HarmonicInterpolation(triangles, known_move, move);
  out.points = points;
  for (size_t i = 0; i < n; ++i)
    if (free[i]) out.points[i] += move[i];
  return out;
}

} // namespace vcg_ext
