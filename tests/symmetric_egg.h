// A mirror-symmetric test object for the symmetry prior on MeshLab's mesh type: an egg with
// bumps in mirrored pairs, and the holes punched over them.
#pragma once

#include "pipeline/meshlab_mesh.h"
#include <vcg/complex/algorithms/create/platonic.h>
#include <vcg_ext/punch_hole.h>

#include <Eigen/Core>

#include <cmath>
#include <vector>

namespace test {

/// The egg's radius in direction p (unit) without its bumps: mirror-symmetric across x = 0
/// only (x enters through the unit direction alone, y and yz break the other planes).
inline double EggRadius(const Eigen::Vector3d& p) {
  return 1 + 0.25 * p.y() + 0.15 * p.y() * p.z() + 0.1 * p.z() * p.z();
}

const double kEggBump = 0.08;

/// Bumps of the egg: each on the +x side with its twin mirrored across x = 0.
inline std::vector<Eigen::Vector3d> EggBumps() {
  std::vector<Eigen::Vector3d> b{{0.7, 0.5, 0.5},   {-0.7, 0.5, 0.5}, {0.4, -0.6, 0.7},
                                 {-0.4, -0.6, 0.7}, {0.6, 0.1, -0.8}, {-0.6, 0.1, -0.8}};
  for (auto& x : b) x.normalize();
  return b;
}

inline void MakeSymmetricEgg(CMeshO& m) {
  vcg::tri::Sphere(m, 5);
  for (auto& v : m.vert) {
    const Eigen::Vector3d p = Eigen::Vector3d(v.P()[0], v.P()[1], v.P()[2]).normalized();
    double r = EggRadius(p);
    for (const auto& b : EggBumps()) r += kEggBump * std::exp(-(p - b).squaredNorm() / 0.04);
    v.P() = Point3m(Scalarm(r * p.x()), Scalarm(r * p.y()), Scalarm(r * p.z()));
  }
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
  vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
}

/// Punches the hole over bump b: every face with a vertex within 0.35 of its tip.
inline void PunchBump(CMeshO& m, const Eigen::Vector3d& b) {
  const Eigen::Vector3d tip = (EggRadius(b) + kEggBump) * b;
  vcg_ext::PunchHole(m, Point3m(Scalarm(tip.x()), Scalarm(tip.y()), Scalarm(tip.z())),
                     Scalarm(0.35));
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
}

/// Height over the bare egg of the fill vertex nearest to direction b.
inline double FillHeight(const CMeshO& m, size_t first_new_vertex, const Eigen::Vector3d& b) {
  double best = -1, height = 0;
  for (size_t v = first_new_vertex; v < m.vert.size(); ++v) {
    const Eigen::Vector3d p(m.vert[v].cP()[0], m.vert[v].cP()[1], m.vert[v].cP()[2]);
    const double c = p.normalized().dot(b);
    if (c > best) best = c, height = p.norm() - EggRadius(p.normalized());
  }
  return height;
}

} // namespace test
