// Stage 2a (vcg_ext/hole_triangulation.h) on its own: a loop closed by n - 2 triangles over its
// own vertices, oriented like the faces around it, never over an edge the mesh already has.
#include <vcg_ext/hole_triangulation.h>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

namespace {

/// A planar loop of `n` points on the unit circle in z = 0, with the faces beside it in that
/// plane (their normals +z).
struct CircleLoop {
  std::vector<Eigen::Vector3d> points, side_normals, vertex_normals;
  explicit CircleLoop(int n) {
    for (int i = 0; i < n; ++i) {
      const double a = 2 * M_PI * i / n;
      points.emplace_back(std::cos(a), std::sin(a), 0);
      side_normals.emplace_back(0, 0, 1);
      vertex_normals.emplace_back(0, 0, 1);
    }
  }
};

/// Every loop edge once and every chord twice, in opposite directions: a closed disk.
void ExpectClosesTheLoop(const vcg_ext::HoleTriangulation& t, int n) {
  ASSERT_TRUE(t.complete);
  ASSERT_EQ(t.triangles.size(), size_t(n - 2));
  std::map<std::pair<int, int>, int> directed;
  for (const auto& tri : t.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{tri[size_t(k)], tri[size_t((k + 1) % 3)]}];
  for (const auto& e : directed) {
    EXPECT_EQ(e.second, 1) << "edge " << e.first.first << "-" << e.first.second << " twice";
    const bool loop_edge = (e.first.second - e.first.first + n) % n == 1 ||
                           (e.first.first - e.first.second + n) % n == 1;
    const bool opposite = directed.count({e.first.second, e.first.first}) > 0;
    EXPECT_NE(loop_edge, opposite) << "edge " << e.first.first << "-" << e.first.second;
  }
}

TEST(HoleTriangulation, ALoopIsClosedByTrianglesOrientedLikeTheFacesAroundIt) {
  const int n = 12;
  const CircleLoop loop(n);
  const vcg_ext::HoleTriangulation t =
      vcg_ext::TriangulateHole(loop.points, loop.side_normals, loop.vertex_normals, {});
  EXPECT_EQ(t.method, "liepa-dp");
  ExpectClosesTheLoop(t, n);
  // The loop's edges run i -> i+1 in the faces beside it, so the fill runs them backwards.
  for (const auto& tri : t.triangles)
    for (int k = 0; k < 3; ++k)
      EXPECT_NE((tri[size_t((k + 1) % 3)] - tri[size_t(k)] + n) % n, 1)
          << "a fill triangle runs a loop edge the way its face does";
}

TEST(HoleTriangulation, AChordTheMeshAlreadyHasIsNeverUsed) {
  const int n = 8;
  const CircleLoop loop(n);
  std::set<vcg_ext::LocalEdge> forbidden;
  for (int i = 2; i < n - 1; ++i) forbidden.insert(vcg_ext::MakeLocalEdge(0, i));
  const vcg_ext::HoleTriangulation t =
      vcg_ext::TriangulateHole(loop.points, loop.side_normals, loop.vertex_normals, forbidden);
  ExpectClosesTheLoop(t, n);
  for (const auto& tri : t.triangles)
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(forbidden.count(vcg_ext::MakeLocalEdge(tri[size_t(k)], tri[size_t((k + 1) % 3)])),
                0u);
}

TEST(HoleTriangulation, LoopsBeyondTheDynamicProgrammeTakeTheEars) {
  const int n = 40;
  const CircleLoop loop(n);
  vcg_ext::HoleTriangulationParams p;
  p.dp_max_edges = 20;
  const vcg_ext::HoleTriangulation t =
      vcg_ext::TriangulateHole(loop.points, loop.side_normals, loop.vertex_normals, {}, p);
  EXPECT_EQ(t.method, "vcg-ears");
  ExpectClosesTheLoop(t, n);
}

} // namespace
