#include "test_mesh.h"

#include <vcg_ext/crease_flips.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

namespace {

using test::Mesh;

// A ridge z = -|x| along the y axis, whose middle row has no vertex on the ridge: the two
// triangles of the edge from one side to the other (faces 2 and 3) cut the ridge off as a
// chamfer.
//   A0 (0)  C0 (1)  B0 (2)     y = -1
//   A1 (3)          B1 (4)     y =  0
//   A2 (5)  C2 (6)  B2 (7)     y =  1
const std::vector<vcg::Point3f> kRidgePoints{{-1, -1, -1}, {0, -1, 0},  {1, -1, -1}, {-1, 0, -1},
                                             {1, 0, -1},   {-1, 1, -1}, {0, 1, 0},   {1, 1, -1}};
const std::vector<std::array<int, 3>> kRidgeFaces{{0, 1, 3}, {1, 2, 4}, {1, 4, 3},
                                                  {3, 4, 6}, {3, 6, 5}, {4, 7, 6}};

std::vector<int> AllFaces(const Mesh& m) {
  std::vector<int> all(m.face.size());
  for (size_t i = 0; i < all.size(); ++i) all[i] = int(i);
  return all;
}

} // namespace

// The flip puts the chamfer's edge on the ridge, each triangle in one face.
TEST(CreaseFlips, AChamferAcrossARidgeIsFlippedOntoIt) {
  Mesh m;
  vcg::tri::BuildMeshFromCoordVectorIndexVector(m, kRidgePoints, kRidgeFaces);
  const vcg::Point3f up_before = vcg::TriangleNormal(m.face[2]) + vcg::TriangleNormal(m.face[3]);
  std::vector<int> flipped;
  EXPECT_EQ(vcg_ext::FlipFillEdgesOntoCreases(m, AllFaces(m), {}, &flipped), 1);
  std::sort(flipped.begin(), flipped.end());
  EXPECT_EQ(flipped, (std::vector<int>{2, 3})); // the two faces of the chamfer
  // Every triangle now lies in one face of the ridge (its vertices all on one side, the ridge
  // included), and faces up as before.
  for (const auto& f : m.face) {
    bool left = true, right = true;
    for (int k = 0; k < 3; ++k) left = left && f.cP(k).X() <= 0, right = right && f.cP(k).X() >= 0;
    EXPECT_TRUE(left || right) << vcg::tri::Index(m, f.cV(0)) << " " << vcg::tri::Index(m, f.cV(1))
                               << " " << vcg::tri::Index(m, f.cV(2));
    EXPECT_GT(vcg::TriangleNormal(f) * up_before, 0);
  }
}

// On a smooth surface both diagonals of every quad bend it alike: nothing flips.
TEST(CreaseFlips, ASmoothFillIsLeftAsItIs) {
  Mesh m;
  test::MakePlane(m, 12, 2);
  for (auto& v : m.vert) {
    const float x = v.P().X() - 1, y = v.P().Y() - 1;
    v.P() = vcg::Point3f(x, y, 0.3f * (x * x + 0.5f * y * y));
  }
  std::vector<std::array<int, 3>> before;
  for (const auto& f : m.face)
    before.push_back({int(vcg::tri::Index(m, f.cV(0))), int(vcg::tri::Index(m, f.cV(1))),
                      int(vcg::tri::Index(m, f.cV(2)))});
  EXPECT_EQ(vcg_ext::FlipFillEdgesOntoCreases(m, AllFaces(m)), 0);
  for (size_t i = 0; i < m.face.size(); ++i)
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(int(vcg::tri::Index(m, m.face[i].cV(k))), before[i][size_t(k)]);
}

// Faces outside the fill are read, never changed, and an edge the mesh has is never made twice:
// with the chamfer's quad outside the fill, or the ridge's edge already in the mesh, no flip.
TEST(CreaseFlips, OnlyTheFillChangesAndNoEdgeIsMadeTwice) {
  Mesh m;
  vcg::tri::BuildMeshFromCoordVectorIndexVector(m, kRidgePoints, kRidgeFaces);
  EXPECT_EQ(vcg_ext::FlipFillEdgesOntoCreases(m, {0, 1, 4, 5}), 0);
  // The edge C0-C2 (1-6) already there, as the side of a face elsewhere in the mesh.
  std::vector<vcg::Point3f> more(kRidgePoints);
  more.push_back({0, 0, 5});
  std::vector<std::array<int, 3>> with_edge(kRidgeFaces);
  with_edge.push_back({1, 8, 6});
  vcg::tri::BuildMeshFromCoordVectorIndexVector(m, more, with_edge);
  EXPECT_EQ(vcg_ext::FlipFillEdgesOntoCreases(m, {0, 1, 2, 3, 4, 5}), 0);
}
