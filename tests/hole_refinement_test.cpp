// Stage 2b (vcg_ext/hole_refinement.h) on its own: a fill refined to the density around it,
// its loop untouched, and locally Delaunay where it is not refined.
#include <vcg_ext/hole_refinement.h>
#include <vcg_ext/hole_triangulation.h>

#include <gtest/gtest.h>

#include <cmath>

namespace {

/// A fan-free start: the unit circle's loop of `n` points in z = 0, triangulated by stage 2a.
vcg_ext::HolePatch CirclePatch(int n) {
  vcg_ext::HolePatch patch;
  patch.boundary_count = n;
  std::vector<Eigen::Vector3d> normals;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n;
    patch.points.emplace_back(std::cos(a), std::sin(a), 0);
    normals.emplace_back(0, 0, 1);
  }
  patch.triangles = vcg_ext::TriangulateHole(patch.points, normals, normals, {}).triangles;
  return patch;
}

double LongestEdge(const vcg_ext::HolePatch& patch) {
  double longest = 0;
  for (const auto& t : patch.triangles)
    for (int k = 0; k < 3; ++k)
      longest = std::max(longest, (patch.points[size_t(t[size_t(k)])] -
                                   patch.points[size_t(t[size_t((k + 1) % 3)])])
                                      .norm());
  return longest;
}

TEST(HoleRefinement, TheFillGetsTheDensityOfItsLoopAndKeepsTheLoop) {
  const int n = 48;
  vcg_ext::HolePatch patch = CirclePatch(n);
  const std::vector<Eigen::Vector3d> loop(patch.points.begin(), patch.points.end());
  const double spacing = 2 * M_PI / n;
  const int inserted = vcg_ext::RefineHolePatch(patch, std::vector<double>(size_t(n), spacing));
  EXPECT_GT(inserted, n) << "a disk of this loop's spacing holds more vertices than its loop";
  EXPECT_EQ(patch.NewVertexCount(), inserted);
  EXPECT_EQ(patch.parents.size(), size_t(inserted));
  EXPECT_EQ(patch.triangles.size(), size_t(n - 2 + 2 * inserted)) << "still one disk";
  for (int i = 0; i < n; ++i) EXPECT_EQ(patch.points[size_t(i)], loop[size_t(i)]);
  EXPECT_LT(LongestEdge(patch), 3 * spacing) << "no long sliver left across the hole";
  for (size_t v = size_t(n); v < patch.points.size(); ++v) {
    EXPECT_LT(patch.points[v].head<2>().norm(), 1.0) << "an inserted vertex outside the loop";
    EXPECT_NEAR(patch.points[v].z(), 0, 1e-12);
  }
}

TEST(HoleRefinement, RelaxingFlipsTheFillUntilItIsLocallyDelaunay) {
  // An ellipse's loop closed by a fan from one vertex: long thin triangles, far from Delaunay.
  const int n = 16;
  vcg_ext::HolePatch patch;
  patch.boundary_count = n;
  for (int i = 0; i < n; ++i)
    patch.points.emplace_back(3 * std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n), 0);
  for (int i = 1; i + 1 < n; ++i) patch.triangles.push_back({0, i + 1, i});
  EXPECT_GT(vcg_ext::RelaxHolePatch(patch), 0);
  ASSERT_EQ(patch.triangles.size(), size_t(n - 2));
  // Every interior edge: the two angles opposite it sum to at most pi.
  for (size_t t = 0; t < patch.triangles.size(); ++t)
    for (size_t u = t + 1; u < patch.triangles.size(); ++u)
      for (int k = 0; k < 3; ++k) {
        const int a = patch.triangles[t][size_t(k)], b = patch.triangles[t][size_t((k + 1) % 3)];
        const int c = patch.triangles[t][size_t((k + 2) % 3)];
        for (int j = 0; j < 3; ++j)
          if (patch.triangles[u][size_t(j)] == b && patch.triangles[u][size_t((j + 1) % 3)] == a) {
            const int d = patch.triangles[u][size_t((j + 2) % 3)];
            const double opposite =
                vcg_ext::detail::Angle(patch.points[size_t(c)], patch.points[size_t(a)],
                                       patch.points[size_t(b)]) +
                vcg_ext::detail::Angle(patch.points[size_t(d)], patch.points[size_t(a)],
                                       patch.points[size_t(b)]);
            EXPECT_LE(opposite, M_PI + 1e-9) << "edge " << a << "-" << b;
          }
      }
}

} // namespace
