// Reflective symmetry of a surface from its oriented samples: the planes that map most of the
// surface onto itself (a face, a bust, an animal, a machined part), found where the surface
// has holes too, so that a hole's mirror image can stand in for its missing shape.
//
// Candidate planes come from the principal axes through the centroid and from votes of sample
// pairs whose normals mirror each other across their bisector (Mitra, Guibas and Pauly 2006,
// with normals for their curvature signatures); each is refined by iterative closest points
// between the samples' mirror images and the surface, and accepted only when the mirror image
// of most of the samples lies on the surface.
#pragma once

#include "parallel_for.h"

#include <Eigen/Dense>
#include <vcg/space/index/kdtree/kdtree.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <unordered_map>
#include <vector>

namespace vcg_ext {

/// The plane n.x = offset and the reflection across it.
struct SymmetryPlane {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX(); ///< unit
  double offset = 0;
  double coverage = 0; ///< fraction of the samples whose mirror image lies on the surface
  double residual = 0; ///< RMS distance of those mirror images to the surface

  Eigen::Vector3d Reflect(const Eigen::Vector3d& p) const {
    return p - 2 * (normal.dot(p) - offset) * normal;
  }
  Eigen::Vector3d ReflectDirection(const Eigen::Vector3d& d) const {
    return d - 2 * normal.dot(d) * normal;
  }
};

/// Nearest neighbours among a fixed point set (vcglib's kd-tree, float precision: the
/// queries' answers are re-measured in double).
class PointIndex {
public:
  /// Precondition: `points` is not empty and outlives the index.
  explicit PointIndex(const std::vector<Eigen::Vector3d>& points) : points_(points) {
    std::vector<vcg::Point3f> p(points.size());
    for (size_t i = 0; i < p.size(); ++i)
      p[i] = vcg::Point3f(float(points[i].x()), float(points[i].y()), float(points[i].z()));
    tree_ = std::make_unique<vcg::KdTree<float>>(
        vcg::ConstDataWrapper<vcg::Point3f>(p.data(), int(p.size()), sizeof(vcg::Point3f)));
  }
  const std::vector<Eigen::Vector3d>& Points() const { return points_; }
  /// The index of the point nearest to q. Thread-safe.
  int Nearest(const Eigen::Vector3d& q) const {
    unsigned int index = 0;
    float d = 0;
    tree_->doQueryClosest(vcg::Point3f(float(q.x()), float(q.y()), float(q.z())), index, d);
    return int(index);
  }
  /// The indices of the k points nearest to q, nearest first. Thread-safe.
  std::vector<int> NearestK(const Eigen::Vector3d& q, int k) const {
    vcg::KdTree<float>::PriorityQueue queue;
    tree_->doQueryK(vcg::Point3f(float(q.x()), float(q.y()), float(q.z())), k, queue);
    std::vector<int> out(size_t(queue.getNofElements()));
    for (size_t i = 0; i < out.size(); ++i) out[i] = queue.getIndex(int(i));
    std::sort(out.begin(), out.end(), [&](int a, int b) {
      return (points_[size_t(a)] - q).squaredNorm() < (points_[size_t(b)] - q).squaredNorm();
    });
    return out;
  }

private:
  const std::vector<Eigen::Vector3d>& points_;
  std::unique_ptr<vcg::KdTree<float>> tree_;
};

struct SymmetryParams {
  /// A mirror image within this distance of the surface (and with its normal within 45 degrees
  /// of the surface's) lies on it. In the unit box, where a scanned face's two halves differ
  /// by about 1 %.
  double tolerance = 0.01;
  double min_coverage = 0.5; ///< of the samples, for a plane to be accepted
  /// Planes that mirror less than `min_coverage` but at least this share of the samples are
  /// partial symmetries (a posed animal: its legs and head turned, much of its body still
  /// mirrored): they never make the object symmetric, but a hole whose own surroundings they
  /// mirror may use them (docs/experiments.md, "The figures behind the defaults").
  double min_partial_coverage = 0.4;
  int samples = 2000;     ///< that vote and register
  int vote_samples = 700; ///< of those, every pair of which votes
  int candidates = 10;    ///< most voted planes refined, besides the principal axes
  int iterations = 30;    ///< of the closest-point registration
  int max_planes = 2;     ///< planes returned of each kind (whole, partial), best first
  uint32_t seed = 1;
  int threads = 0; ///< that refine the candidates (0: one per core); the planes do not depend on it
};

namespace detail {

/// The point of the surface nearest to m, as the foot of m on the tangent plane of the nearest
/// sample point (its index in `nearest`): a surface sampled more coarsely than the tolerance
/// still measures its distance right.
inline Eigen::Vector3d SurfacePoint(const PointIndex& index,
                                    const std::vector<Eigen::Vector3d>& normals,
                                    const Eigen::Vector3d& m, int* nearest) {
  const int j = index.Nearest(m);
  *nearest = j;
  const Eigen::Vector3d& q = index.Points()[size_t(j)];
  const Eigen::Vector3d& n = normals[size_t(j)];
  return m - (m - q).dot(n) * n;
}

/// Fraction of `samples` whose mirror image lies on the surface, and the RMS distance of those.
inline void MeasurePlane(const std::vector<int>& samples,
                         const std::vector<Eigen::Vector3d>& normals, const PointIndex& index,
                         double tolerance, SymmetryPlane& plane) {
  const auto& points = index.Points();
  int on = 0;
  double sum = 0;
  for (int i : samples) {
    const Eigen::Vector3d m = plane.Reflect(points[size_t(i)]);
    int j = 0;
    const double d = (SurfacePoint(index, normals, m, &j) - m).norm();
    const double agree = normals[size_t(j)].dot(plane.ReflectDirection(normals[size_t(i)]));
    // Off the surface's edge the foot on the tangent plane is no surface point.
    const bool beside = (points[size_t(j)] - m).norm() <= 2 * tolerance;
    if (d <= tolerance && beside && agree > 0.7) ++on, sum += d * d;
  }
  plane.coverage = samples.empty() ? 0 : double(on) / double(samples.size());
  plane.residual = on ? std::sqrt(sum / on) : 0;
}

/// Iterative closest points of the samples' mirror images, point to plane: each step pairs
/// every sample p with the surface point q nearest to its mirror image (within a shrinking
/// distance, normals agreeing) and moves the plane (Gauss-Newton on its two angles and its
/// offset) so that the mirror images come onto the tangent planes at the q.
inline void RefinePlane(const std::vector<int>& samples,
                        const std::vector<Eigen::Vector3d>& normals, const PointIndex& index,
                        const SymmetryParams& params, SymmetryPlane& plane) {
  const auto& points = index.Points();
  double reach = std::max(0.1, 4 * params.tolerance);
  for (int it = 0; it < params.iterations; ++it) {
    const Eigen::Vector3d n0 = plane.normal;
    const Eigen::Vector3d t1 = n0.unitOrthogonal(), t2 = n0.cross(t1);
    Eigen::Matrix3d jtj = Eigen::Matrix3d::Zero();
    Eigen::Vector3d jtr = Eigen::Vector3d::Zero();
    int pairs = 0;
    for (int i : samples) {
      const Eigen::Vector3d& p = points[size_t(i)];
      const Eigen::Vector3d m = plane.Reflect(p);
      const int j = index.Nearest(m);
      const Eigen::Vector3d& q = points[size_t(j)];
      const Eigen::Vector3d& nq = normals[size_t(j)];
      if ((q - m).norm() > reach) continue;
      if (nq.dot(plane.ReflectDirection(normals[size_t(i)])) < 0.5) continue;
      // r = nq . (R(p) - q) with R(p) = p - 2 (n.p - d) n, linear in (a, b, dd) for
      // n = n0 + a t1 + b t2, d = d0 + dd.
      const double s = n0.dot(p) - plane.offset, c = nq.dot(n0);
      const Eigen::Vector3d jac(-2 * (t1.dot(p) * c + s * nq.dot(t1)),
                                -2 * (t2.dot(p) * c + s * nq.dot(t2)), 2 * c);
      const double r = nq.dot(m - q);
      jtj += jac * jac.transpose();
      jtr += jac * r;
      ++pairs;
    }
    if (pairs < 10) return;
    const Eigen::Vector3d x = jtj.ldlt().solve(-jtr);
    if (!x.allFinite()) return;
    plane.normal = (n0 + x[0] * t1 + x[1] * t2).normalized();
    plane.offset += x[2];
    reach = std::max(2 * params.tolerance, 0.7 * reach);
    if (x.norm() < 1e-7 && reach <= 2 * params.tolerance) return;
  }
}

/// The plane with its normal's largest component positive (n and -n are one plane).
inline SymmetryPlane Canonical(Eigen::Vector3d n, double offset) {
  Eigen::Index k;
  n.cwiseAbs().maxCoeff(&k);
  if (n[k] < 0) n = -n, offset = -offset;
  SymmetryPlane plane;
  plane.normal = n;
  plane.offset = offset;
  return plane;
}

} // namespace detail

/// The reflective symmetry planes of the surface sampled by the points of `index` (with unit
/// `normals`), best coverage first; none when no plane maps `params.min_coverage` of the
/// samples onto the surface (`best`, if given, gets the best-covering plane, accepted or not;
/// `partial`, if given, the planes that map at least `params.min_partial_coverage` but less
/// than `min_coverage`). The points should sample the surface about evenly (a scan's vertices
/// do); holes lower the coverage by the share of the surface whose mirror image they removed.
/// The index is the caller's, who keeps it for looking up mirror images on the same surface.
/// Precondition: `normals` has the size of `index.Points()`.
inline std::vector<SymmetryPlane>
DetectReflectiveSymmetry(const PointIndex& index, const std::vector<Eigen::Vector3d>& normals,
                         const SymmetryParams& params, SymmetryPlane* best = nullptr,
                         std::vector<SymmetryPlane>* partial = nullptr) {
  std::vector<SymmetryPlane> found;
  const std::vector<Eigen::Vector3d>& points = index.Points();
  if (points.size() < 16 || normals.size() != points.size()) return found;
  std::mt19937 rng(params.seed);
  std::vector<int> order(points.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = int(i);
  std::shuffle(order.begin(), order.end(), rng);
  const std::vector<int> samples(
      order.begin(), order.begin() + std::min<size_t>(order.size(), size_t(params.samples)));
  const std::vector<int> check(
      order.begin() + std::min<size_t>(order.size(), size_t(params.samples)),
      order.begin() + std::min<size_t>(order.size(), 2 * size_t(params.samples)));
  const std::vector<int>& evaluate = check.size() >= samples.size() / 2 ? check : samples;

  std::vector<SymmetryPlane> guesses;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (int i : samples) centroid += points[size_t(i)];
  centroid /= double(samples.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (int i : samples)
    cov += (points[size_t(i)] - centroid) * (points[size_t(i)] - centroid).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axes(cov);
  for (int k = 0; k < 3; ++k)
    guesses.push_back(
        detail::Canonical(axes.eigenvectors().col(k), axes.eigenvectors().col(k).dot(centroid)));

  // Votes: every pair of the first vote_samples whose normals are each other's mirror images
  // across their bisector votes for that bisector, binned by direction (about 6 degrees) and
  // offset (a twentieth of the unit box).
  struct Bin {
    int votes = 0;
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    double offset = 0;
  };
  std::unordered_map<int64_t, Bin> bins;
  const size_t voters = std::min(samples.size(), size_t(params.vote_samples));
  for (size_t a = 0; a < voters; ++a)
    for (size_t b = a + 1; b < voters; ++b) {
      const Eigen::Vector3d& p = points[size_t(samples[a])];
      const Eigen::Vector3d& q = points[size_t(samples[b])];
      const double len = (p - q).norm();
      if (len < 4 * params.tolerance) continue;
      const Eigen::Vector3d m = (p - q) / len;
      const Eigen::Vector3d& np = normals[size_t(samples[a])];
      if ((np - 2 * np.dot(m) * m).dot(normals[size_t(samples[b])]) < 0.95) continue;
      const SymmetryPlane pl = detail::Canonical(m, m.dot(p + q) / 2);
      const int64_t key = (int64_t(std::lround(pl.normal.x() * 10)) + 16) +
                          32 * ((int64_t(std::lround(pl.normal.y() * 10)) + 16) +
                                32 * ((int64_t(std::lround(pl.normal.z() * 10)) + 16) +
                                      32 * (int64_t(std::lround(pl.offset * 20)) + 1024)));
      Bin& bin = bins[key];
      ++bin.votes;
      bin.normal += pl.normal;
      bin.offset += pl.offset;
    }
  std::vector<Bin> voted;
  for (const auto& kv : bins) voted.push_back(kv.second);
  std::sort(voted.begin(), voted.end(), [](const Bin& a, const Bin& b) {
    return a.votes != b.votes     ? a.votes > b.votes
           : a.offset != b.offset ? a.offset < b.offset
                                  : a.normal.x() < b.normal.x();
  });
  for (size_t k = 0; k < voted.size() && int(k) < 8 * params.candidates; ++k)
    guesses.push_back(
        detail::Canonical(voted[k].normal.normalized(), voted[k].offset / voted[k].votes));
  // A round object votes for every plane through its centre about as much as for its true
  // symmetry: the guesses are ranked by a quick coverage (a few hundred samples, twice the
  // tolerance) and only the best are refined.
  {
    const std::vector<int> quick(samples.begin(),
                                 samples.begin() + std::min<size_t>(samples.size(), 300));
    ParallelFor(int(guesses.size()), params.threads, [&](int k) {
      detail::MeasurePlane(quick, normals, index, 2 * params.tolerance, guesses[size_t(k)]);
    });
    std::stable_sort(
        guesses.begin(), guesses.end(),
        [](const SymmetryPlane& a, const SymmetryPlane& b) { return a.coverage > b.coverage; });
    if (int(guesses.size()) > params.candidates) guesses.resize(size_t(params.candidates));
  }

  // Each guess is refined on its own; the index answers queries from any thread.
  std::vector<SymmetryPlane> refined(guesses);
  ParallelFor(int(refined.size()), params.threads, [&](int k) {
    SymmetryPlane& plane = refined[size_t(k)];
    detail::RefinePlane(samples, normals, index, params, plane);
    plane = detail::Canonical(plane.normal, plane.offset);
    detail::MeasurePlane(evaluate, normals, index, params.tolerance, plane);
  });
  std::stable_sort(
      refined.begin(), refined.end(),
      [](const SymmetryPlane& a, const SymmetryPlane& b) { return a.coverage > b.coverage; });
  std::vector<SymmetryPlane> partial_found;
  auto same_as_one_of = [&](const SymmetryPlane& plane, const std::vector<SymmetryPlane>& list) {
    for (const SymmetryPlane& f : list)
      if (f.normal.dot(plane.normal) > std::cos(5 * M_PI / 180) &&
          std::abs(f.offset - plane.offset) < 4 * params.tolerance)
        return true;
    return false;
  };
  for (const SymmetryPlane& plane : refined) {
    const bool whole = plane.coverage >= params.min_coverage;
    if (!whole && plane.coverage < params.min_partial_coverage) break;
    std::vector<SymmetryPlane>& list = whole ? found : partial_found;
    if (int(list.size()) < params.max_planes && !same_as_one_of(plane, found) &&
        !same_as_one_of(plane, partial_found))
      list.push_back(plane);
  }
  if (partial) *partial = partial_found;
  if (best && !refined.empty()) *best = refined.front();
  return found;
}

/// The same, for `points` with no index yet (none when they are fewer than 16 or `normals` has
/// another size).
inline std::vector<SymmetryPlane>
DetectReflectiveSymmetry(const std::vector<Eigen::Vector3d>& points,
                         const std::vector<Eigen::Vector3d>& normals, const SymmetryParams& params,
                         SymmetryPlane* best = nullptr,
                         std::vector<SymmetryPlane>* partial = nullptr) {
  if (points.size() < 16 || normals.size() != points.size()) return {};
  return DetectReflectiveSymmetry(PointIndex(points), normals, params, best, partial);
}

} // namespace vcg_ext
