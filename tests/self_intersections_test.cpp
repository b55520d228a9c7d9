#include <vcg_ext/self_intersections.h>

#include <gtest/gtest.h>

namespace {

using Points = std::vector<Eigen::Vector3d>;
using Triangles = std::vector<std::array<int, 3>>;

// A flat n x n grid of unit squares, two triangles each, in the plane z = 0.
void Grid(int n, Points& p, Triangles& t) {
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) p.emplace_back(x, y, 0);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const int a = y * (n + 1) + x, b = a + 1, c = a + n + 1, d = c + 1;
      t.push_back({a, b, d});
      t.push_back({a, d, c});
    }
}

TEST(SelfIntersections, NoneOnAFlatGridNorOnABentOne) {
  Points p;
  Triangles t;
  Grid(6, p, t);
  EXPECT_EQ(vcg_ext::CountSelfIntersections(p, t), 0);
  for (auto& q : p) q.z() = 0.3 * q.x() * q.x();
  EXPECT_EQ(vcg_ext::CountSelfIntersections(p, t), 0);
}

TEST(SelfIntersections, TwoCrossingTrianglesWithoutSharedVertex) {
  const Points p{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5, 0.5, -1}, {0.5, 0.5, 1}, {1.5, 1.5, 1}};
  EXPECT_EQ(vcg_ext::CountSelfIntersections(p, {{0, 1, 2}, {3, 4, 5}}), 1);
  // Apart along x, their widest axis, so the sweep never pairs them.
  const Points q{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {3, 0, -1}, {3, 0, 1}, {4, 1, 1}};
  EXPECT_EQ(vcg_ext::CountSelfIntersections(q, {{0, 1, 2}, {3, 4, 5}}), 0);
}

TEST(SelfIntersections, TheSameCountWhicheverAxisThePatchLiesAlong) {
  // The tents of the test below, the grid turned so that it lies along each pair of axes in
  // turn: the sweep runs along the widest one, and the count must not depend on it.
  Points p;
  Triangles t;
  Grid(6, p, t);
  p[3 * 7 + 1] = Eigen::Vector3d(4, 3, 1);
  p[3 * 7 + 5] = Eigen::Vector3d(2, 3, 2);
  const int crossings = vcg_ext::CountSelfIntersections(p, t);
  ASSERT_GT(crossings, 0);
  for (int turn = 1; turn < 3; ++turn) {
    Points q = p;
    for (auto& v : q) v = Eigen::Vector3d(v[(turn + 2) % 3], v[turn % 3], v[(turn + 1) % 3]);
    EXPECT_EQ(vcg_ext::CountSelfIntersections(q, t), crossings) << "turn " << turn;
  }
}

TEST(SelfIntersections, TwoVerticesPulledAcrossEachOtherAreFound) {
  // Two tents rising from the grid towards each other: in the slice y = 3 one climbs from
  // (1, 0) to (4, 1), the other from (5, 0) to (2, 2), and they cross near x = 3.7.
  Points p;
  Triangles t;
  Grid(6, p, t);
  EXPECT_EQ(vcg_ext::CountSelfIntersections(p, t), 0);
  p[3 * 7 + 1] = Eigen::Vector3d(4, 3, 1);
  p[3 * 7 + 5] = Eigen::Vector3d(2, 3, 2);
  EXPECT_GT(vcg_ext::CountSelfIntersections(p, t), 0);
}

TEST(SelfIntersections, CountsOnlyPairsWithATestedTriangle) {
  const Points p{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5, 0.5, -1}, {0.5, 0.5, 1}, {1.5, 1.5, 1}};
  const Triangles t{{0, 1, 2}, {3, 4, 5}};
  EXPECT_EQ(vcg_ext::CountSelfIntersections(p, t, {0, 0}), 0);
  EXPECT_EQ(vcg_ext::CountSelfIntersections(p, t, {1, 0}), 1);
}

TEST(SelfIntersections, TrianglesMeetingAtAVertexCrossWhenOneEdgePiercesTheOther) {
  // Both triangles have vertex 0; the second's far edge passes through the first.
  const Points p{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5, 0.5, -1}, {0.5, 0.5, 1}};
  EXPECT_EQ(vcg_ext::CountSelfIntersections(p, {{0, 1, 2}, {0, 3, 4}}), 1);
  // A fan neighbour tilted up out of the plane does not.
  const Points q{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {-1, 0, 1}, {0, -1, 1}};
  EXPECT_EQ(vcg_ext::CountSelfIntersections(q, {{0, 1, 2}, {0, 3, 4}}), 0);
}

} // namespace
