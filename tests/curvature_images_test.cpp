#include "test_mesh.h"

#include <vcg_ext/apss_curvature.h>
#include <vcg_ext/coarse_fill.h>
#include <vcg_ext/curvature_colormap.h>
#include <vcg_ext/curvature_image.h>
#include <vcg_ext/mvc_parameterization.h>
#include <vcg_ext/patch_extraction.h>
#include <wrap/io_trimesh/import_ply.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using test::Mesh;

namespace {

std::vector<double> Curvature(Mesh& m, const std::vector<int>& query) {
  vcg::tri::UpdateNormal<Mesh>::PerVertexNormalizedPerFace(m);
  std::vector<Eigen::Vector3d> p, n;
  for (const auto& v : m.vert) {
    p.emplace_back(v.cP()[0], v.cP()[1], v.cP()[2]);
    n.emplace_back(v.cN()[0], v.cN()[1], v.cN()[2]);
  }
  return vcg_ext::ApssMeanCurvature(p, n, query);
}

TEST(ApssCurvature, SphereIsOneOverRadiusAndConvexNegative) {
  Mesh m;
  test::MakeSphere(m, 2.0f);
  std::vector<int> all(m.vert.size());
  for (size_t i = 0; i < all.size(); ++i) all[i] = int(i);
  for (double h : Curvature(m, all)) EXPECT_NEAR(h, -0.5, 0.5 * 0.02);
}

TEST(ApssCurvature, PlaneIsFlat) {
  Mesh m;
  test::MakePlane(m, 40, 1.0f);
  const auto h = Curvature(m, {20 * 41 + 20, 10 * 41 + 30, 30 * 41 + 12});
  for (double x : h) EXPECT_NEAR(x, 0.0, 1e-3);
}

TEST(ApssCurvature, CylinderIsOneOverTwiceTheRadius) {
  Mesh m;
  const float r = 0.5f;
  test::MakeCylinder(m, r, 4.0f); // rows of 96 vertices; row 24 is half way up
  const auto h = Curvature(m, {24 * 96, 24 * 96 + 31, 20 * 96 + 70});
  for (double x : h) EXPECT_NEAR(std::abs(x), 1 / (2 * r), 0.02 / (2 * r));
}

TEST(ApssCurvature, TorusOutsideAndInsideHaveOppositeSigns) {
  Mesh m;
  test::MakeTorus(m, 1.0f, 0.6f); // row 0: outer equator, row 24: inner equator
  const auto h = Curvature(m, {0, 24 * 96});
  EXPECT_LT(h[0], 0) << "the outer equator is convex";
  EXPECT_GT(h[1], 0) << "the inner equator bends more along the hole than around the tube";
  EXPECT_NEAR(h[0], -(1 / 0.6 + 1 / 1.6) / 2, 0.05);
  EXPECT_NEAR(h[1], -(1 / 0.6 - 1 / 0.4) / 2, 0.05);
}

TEST(CurvatureColormap, InverseRecoversEveryValue) {
  for (int i = 0; i <= 1000; ++i) {
    const double t = i / 1000.0;
    const auto inv = vcg_ext::CurvatureColormap::Invert(vcg_ext::CurvatureColormap::Color8(t));
    EXPECT_NEAR(inv.t, t, 1.0 / 255) << "t = " << t;
    EXPECT_LT(inv.distance, 1.0);
  }
}

TEST(CurvatureColormap, OffPaletteColoursMapToTheNearestPoint) {
  // Green with some red and blue mixed in: the nearest palette point is (0, 255, 30) on the
  // green-cyan edge, 30/255 of the way to cyan (a quarter of the map per edge).
  const auto g = vcg_ext::CurvatureColormap::Invert(Eigen::Vector3d(30, 250, 30));
  EXPECT_NEAR(g.t, 0.5 - 0.25 * 30 / 255, 1e-12);
  EXPECT_NEAR(g.distance, std::sqrt(30.0 * 30 + 5 * 5), 1e-9);
  // Grey is far from every knot and edge.
  const auto grey = vcg_ext::CurvatureColormap::Invert(Eigen::Vector3d(128, 128, 128));
  EXPECT_GT(grey.distance, 100);
  // Beyond the ends clamps to them.
  EXPECT_NEAR(vcg_ext::CurvatureColormap::Invert(Eigen::Vector3d(0, 0, 300)).t, 0.0, 1e-9);
}

// Coarse fill, segmentation and extraction of every hole of `m`.
std::vector<vcg_ext::PatchMesh> Patches(Mesh& m, double context,
                                        std::vector<vcg_ext::HoleRegion>* out = nullptr) {
  const auto fill = vcg_ext::CoarseFill(m);
  std::vector<vcg_ext::FilledHole> holes;
  for (const auto& h : fill.holes)
    if (h.filled) holes.push_back({h.loop, h.new_faces});
  const vcg_ext::VertexFaces vf(m);
  vcg_ext::HoleSegmentationParams params;
  params.context = context;
  const auto regions = vcg_ext::SegmentHolePatches(m, vf, holes, fill.box, params);
  std::vector<vcg_ext::PatchMesh> patches;
  for (const auto& r : regions) patches.push_back(vcg_ext::ExtractPatch(m, r, fill.box));
  if (out) *out = regions;
  return patches;
}

void ExpectValidParameterization(const vcg_ext::PatchMesh& p) {
  ASSERT_TRUE(p.IsDisk());
  const auto uv = vcg_ext::ParameterizeMvc(p.points, p.triangles, p.boundary);
  ASSERT_TRUE(uv.solved);
  EXPECT_EQ(uv.flipped, 0);
  EXPECT_EQ(uv.degenerate, 0);
  std::vector<char> on_boundary(p.points.size(), 0);
  for (int v : p.boundary) {
    on_boundary[v] = 1;
    const auto& q = uv.uv[v];
    const double to_border = std::min({q.x(), 1 - q.x(), q.y(), 1 - q.y()});
    EXPECT_NEAR(to_border, 0.0, 1e-12);
  }
  for (size_t v = 0; v < p.points.size(); ++v)
    if (!on_boundary[v]) {
      EXPECT_GT(uv.uv[v].x(), 0);
      EXPECT_LT(uv.uv[v].x(), 1);
      EXPECT_GT(uv.uv[v].y(), 0);
      EXPECT_LT(uv.uv[v].y(), 1);
    }
}

void LoadShared(Mesh& m, const std::string& name) {
  const std::string path = std::string(CI_SHARED_MESHES) + "/" + name;
  ASSERT_EQ(vcg::tri::io::ImporterPLY<Mesh>::Open(m, path.c_str()), 0) << path;
  vcg::tri::UpdateBounding<Mesh>::Box(m);
}

TEST(MvcParameterization, PatchesOfSharedScansAreEmbedded) {
  for (const std::string name : {"igea_190k.ply", "armadillo.ply", "fandisk.ply"}) {
    SCOPED_TRACE(name);
    Mesh m;
    LoadShared(m, name);
    const float d = m.bbox.Diag();
    vcg_ext::PunchHole(m, m.vert[m.vert.size() / 3].cP(), 0.04f * d);
    vcg_ext::PunchHole(m, m.vert[2 * m.vert.size() / 3].cP(), 0.03f * d);
    const auto patches = Patches(m, 1.0);
    ASSERT_EQ(patches.size(), 2u);
    for (const auto& p : patches) ExpectValidParameterization(p);
  }
}

TEST(HoleSegmentation, NeighbouringPatchesNeverOverlapAndAreDisks) {
  Mesh m;
  test::MakeSphere(m, 1.0f, 5);
  // Two holes close together: their patches compete for the faces between them.
  Mesh alone;
  vcg::tri::Append<Mesh, Mesh>::MeshCopy(alone, m);
  test::PunchSphere(m, vcg::Point3f(1, 0, 0), 1.0f, 20);
  test::PunchSphere(m, vcg::Point3f(1, 0.45f, 0), 1.0f, 20);
  test::PunchSphere(alone, vcg::Point3f(1, 0, 0), 1.0f, 20);
  std::vector<vcg_ext::HoleRegion> regions, alone_regions;
  const auto patches = Patches(m, 2.0, &regions);
  Patches(alone, 2.0, &alone_regions);
  ASSERT_EQ(alone_regions.size(), 1u);
  ASSERT_EQ(patches.size(), 2u);
  std::set<int> first(regions[0].faces.begin(), regions[0].faces.end());
  for (int f : regions[1].faces) EXPECT_EQ(first.count(f), 0u) << "face " << f << " in both";
  std::set<int> first_vertices(patches[0].vertices.begin(), patches[0].vertices.end());
  for (int v : patches[1].vertices) EXPECT_EQ(first_vertices.count(v), 0u);
  for (const auto& p : patches) EXPECT_TRUE(p.IsDisk());
  // The neighbour takes faces the hole's patch gets when it is alone.
  for (const auto& r : regions) EXPECT_LT(r.faces.size(), alone_regions[0].faces.size());
}

TEST(HoleSegmentation, HoleNearAHandleStillGetsADisk) {
  Mesh m;
  test::MakeTorus(m, 1.0f, 0.4f, 64, 32);
  vcg_ext::PunchHole(m, m.vert[16 * 64].cP(), 0.3f); // on the inner equator, by the handle
  std::vector<vcg_ext::HoleRegion> regions;
  const auto patches = Patches(m, 8.0, &regions); // enough context to wrap around the tube
  ASSERT_EQ(patches.size(), 1u);
  EXPECT_TRUE(patches[0].IsDisk());
  EXPECT_GT(patches[0].triangles.size(), m.face.size() / 4) << "the patch should grow far";
  ExpectValidParameterization(patches[0]);
}

TEST(CurvatureImage, MaskCoversExactlyTheHoleTriangles) {
  Mesh m;
  LoadShared(m, "nefertiti.ply");
  vcg_ext::PunchHole(m, m.vert[33416].cP(), 0.03f * m.bbox.Diag());
  const auto patches = Patches(m, 1.0);
  ASSERT_EQ(patches.size(), 1u);
  const auto& p = patches[0];
  const auto uv = vcg_ext::ParameterizeMvc(p.points, p.triangles, p.boundary);
  const std::vector<double> t(p.points.size(), 0.5);
  const int size = 512;
  const auto img = vcg_ext::RasterizeCurvature(uv.uv, t, p.triangles, p.is_fill, size);
  // Area and border length of the hole in UV.
  double area = 0, border = 0;
  std::map<std::pair<int, int>, int> edges;
  for (size_t f = 0; f < p.triangles.size(); ++f) {
    if (!p.is_fill[f]) continue;
    const auto& tri = p.triangles[f];
    area += vcg_ext::detail::SignedArea(uv.uv[tri[0]], uv.uv[tri[1]], uv.uv[tri[2]]);
    for (int k = 0; k < 3; ++k) ++edges[std::minmax(tri[k], tri[(k + 1) % 3])];
  }
  for (const auto& e : edges)
    if (e.second == 1) border += (uv.uv[e.first.first] - uv.uv[e.first.second]).norm();
  const double expected = area * size * size;
  EXPECT_GT(img.HolePixels(), 1000);
  // Only pixels along the hole's border can go either way.
  EXPECT_NEAR(img.HolePixels(), expected, border * size);
  // Every pixel is coloured (the square is covered) and green here (t = 0.5 everywhere).
  for (size_t i = 0; i < img.rgb.size(); i += 3) {
    ASSERT_EQ(img.rgb[i], 0);
    ASSERT_EQ(img.rgb[i + 1], 255);
    ASSERT_EQ(img.rgb[i + 2], 0);
  }
}

} // namespace
