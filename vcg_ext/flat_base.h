// Stage 2, the coarse fill's choice of a flat cap: a hole that is a cut base. The underside a
// statue stands on, or the flat bottom of a scanned object, is where the scanner never looks:
// its hole is large, its loop lies nearly in a plane, and the surface beside it leaves that
// plane at a crease. A thin plate continues the walls into a dome below the base, and the
// object no longer stands. A small hole on a sphere looks the same at its loop; what tells
// them apart is the surface farther out: a sphere's keeps turning towards closing the dome, a
// wall's does not.
#pragma once

#include "unit_box.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace vcg_ext {

/// The plane of a hole's loop (least squares) and how far the loop strays from it.
struct LoopPlane {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double off_plane = 0; ///< the largest distance of a loop point from the plane
  double size = 0;      ///< the diagonal of the loop's bounding box
};

/// \pre points is not empty.
inline LoopPlane FitLoopPlane(const std::vector<Eigen::Vector3d>& points) {
  LoopPlane plane;
  for (const auto& p : points) plane.centre += p;
  plane.centre /= double(points.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  Eigen::AlignedBox3d box;
  for (const auto& p : points)
    cov += (p - plane.centre) * (p - plane.centre).transpose(), box.extend(p);
  plane.normal = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvectors().col(0);
  for (const auto& p : points)
    plane.off_plane = std::max(plane.off_plane, std::abs((p - plane.centre).dot(plane.normal)));
  plane.size = box.diagonal().norm();
  return plane;
}

struct FlatBaseParams {
  /// The loop's largest distance from its plane, as a share of its size: a scanned base's
  /// rim is ragged (the lion statue's 1.8 %).
  double max_off_plane = 0.02;
  /// Degrees between the faces beside the loop and its plane: the base's rim is a crease.
  double min_wall_angle = 35;
  /// The surface from a quarter to half the loop's radius beyond it turns towards closing a
  /// dome by less than this share of what a sphere through the loop at the same slope would.
  double max_turn = 0.5;
};

/// Whether the hole of `loop_points` (unit box `box`; `plane` its FitLoopPlane, `side_normals`
/// the unit normals of the faces beside its edges) is a cut base of mesh `m` (FlatBaseParams):
/// nearly planar, its rim a crease, and the surface beyond it not turning on as a sphere's
/// would. Reads every face of `m` near the loop where the loop passes the first two tests.
/// \pre loop_points is not empty.
template <class MeshType>
bool IsFlatBase(const MeshType& m, const LoopPlane& plane,
                const std::vector<Eigen::Vector3d>& loop_points,
                const std::vector<Eigen::Vector3d>& side_normals, const UnitBox& box,
                const FlatBaseParams& params = {}) {
  if (!(plane.off_plane <= params.max_off_plane * plane.size)) return false;
  auto angle = [&](const Eigen::Vector3d& n) {
    return std::acos(std::min(1.0, std::abs(n.dot(plane.normal))));
  };
  double wall = 0;
  int walls = 0;
  for (const auto& n : side_normals)
    if (n.squaredNorm() > 0) wall += angle(n), ++walls;
  if (walls == 0) return false;
  wall /= walls;
  if (!(wall >= params.min_wall_angle * M_PI / 180)) return false;

  // The faces from a quarter to half the loop's radius beyond it (by their centres' distance
  // from the nearest of up to 256 loop points): their mean angle to the plane, weighted by area.
  double radius = 0;
  for (const auto& p : loop_points) radius += (p - plane.centre).norm();
  radius /= double(loop_points.size());
  std::vector<Eigen::Vector3d> samples;
  const size_t step = std::max<size_t>(1, loop_points.size() / 256);
  for (size_t i = 0; i < loop_points.size(); i += step) samples.push_back(loop_points[i]);
  Eigen::AlignedBox3d near;
  for (const auto& p : loop_points) near.extend(p);
  near.min().array() -= 0.5 * radius;
  near.max().array() += 0.5 * radius;
  double turned = 0, distance = 0, area = 0;
  for (const auto& f : m.face) {
    if (f.IsD()) continue;
    const Eigen::Vector3d a = box.ToUnit(f.cV(0)->cP()), b = box.ToUnit(f.cV(1)->cP()),
                          c = box.ToUnit(f.cV(2)->cP());
    const Eigen::Vector3d centroid = (a + b + c) / 3;
    if (!near.contains(centroid)) continue;
    double d = std::numeric_limits<double>::infinity();
    for (const auto& s : samples) d = std::min(d, (centroid - s).norm());
    if (d < 0.25 * radius || d >= 0.5 * radius) continue;
    const Eigen::Vector3d n = (b - a).cross(c - a);
    const double w = 0.5 * n.norm();
    if (!(w > 0)) continue;
    turned += w * angle(n.normalized());
    distance += w * d;
    area += w;
  }
  if (!(area > 0)) return false;
  // A sphere through the loop at the walls' slope has radius radius / sin(wall): over a
  // distance s along it the normal turns by s sin(wall) / radius.
  const double sphere_turn = distance / area * std::sin(wall) / radius;
  return turned / area - wall < params.max_turn * sphere_turn;
}

} // namespace vcg_ext
