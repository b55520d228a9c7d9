// Stage 1 (vcg_ext/hole_loops.h) on its own: the holes of a mesh as simple loops, in the
// faces' direction, and the ones the parameters leave open.
#include "test_mesh.h"

#include <vcg_ext/edge_census.h>
#include <vcg_ext/hole_loops.h>

#include <gtest/gtest.h>

#include <set>

namespace {

/// The unit sphere with two holes on opposite sides, spanning `first` and `second` degrees, its
/// edges and its loops with the default parameters.
struct TwoHoledSphere {
  test::Mesh m;
  vcg_ext::EdgeCensus census;
  vcg_ext::HoleLoops loops;
  TwoHoledSphere(float first, float second) {
    test::MakeSphere(m, 1);
    test::PunchSphere(m, vcg::Point3f(1, 0, 0), 1, first);
    test::PunchSphere(m, vcg::Point3f(-1, 0, 0), 1, second);
    census = vcg_ext::CensusEdges(m);
    loops = vcg_ext::FindHoleLoops(m, census);
  }
};

TEST(HoleLoops, EachHoleIsOneLoopThatRunsAlongTheFacesBesideIt) {
  const TwoHoledSphere sphere(30, 40);
  const test::Mesh& m = sphere.m;
  const vcg_ext::HoleLoops& loops = sphere.loops;
  ASSERT_EQ(loops.holes.size(), 2u);
  size_t edges = 0;
  for (const vcg_ext::HoleLoop& loop : loops.holes) {
    EXPECT_FALSE(loop.pinched);
    ASSERT_EQ(loop.faces.size(), loop.vertices.size());
    const std::set<int> distinct(loop.vertices.begin(), loop.vertices.end());
    EXPECT_EQ(distinct.size(), loop.vertices.size()) << "a loop passes a vertex twice";
    for (int i = 0; i < loop.EdgeCount(); ++i) {
      const int a = loop.vertices[size_t(i)], b = loop.vertices[size_t((i + 1) % loop.EdgeCount())];
      const auto& f = m.face[size_t(loop.faces[size_t(i)])];
      bool runs = false; // the face beside the edge has it as a -> b
      for (int k = 0; k < 3; ++k)
        runs = runs || (vcg::tri::Index(m, f.cV(k)) == size_t(a) &&
                        vcg::tri::Index(m, f.cV((k + 1) % 3)) == size_t(b));
      EXPECT_TRUE(runs) << "edge " << i << " does not run along its face";
      EXPECT_TRUE(loop.face_agrees[size_t(i)]);
    }
    edges += size_t(loop.EdgeCount());
  }
  EXPECT_EQ(edges, sphere.census.boundary.size()) << "every boundary edge is in one loop";
}

TEST(HoleLoops, TheSizeLimitAndTheOuterBorderLeaveLoopsOpenAndSaySo) {
  const TwoHoledSphere sphere(20, 60);
  const test::Mesh& m = sphere.m;
  const vcg_ext::EdgeCensus& census = sphere.census;
  const vcg_ext::HoleLoops& all = sphere.loops;
  ASSERT_EQ(all.holes.size(), 2u);
  const int small = std::min(all.holes[0].EdgeCount(), all.holes[1].EdgeCount());

  // Either way of leaving the big loop open keeps the small one alone and counts what it left.
  vcg_ext::HoleLoopParams by_edges;
  by_edges.max_edges = small;
  vcg_ext::HoleLoopParams border;
  border.keep_longest_open = true;
  for (const vcg_ext::HoleLoopParams& p : {by_edges, border}) {
    const vcg_ext::HoleLoops kept = vcg_ext::FindHoleLoops(m, census, p);
    ASSERT_EQ(kept.holes.size(), 1u);
    EXPECT_EQ(kept.holes[0].EdgeCount(), small);
    EXPECT_EQ(kept.skipped_by_size, p.max_edges > 0 ? 1 : 0);
    EXPECT_EQ(kept.kept_as_border, p.keep_longest_open ? 1 : 0);
  }
}

TEST(HoleLoops, AClosedMeshHasNone) {
  test::Mesh m;
  test::MakeSphere(m, 1);
  EXPECT_TRUE(vcg_ext::FindHoleLoops(m, vcg_ext::CensusEdges(m)).holes.empty());
}

} // namespace
