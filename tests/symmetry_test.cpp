// The symmetry detector and the mirrored fill on synthetic objects with a known plane.
#include "test_mesh.h"

#include <vcg_ext/mirrored_fill.h>
#include <vcg_ext/reflective_symmetry.h>

#include <vcg/complex/algorithms/update/normal.h>
#include <wrap/io_trimesh/import_ply.h>

#include <gtest/gtest.h>

#include <random>

namespace {

/// Oriented vertices of a mesh, moved by (rotation times a scale, shift).
void Sample(test::Mesh& m, const Eigen::Matrix3d& rotation, const Eigen::Vector3d& shift,
            std::vector<Eigen::Vector3d>& points, std::vector<Eigen::Vector3d>& normals) {
  vcg::tri::UpdateNormal<test::Mesh>::PerVertexNormalizedPerFace(m);
  for (const auto& v : m.vert) {
    points.push_back(rotation * Eigen::Vector3d(v.cP()[0], v.cP()[1], v.cP()[2]) + shift);
    normals.push_back((rotation * Eigen::Vector3d(v.cN()[0], v.cN()[1], v.cN()[2])).normalized());
  }
}

/// An egg mirror-symmetric across x = 0 only (its radius depends on x through x^2), with bumps
/// in mirrored pairs, of radius about 1.
void MakeSymmetricEgg(test::Mesh& m) {
  test::MakeSphere(m, 1, 5);
  const std::vector<Eigen::Vector3d> bumps{{0.7, 0.5, 0.5}, {0.4, -0.6, 0.7}, {0.6, 0.1, -0.8}};
  for (auto& v : m.vert) {
    const Eigen::Vector3d p = Eigen::Vector3d(v.P()[0], v.P()[1], v.P()[2]).normalized();
    double r = 1 + 0.25 * p.y() + 0.15 * p.y() * p.z() + 0.1 * p.z() * p.z();
    for (Eigen::Vector3d b : bumps)
      for (int side : {1, -1}) {
        b.x() = side * std::abs(b.x());
        r += 0.08 * std::exp(-(p - b.normalized()).squaredNorm() / 0.04);
      }
    v.P() = vcg::Point3f(float(r * p.x()), float(r * p.y()), float(r * p.z()));
  }
}

const Eigen::Matrix3d kRotation =
    (Eigen::AngleAxisd(0.4, Eigen::Vector3d(0.3, 1, 0.2).normalized()) *
     Eigen::AngleAxisd(-0.7, Eigen::Vector3d::UnitZ()))
        .toRotationMatrix();

TEST(ReflectiveSymmetry, FindsThePlaneOfASymmetricObjectUnderNoise) {
  test::Mesh m;
  MakeSymmetricEgg(m);
  // Noise along the normals, 0.2 % of the egg's size, then the egg turned and moved off the
  // axes and scaled into about a unit box.
  vcg::tri::UpdateNormal<test::Mesh>::PerVertexNormalizedPerFace(m);
  std::mt19937 rng(7);
  std::normal_distribution<float> noise(0, 0.004f);
  for (auto& v : m.vert) v.P() += v.N() * noise(rng);
  std::vector<Eigen::Vector3d> points, normals;
  const Eigen::Vector3d shift(0.5, 0.4, 0.6);
  Sample(m, 0.45 * kRotation, shift, points, normals);
  const double diagonal = 0.45 * 2 * std::sqrt(3.0); // about
  const auto planes = vcg_ext::DetectReflectiveSymmetry(points, normals, vcg_ext::SymmetryParams());
  ASSERT_FALSE(planes.empty());
  const Eigen::Vector3d truth = kRotation * Eigen::Vector3d::UnitX();
  const double angle = std::acos(std::min(1.0, std::abs(planes[0].normal.dot(truth)))) * 180 / M_PI;
  EXPECT_LT(angle, 1.0);
  // The plane passes through the egg's centre (the shift) where the true one does.
  const double sign = planes[0].normal.dot(truth) < 0 ? -1 : 1;
  EXPECT_LT(std::abs(sign * planes[0].offset - truth.dot(shift)), 0.005 * diagonal);
  EXPECT_GT(planes[0].coverage, 0.9);
}

TEST(ReflectiveSymmetry, FindsNoneOnATwistedObject) {
  // An ellipsoid twisted about its long axis is chiral: no plane mirrors it onto itself.
  test::Mesh m;
  test::MakeSphere(m, 1, 5);
  for (auto& v : m.vert) {
    const double x = v.P()[0], t = 1.2 * x + 0.4;
    const double y = 0.55 * v.P()[1], z = 0.25 * v.P()[2];
    v.P() = vcg::Point3f(float(x), float(std::cos(t) * y - std::sin(t) * z),
                         float(std::sin(t) * y + std::cos(t) * z));
  }
  std::vector<Eigen::Vector3d> points, normals;
  Sample(m, 0.5 * kRotation, Eigen::Vector3d(0.5, 0.5, 0.5), points, normals);
  vcg_ext::SymmetryPlane best;
  EXPECT_TRUE(
      vcg_ext::DetectReflectiveSymmetry(points, normals, vcg_ext::SymmetryParams(), &best).empty())
      << "coverage " << best.coverage;
}

TEST(ReflectiveSymmetry, FindsNoneOnTheBunny) {
  test::Mesh m;
  int mask = 0;
  ASSERT_EQ(
      vcg::tri::io::ImporterPLY<test::Mesh>::Open(m, CI_SHARED_MESHES "/stanford_bunny.ply", mask),
      0);
  vcg::tri::UpdateBounding<test::Mesh>::Box(m);
  const double scale = 1.0 / m.bbox.Dim()[m.bbox.MaxDim()];
  std::vector<Eigen::Vector3d> points, normals;
  const Eigen::Vector3d origin(m.bbox.min[0], m.bbox.min[1], m.bbox.min[2]);
  Sample(m, scale * Eigen::Matrix3d::Identity(), -scale * origin, points, normals);
  vcg_ext::SymmetryPlane best;
  EXPECT_TRUE(
      vcg_ext::DetectReflectiveSymmetry(points, normals, vcg_ext::SymmetryParams(), &best).empty())
      << "coverage " << best.coverage;
}

} // namespace
