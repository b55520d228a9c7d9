#include <vcg_ext/self_intersections.h>

#include <gtest/gtest.h>

#include <random>

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

TEST(SelfIntersections, NamesTheTrianglesOfEachCrossing) {
  // A flat triangle, one far from it, and one that pierces the first: the pair (0, 2).
  const Points p{{0, 0, 0},  {2, 0, 0},      {0, 2, 0},     {9, 9, 0},    {10, 9, 0},
                 {9, 10, 0}, {0.5, 0.5, -1}, {0.5, 0.5, 1}, {1.5, 1.5, 1}};
  std::vector<std::pair<int, int>> pairs;
  EXPECT_EQ(vcg_ext::CountSelfIntersections(p, {{6, 7, 8}, {3, 4, 5}, {0, 1, 2}}, {}, &pairs), 1);
  EXPECT_EQ(pairs, (std::vector<std::pair<int, int>>{{0, 2}}));
}

TEST(SelfIntersections, TrianglesMeetingAtAVertexCrossWhenOneEdgePiercesTheOther) {
  // Both triangles have vertex 0; the second's far edge passes through the first.
  const Points p{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5, 0.5, -1}, {0.5, 0.5, 1}};
  EXPECT_EQ(vcg_ext::CountSelfIntersections(p, {{0, 1, 2}, {0, 3, 4}}), 1);
  // A fan neighbour tilted up out of the plane does not.
  const Points q{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {-1, 0, 1}, {0, -1, 1}};
  EXPECT_EQ(vcg_ext::CountSelfIntersections(q, {{0, 1, 2}, {0, 3, 4}}), 0);
}

TEST(SelfIntersections, TheSameCountAsEveryPairTestedOnATangledPatch) {
  // A grid whose inner vertices are thrown about, half its triangles tested: the sweep and the
  // bounds it skips by must count exactly the crossing pairs a test of every pair finds.
  Points p;
  Triangles t;
  Grid(12, p, t);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-1.5, 1.5);
  for (int y = 1; y < 12; ++y)
    for (int x = 1; x < 12; ++x)
      p[size_t(y * 13 + x)] += Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng));
  std::vector<char> tested(t.size(), 0);
  for (size_t f = 0; f < t.size(); ++f) tested[f] = (f / 24) % 2 == 0;
  int every_pair = 0, every_tested_pair = 0;
  for (size_t a = 0; a < t.size(); ++a)
    for (size_t b = a + 1; b < t.size(); ++b) {
      int shared = 0;
      for (int x = 0; x < 3; ++x)
        for (int y = 0; y < 3; ++y) shared += t[a][x] == t[b][y];
      if (shared >= 2 || !vcg_ext::detail::TrianglesCross(p, t[a], t[b])) continue;
      ++every_pair;
      every_tested_pair += tested[a] || tested[b];
    }
  ASSERT_GT(every_tested_pair, 10);
  ASSERT_LT(every_tested_pair, every_pair);
  EXPECT_EQ(vcg_ext::CountSelfIntersections(p, t), every_pair);
  EXPECT_EQ(vcg_ext::CountSelfIntersections(p, t, tested), every_tested_pair);
}

} // namespace
