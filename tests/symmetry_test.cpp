// The symmetry detector and the mirrored fill on synthetic objects with a known plane.
#include "test_mesh.h"

#include <vcg_ext/mirrored_fill.h>
#include <vcg_ext/reflective_symmetry.h>

#include <vcg/complex/algorithms/update/normal.h>
#include <wrap/io_trimesh/import_ply.h>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <string>

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

TEST(ReflectiveSymmetry, ThePlanesDoNotDependOnTheThreads) {
  test::Mesh m;
  MakeSymmetricEgg(m);
  std::vector<Eigen::Vector3d> points, normals;
  Sample(m, 0.45 * kRotation, Eigen::Vector3d(0.5, 0.4, 0.6), points, normals);
  vcg_ext::SymmetryParams one, three;
  one.threads = 1;
  three.threads = 3;
  vcg_ext::SymmetryPlane best_one, best_three;
  const auto a = vcg_ext::DetectReflectiveSymmetry(points, normals, one, &best_one);
  const auto b = vcg_ext::DetectReflectiveSymmetry(points, normals, three, &best_three);
  ASSERT_EQ(a.size(), b.size());
  ASSERT_FALSE(a.empty());
  for (size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].normal, b[k].normal);
    EXPECT_EQ(a[k].offset, b[k].offset);
    EXPECT_EQ(a[k].coverage, b[k].coverage);
  }
  EXPECT_EQ(best_one.normal, best_three.normal);
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

/// The vertices of one of the meshes beside the project, in its unit box.
void SampleSharedMesh(const std::string& name, std::vector<Eigen::Vector3d>& points,
                      std::vector<Eigen::Vector3d>& normals) {
  test::Mesh m;
  int mask = 0;
  const std::string path = std::string(CI_SHARED_MESHES) + "/" + name;
  ASSERT_EQ(vcg::tri::io::ImporterPLY<test::Mesh>::Open(m, path.c_str(), mask), 0);
  vcg::tri::UpdateBounding<test::Mesh>::Box(m);
  const double scale = 1.0 / m.bbox.Dim()[m.bbox.MaxDim()];
  const Eigen::Vector3d origin(m.bbox.min[0], m.bbox.min[1], m.bbox.min[2]);
  Sample(m, scale * Eigen::Matrix3d::Identity(), -scale * origin, points, normals);
}

TEST(ReflectiveSymmetry, FindsNoneOnTheBunny) {
  std::vector<Eigen::Vector3d> points, normals;
  SampleSharedMesh("stanford_bunny.ply", points, normals);
  vcg_ext::SymmetryPlane best;
  EXPECT_TRUE(
      vcg_ext::DetectReflectiveSymmetry(points, normals, vcg_ext::SymmetryParams(), &best).empty())
      << "coverage " << best.coverage;
}

TEST(ReflectiveSymmetry, FindsThePosedHorsesPlaneAsAPartialSymmetry) {
  std::vector<Eigen::Vector3d> points, normals;
  SampleSharedMesh("horse.ply", points, normals);
  vcg_ext::SymmetryPlane best;
  std::vector<vcg_ext::SymmetryPlane> partial;
  EXPECT_TRUE(
      vcg_ext::DetectReflectiveSymmetry(points, normals, vcg_ext::SymmetryParams(), &best, &partial)
          .empty())
      << "its legs and head are posed: coverage " << best.coverage;
  ASSERT_FALSE(partial.empty());
  // Its body's plane, across the x axis.
  EXPECT_GT(std::abs(partial[0].normal.x()), std::cos(5 * M_PI / 180));
  EXPECT_GE(partial[0].coverage, vcg_ext::SymmetryParams().min_partial_coverage);
}

/// The wavy sheet x = Sheet(y, z): features everywhere, so a ring on it pins its place.
double Sheet(double y, double z) {
  return 1 + 0.08 * std::sin(6 * y) * std::cos(5 * z);
}

TEST(MirroredFill, RegistersTheMirrorImageOntoATwinOffItsMirrorPlace) {
  // The object's other half (x < 0) is the sheet's mirror image moved by `shift` along y, as
  // a posed limb's twin lies beside the mirror place of the limb. The hole is the disc of
  // radius 0.3 around (Sheet(0, 0), 0, 0); its fill starts flat at x = 1.
  const double shift = 0.1, radius = 0.3, step = 0.02;
  std::vector<Eigen::Vector3d> known, normals;
  for (double y = -1.2; y <= 1.2; y += step)
    for (double z = -1.2; z <= 1.2; z += step) {
      const double yy = y - shift;
      known.emplace_back(-Sheet(yy, z), y, z);
      // Outwards (towards -x): minus the gradient of x + Sheet(y - shift, z).
      normals.push_back(-Eigen::Vector3d(1, 0.48 * std::cos(6 * yy) * std::cos(5 * z),
                                         -0.4 * std::sin(6 * yy) * std::sin(5 * z))
                             .normalized());
    }
  // The patch: a grid of the sheet within 2 radii, the disc's vertices free and flat.
  std::vector<Eigen::Vector3d> points;
  std::vector<char> free;
  std::map<std::pair<int, int>, int> index;
  const int cells = int(std::lround(2 * radius / step));
  for (int i = -cells; i <= cells; ++i)
    for (int j = -cells; j <= cells; ++j) {
      const double y = i * step, z = j * step;
      if (std::hypot(y, z) > 2 * radius) continue;
      index[{i, j}] = int(points.size());
      const bool in_hole = std::hypot(y, z) < radius;
      points.emplace_back(in_hole ? 1.0 : Sheet(y, z), y, z);
      free.push_back(in_hole);
    }
  std::vector<std::array<int, 3>> triangles;
  for (const auto& e : index) {
    const int i = e.first.first, j = e.first.second;
    const auto b = index.find({i + 1, j}), c = index.find({i, j + 1}),
               d = index.find({i + 1, j + 1});
    if (b == index.end() || c == index.end() || d == index.end()) continue;
    triangles.push_back({{e.second, b->second, d->second}});
    triangles.push_back({{e.second, d->second, c->second}});
  }
  const vcg_ext::PointIndex points_index(known);
  vcg_ext::KnownSurface surface;
  surface.index = &points_index;
  surface.normals = &normals;
  vcg_ext::SymmetryPlane plane; // x = 0
  auto worst_error = [&](const vcg_ext::MirroredFillParams& params) {
    const vcg_ext::MirroredFill fill =
        vcg_ext::MirrorFill(points, triangles, free, plane, surface, radius, params);
    EXPECT_TRUE(fill.problem.empty()) << fill.problem;
    double worst = 0;
    for (size_t i = 0; i < points.size(); ++i)
      if (free[i])
        worst = std::max(
            worst, std::abs(fill.points[i].x() - Sheet(fill.points[i].y(), fill.points[i].z())));
    return worst;
  };
  vcg_ext::MirroredFillParams reflected;
  reflected.registration_rounds = 0;
  const double without = worst_error(reflected);
  const double with = worst_error(vcg_ext::MirroredFillParams());
  EXPECT_GT(without, 0.04) << "the reflection alone reads the twin shifted";
  EXPECT_LT(with, 0.6 * without) << "registered, it reads the twin nearer its place";
}

} // namespace
