// The size of a hole from its fill: the ball around the fill's vertices, which the priors
// measure their tolerances in.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <vector>

namespace vcg_ext {

/// The centroid of the vertices with `free` set and the largest distance of one from it (the
/// hole's radius); false when no vertex is free.
inline bool FillExtent(const std::vector<Eigen::Vector3d>& points, const std::vector<char>& free,
                       Eigen::Vector3d* centre, double* radius) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  int count = 0;
  for (size_t i = 0; i < points.size(); ++i)
    if (free[i]) c += points[i], ++count;
  if (count == 0) return false;
  c /= count;
  double r = 0;
  for (size_t i = 0; i < points.size(); ++i)
    if (free[i]) r = std::max(r, (points[i] - c).norm());
  *centre = c;
  *radius = r;
  return true;
}

} // namespace vcg_ext
