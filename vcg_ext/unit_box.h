// Stage 0: the unit box every stage computes in.
//
// Curvature values and the paper's constants (similitude, transformation constant 5e-5) are
// defined for a mesh scaled into the unit bounding box. The mesh itself is never rescaled:
// rescaling a float mesh and back would change every vertex in its last bits. Stages read
// positions through ToUnit() in double precision and write new ones back through FromUnit().
#pragma once

#include <Eigen/Core>
#include <vcg/complex/complex.h>

#include <algorithm>

namespace vcg_ext {

/// Similarity that maps a mesh's bounding box into [0,1]^3, its longest side onto [0,1].
struct UnitBox {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  double scale = 1.0; ///< unit length per user length

  template <class Scalar>
  Eigen::Vector3d ToUnit(const vcg::Point3<Scalar>& p) const {
    return (Eigen::Vector3d(p[0], p[1], p[2]) - origin) * scale;
  }
  template <class Scalar>
  vcg::Point3<Scalar> FromUnit(const Eigen::Vector3d& u) const {
    const Eigen::Vector3d p = u / scale + origin;
    return vcg::Point3<Scalar>(Scalar(p.x()), Scalar(p.y()), Scalar(p.z()));
  }
  /// A length in unit-box units expressed in the user's units.
  double LengthFromUnit(double l) const { return l / scale; }
};

/// The unit box of the live (not deleted) vertices of `m`.
/// Precondition: coordinates are finite. A mesh with no extent maps with scale 1.
template <class MeshType>
UnitBox ComputeUnitBox(const MeshType& m) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector3d hi = -lo;
  bool any = false;
  for (const auto& v : m.vert) {
    if (v.IsD()) continue;
    const Eigen::Vector3d p(v.cP()[0], v.cP()[1], v.cP()[2]);
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
    any = true;
  }
  UnitBox box;
  if (!any) return box;
  box.origin = lo;
  const double side = (hi - lo).maxCoeff();
  box.scale = side > 0 ? 1.0 / side : 1.0;
  return box;
}

} // namespace vcg_ext
