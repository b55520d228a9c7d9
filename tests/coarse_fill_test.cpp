#include "test_mesh.h"

#include <vcg_ext/coarse_fill.h>
#include <wrap/io_trimesh/import_ply.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

using test::Mesh;

namespace {

const vcg::Point3f kDirections[] = {
    {1, 0.2f, 0.1f}, {-0.3f, 1, 0.2f}, {0.1f, -0.2f, -1}, {-1, -1, 1}};

double MaxRadiusError(const Mesh& m, const vcg_ext::CoarseFillResult& r, float radius) {
  double worst = 0;
  for (const auto& h : r.holes)
    for (int v : h.new_vertices)
      worst = std::max(worst, std::abs(double(m.vert[v].cP().Norm()) - radius) / radius);
  return worst;
}

TEST(CoarseFill, SphereHolesComeBackWatertightAndOnTheSphere) {
  Mesh m;
  const float radius = 2.0f;
  test::MakeSphere(m, radius);
  for (const auto& d : kDirections) ASSERT_GT(test::PunchSphere(m, d, radius, 30), 0);
  ASSERT_EQ(test::Inspect(m).loops, 4u);

  const auto result = vcg_ext::CoarseFill(m);

  ASSERT_EQ(result.holes.size(), 4u);
  EXPECT_EQ(result.FilledCount(), 4);
  const auto topo = test::Inspect(m);
  EXPECT_EQ(topo.boundary_edges, 0u);
  EXPECT_EQ(topo.non_manifold_edges, 0u);
  for (const auto& h : result.holes) {
    EXPECT_EQ(h.triangulation, "liepa-dp");
    EXPECT_TRUE(h.faired);
    EXPECT_GT(h.new_vertices.size(), 5u) << "refinement should match the sphere's density";
  }
  EXPECT_LT(MaxRadiusError(m, result, radius), 0.01);
}

std::vector<std::pair<int, std::string>> progress_seen;
bool RecordProgress(int percent, const char* message) {
  progress_seen.emplace_back(percent, message);
  return true;
}

// One hole per thread: the calling thread fills one of the four, and the count must still
// reach the end when another thread finishes last.
TEST(CoarseFill, ProgressCountsTheHolesOtherThreadsFill) {
  Mesh m;
  test::MakeSphere(m, 1.0f);
  for (const auto& d : kDirections) test::PunchSphere(m, d, 1.0f, 30);
  vcg_ext::CoarseFillParams params;
  params.threads = 4;
  progress_seen.clear();

  vcg_ext::CoarseFill(m, params, RecordProgress);

  ASSERT_FALSE(progress_seen.empty());
  EXPECT_EQ(progress_seen.back().first, 100);
  EXPECT_EQ(progress_seen.back().second, "Coarse fill: hole 4 of 4");
}

TEST(CoarseFill, VcgEarsCloseLoopsBeyondTheDynamicProgramme) {
  Mesh m;
  const float radius = 1.0f;
  test::MakeSphere(m, radius);
  for (const auto& d : kDirections) test::PunchSphere(m, d, radius, 30);
  vcg_ext::CoarseFillParams params;
  params.dp_max_edges = 8; // every loop here is longer

  const auto result = vcg_ext::CoarseFill(m, params);

  EXPECT_EQ(result.FilledCount(), 4);
  for (const auto& h : result.holes) EXPECT_EQ(h.triangulation, "vcg-ears");
  const auto topo = test::Inspect(m);
  EXPECT_EQ(topo.boundary_edges, 0u);
  EXPECT_EQ(topo.non_manifold_edges, 0u);
  EXPECT_LT(MaxRadiusError(m, result, radius), 0.01);
}

TEST(CoarseFill, FlatHoleStaysFlat) {
  Mesh m;
  test::MakePlane(m, 40, 1.0f);
  vcg_ext::PunchHole(m, vcg::Point3f(0.5f, 0.5f, 0), 0.2f);
  vcg_ext::CoarseFillParams params;
  params.max_hole_edges = 100; // the plane's outer border is not a hole to fill
  const auto result = vcg_ext::CoarseFill(m, params);

  ASSERT_EQ(result.FilledCount(), 1);
  EXPECT_EQ(result.skipped_by_size, 1);
  EXPECT_GT(result.holes[0].new_vertices.size(), 20u);
  for (int v : result.holes[0].new_vertices) EXPECT_NEAR(m.vert[v].cP()[2], 0.0, 1e-6);
  EXPECT_EQ(test::Inspect(m).loops, 1u); // only the outer border
  EXPECT_EQ(test::Inspect(m).non_manifold_edges, 0u);
}

TEST(CoarseFill, PinchedHoleIsSplitAndFilled) {
  Mesh m;
  const int n = 10;
  test::MakePlane(m, n, 1.0f);
  // Two square holes touching at one corner vertex: one boundary walk through a pinch vertex.
  auto remove_cell = [&](int i, int j) {
    vcg::tri::Allocator<Mesh>::DeleteFace(m, m.face[2 * (i * n + j)]);
    vcg::tri::Allocator<Mesh>::DeleteFace(m, m.face[2 * (i * n + j) + 1]);
  };
  remove_cell(4, 4);
  remove_cell(4, 5);
  remove_cell(5, 6);
  remove_cell(6, 6);
  vcg::tri::Allocator<Mesh>::CompactEveryVector(m);
  vcg_ext::CoarseFillParams params;
  params.max_hole_edges = 30;

  const auto result = vcg_ext::CoarseFill(m, params);

  ASSERT_EQ(result.holes.size(), 2u);
  for (const auto& h : result.holes) EXPECT_TRUE(h.pinched);
  EXPECT_EQ(result.FilledCount(), 2);
  const auto topo = test::Inspect(m);
  EXPECT_EQ(topo.non_manifold_edges, 0u);
  EXPECT_EQ(topo.loops, 1u); // only the outer border
}

/// How far the farthest new vertex of `hole` lies from the plane of its loop, and that plane.
std::pair<double, vcg_ext::LoopPlane> FarthestFromLoopPlane(const Mesh& m,
                                                            const vcg_ext::CoarseHoleReport& hole) {
  auto point = [&](int v) {
    const auto& p = m.vert[size_t(v)].cP();
    return Eigen::Vector3d(p[0], p[1], p[2]);
  };
  std::vector<Eigen::Vector3d> loop;
  for (int v : hole.loop) loop.push_back(point(v));
  const vcg_ext::LoopPlane plane = vcg_ext::FitLoopPlane(loop);
  double farthest = 0;
  for (int v : hole.new_vertices)
    farthest = std::max(farthest, std::abs((point(v) - plane.centre).dot(plane.normal)));
  return {farthest, plane};
}

// A statue's cut base (the lion statue's underside: 322 edges, the loop 1.8 % of its size off
// its plane, the walls beside it at about 57 degrees and not turning further out) comes back
// flat, not as a dome below the base: the statue stands again.
TEST(CoarseFill, AStatuesCutBaseIsCappedFlat) {
  Mesh m;
  const std::string path = std::string(CI_SHARED_MESHES) + "/lionstatue.ply";
  ASSERT_EQ(vcg::tri::io::ImporterPLY<Mesh>::Open(m, path.c_str()), 0) << path;

  const auto result = vcg_ext::CoarseFill(m);

  ASSERT_EQ(result.holes.size(), 1u);
  ASSERT_TRUE(result.holes[0].filled);
  EXPECT_TRUE(result.holes[0].planar_cap);
  const auto farthest = FarthestFromLoopPlane(m, result.holes[0]);
  ASSERT_GT(farthest.second.off_plane, 0.005 * farthest.second.size) << "not IsPlanarCap's case";
  EXPECT_LE(farthest.first, farthest.second.off_plane + 0.001 * farthest.second.size);
}

// A hole that takes a sphere's cap 100 degrees wide: its loop is nearly planar and the sphere
// leaves the loop's plane at about 50 degrees, as a statue's walls leave its base, but further
// out it keeps turning: a dome is missing, not a base.
TEST(CoarseFill, ASpheresCapIsNoCutBase) {
  Mesh m;
  test::MakeSphere(m, 1.0f);
  test::PunchSphere(m, kDirections[0], 1.0f, 100);

  const auto result = vcg_ext::CoarseFill(m);

  ASSERT_EQ(result.FilledCount(), 1);
  EXPECT_FALSE(result.holes[0].planar_cap);
  const auto farthest = FarthestFromLoopPlane(m, result.holes[0]);
  ASSERT_LE(farthest.second.off_plane, 0.02 * farthest.second.size) << "not IsFlatBase's case";
  // The cap rises 1 - cos(50 degrees) = 0.36 above its loop's plane.
  EXPECT_GT(farthest.first, 0.2);
}

TEST(CoarseFill, HolesOverTheSizeLimitStayOpen) {
  Mesh m;
  test::MakeSphere(m, 1.0f);
  test::PunchSphere(m, kDirections[0], 1.0f, 50);
  test::PunchSphere(m, kDirections[2], 1.0f, 20);
  const auto before = vcg_ext::FindHoleLoops(m, vcg_ext::CensusEdges(m)).holes;
  ASSERT_EQ(before.size(), 2u);
  const int small = std::min(before[0].EdgeCount(), before[1].EdgeCount());
  const int large = std::max(before[0].EdgeCount(), before[1].EdgeCount());
  ASSERT_LT(small, large);
  vcg_ext::CoarseFillParams params;
  params.max_hole_edges = small;

  const auto result = vcg_ext::CoarseFill(m, params);

  EXPECT_EQ(result.FilledCount(), 1);
  EXPECT_EQ(result.skipped_by_size, 1);
  const auto after = vcg_ext::FindHoleLoops(m, vcg_ext::CensusEdges(m)).holes;
  ASSERT_EQ(after.size(), 1u);
  EXPECT_EQ(after[0].EdgeCount(), large);
}

TEST(CoarseFill, OnlyHolesTouchingTheSelection) {
  Mesh m;
  test::MakeSphere(m, 1.0f);
  test::PunchSphere(m, kDirections[0], 1.0f, 30);
  test::PunchSphere(m, kDirections[1], 1.0f, 30);
  const auto loops = vcg_ext::FindHoleLoops(m, vcg_ext::CensusEdges(m)).holes;
  ASSERT_EQ(loops.size(), 2u);
  m.face[loops[1].faces[0]].SetS();
  vcg_ext::CoarseFillParams params;
  params.selected_only = true;

  const auto result = vcg_ext::CoarseFill(m, params);

  EXPECT_EQ(result.FilledCount(), 1);
  EXPECT_EQ(result.skipped_by_selection, 1);
  EXPECT_EQ(result.holes[0].loop, loops[1].vertices);
  // Afterwards exactly the new faces are selected.
  size_t selected = 0;
  for (const auto& f : m.face) selected += f.IsS();
  EXPECT_EQ(selected, result.holes[0].new_faces.size());
}

TEST(CoarseFill, ClosedMeshComesBackUnchanged) {
  Mesh m, original;
  test::MakeSphere(m, 1.5f);
  vcg::tri::Append<Mesh, Mesh>::MeshCopy(original, m);

  const auto result = vcg_ext::CoarseFill(m);

  EXPECT_TRUE(result.holes.empty());
  ASSERT_EQ(m.vert.size(), original.vert.size());
  ASSERT_EQ(m.face.size(), original.face.size());
  for (size_t i = 0; i < m.vert.size(); ++i) EXPECT_EQ(m.vert[i].cP(), original.vert[i].cP());
  for (size_t i = 0; i < m.face.size(); ++i)
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(vcg::tri::Index(m, m.face[i].cV(k)),
                vcg::tri::Index(original, original.face[i].cV(k)));
}

TEST(CoarseFill, ExistingVerticesAndAttributesAreKept) {
  Mesh m;
  test::MakeSphere(m, 1.0f);
  test::PunchSphere(m, kDirections[0], 1.0f, 30);
  for (auto& v : m.vert) v.C() = vcg::Color4b(200, 40, 10, 255), v.Q() = 7.0f;
  Mesh original;
  vcg::tri::Append<Mesh, Mesh>::MeshCopy(original, m);

  const auto result = vcg_ext::CoarseFill(m);

  ASSERT_EQ(result.FilledCount(), 1);
  for (size_t i = 0; i < original.vert.size(); ++i) {
    EXPECT_EQ(m.vert[i].cP(), original.vert[i].cP());
    EXPECT_EQ(m.vert[i].cC(), original.vert[i].cC());
  }
  for (int v : result.holes[0].new_vertices) {
    EXPECT_EQ(m.vert[v].cC(), vcg::Color4b(200, 40, 10, 255));
    EXPECT_FLOAT_EQ(m.vert[v].cQ(), 7.0f);
  }
}

TEST(CoarseFill, RejectsAnEmptyMesh) {
  Mesh m;
  EXPECT_THROW(vcg_ext::CoarseFill(m), vcg_ext::InvalidMeshError);
}

TEST(CoarseFill, RejectsNonFiniteCoordinatesAndChangesNothing) {
  Mesh m;
  test::MakeSphere(m, 1.0f);
  test::PunchSphere(m, kDirections[0], 1.0f, 30);
  m.vert[3].P()[1] = std::numeric_limits<float>::quiet_NaN();
  const size_t vn = m.vert.size(), fn = m.face.size();
  try {
    vcg_ext::CoarseFill(m);
    FAIL() << "a NaN coordinate was accepted";
  } catch (const vcg_ext::InvalidMeshError& e) {
    EXPECT_NE(std::string(e.what()).find("non-finite"), std::string::npos) << e.what();
  }
  EXPECT_EQ(m.vert.size(), vn);
  EXPECT_EQ(m.face.size(), fn);
}

TEST(CoarseFill, RejectsNonManifoldEdges) {
  Mesh m;
  test::MakePlane(m, 4, 1.0f);
  // A third face on the edge between vertices 6 and 7.
  auto vi = vcg::tri::Allocator<Mesh>::AddVertices(m, 1);
  vi->P() = vcg::Point3f(0.3f, 0.3f, 1.0f);
  vcg::tri::Allocator<Mesh>::AddFace(m, &m.vert[6], &m.vert[7], &*vi);
  try {
    vcg_ext::CoarseFill(m);
    FAIL() << "a non-manifold edge was accepted";
  } catch (const vcg_ext::InvalidMeshError& e) {
    EXPECT_NE(std::string(e.what()).find("more than two faces"), std::string::npos) << e.what();
  }
}

} // namespace

namespace {

// A closed prism (a hexagonal "statue" standing on its base) with its base missing: the base
// loop is planar and its walls meet it at a right angle.
void MakeOpenPrism(Mesh& m, int sides, int rings) {
  m.Clear();
  const float h = 1.0f;
  auto vi = vcg::tri::Allocator<Mesh>::AddVertices(m, sides * (rings + 1) + 1);
  for (int r = 0; r <= rings; ++r)
    for (int s = 0; s < sides; ++s) {
      const double a = 2 * M_PI * s / sides;
      m.vert[r * sides + s].P() =
          vcg::Point3f(float(std::cos(a)), float(std::sin(a)), h * r / rings);
    }
  m.vert.back().P() = vcg::Point3f(0, 0, h); // top centre
  (void)vi;
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < sides; ++s) {
      const int a = r * sides + s, b = r * sides + (s + 1) % sides;
      vcg::tri::Allocator<Mesh>::AddFace(m, &m.vert[a], &m.vert[b], &m.vert[b + sides]);
      vcg::tri::Allocator<Mesh>::AddFace(m, &m.vert[a], &m.vert[b + sides], &m.vert[a + sides]);
    }
  const int top = int(m.vert.size()) - 1;
  for (int s = 0; s < sides; ++s)
    vcg::tri::Allocator<Mesh>::AddFace(m, &m.vert[rings * sides + s],
                                       &m.vert[rings * sides + (s + 1) % sides], &m.vert[top]);
}

TEST(CoarseFill, PlanarCapAtACreaseStaysFlat) {
  Mesh m;
  MakeOpenPrism(m, 24, 8);
  ASSERT_EQ(test::Inspect(m).loops, 1u);

  const auto result = vcg_ext::CoarseFill(m);

  ASSERT_EQ(result.FilledCount(), 1);
  EXPECT_TRUE(result.holes[0].planar_cap);
  EXPECT_GT(result.holes[0].new_vertices.size(), 10u);
  for (int v : result.holes[0].new_vertices) EXPECT_NEAR(m.vert[v].cP()[2], 0.0, 1e-5);
  EXPECT_EQ(test::Inspect(m).boundary_edges, 0u);
}

TEST(CoarseFill, PlanarCapCanBeFairedOnRequest) {
  Mesh m;
  MakeOpenPrism(m, 24, 8);
  vcg_ext::CoarseFillParams params;
  params.flat_planar_caps = false;

  const auto result = vcg_ext::CoarseFill(m, params);

  ASSERT_EQ(result.FilledCount(), 1);
  EXPECT_FALSE(result.holes[0].planar_cap);
  double lowest = 0;
  for (int v : result.holes[0].new_vertices) lowest = std::min(lowest, double(m.vert[v].cP()[2]));
  EXPECT_LT(lowest, -0.05) << "a thin plate continues the walls below the base";
}

// A round hole in a gently curved sheet (normals about 1 degree off the loop's plane beside it,
// as on the fandisk's curved faces) has a planar loop too: it is no flat cap, and the thin
// plate brings the dome back where a flat cap would cut it off.
TEST(CoarseFill, AHoleInAGentlyCurvedSheetIsNoFlatCap) {
  Mesh m;
  test::MakePlane(m, 50, 1.0f);
  const double k = 0.1; // z = -k r^2: slope 2 k r, about 1.1 degrees at the hole's border
  for (auto& v : m.vert) {
    const double x = v.P()[0] - 0.5, y = v.P()[1] - 0.5;
    v.P()[2] = float(-k * (x * x + y * y));
  }
  // Every loop vertex lies 0.1 or more from the centre: at or below z = -0.001.
  vcg_ext::PunchHole(m, vcg::Point3f(0.5f, 0.5f, 0), 0.1f);
  vcg_ext::CoarseFillParams params;
  params.max_hole_edges = 100; // the sheet's outer border is not a hole to fill

  const auto result = vcg_ext::CoarseFill(m, params);

  ASSERT_EQ(result.FilledCount(), 1);
  EXPECT_FALSE(result.holes[0].planar_cap);
  double top = -1;
  for (int v : result.holes[0].new_vertices) top = std::max(top, double(m.vert[v].cP()[2]));
  // The dome rises towards z = 0 at the centre; a flat cap would stay at or below -0.001.
  EXPECT_GT(top, -0.0005);
  EXPECT_LT(top, 0.0002);
}

} // namespace

namespace {

TEST(CoarseFill, HoleOfOverAThousandEdgesTakesTheEars) {
  Mesh m;
  test::MakePlane(m, 400, 1.0f);
  vcg_ext::PunchHole(m, vcg::Point3f(0.5f, 0.5f, 0), 0.45f);
  const auto loops = vcg_ext::FindHoleLoops(m, vcg_ext::CensusEdges(m)).holes;
  ASSERT_EQ(loops.size(), 2u); // the hole and the plane's outer border
  const int hole_edges = std::min(loops[0].EdgeCount(), loops[1].EdgeCount());
  ASSERT_GT(hole_edges, 1000);
  vcg_ext::CoarseFillParams params;
  params.max_hole_edges = hole_edges; // keep the outer border open

  const auto result = vcg_ext::CoarseFill(m, params);

  ASSERT_EQ(result.FilledCount(), 1);
  EXPECT_EQ(result.holes[0].boundary_edges, hole_edges);
  EXPECT_EQ(result.holes[0].triangulation, "vcg-ears");
  const auto topo = test::Inspect(m);
  EXPECT_EQ(topo.loops, 1u);
  EXPECT_EQ(topo.non_manifold_edges, 0u);
  for (int v : result.holes[0].new_vertices) ASSERT_NEAR(m.vert[v].cP()[2], 0.0, 1e-5);
}

// A low height field z = (x^2 + y^2)^2 / 10 over a grid, its middle flattened. With weights
// close to the flat grid's (one solve) the thin plate reproduces only what is at most cubic
// across the hole, the tri-Laplacian up to quintic: it brings the quartic back, the thin plate
// cannot.
TEST(FairFreeVertices, TheTriLaplacianContinuesCurvatureTheThinPlateCannot) {
  const int n = 41;
  std::vector<Eigen::Vector3d> truth, points;
  std::vector<char> is_free;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = -1 + 2.0 * i / (n - 1), y = -1 + 2.0 * j / (n - 1);
      const double r2 = x * x + y * y;
      truth.emplace_back(x, y, 0.1 * r2 * r2);
      is_free.push_back(r2 < 0.5 * 0.5);
      points.push_back(is_free.back() ? Eigen::Vector3d(x, y, 0) : truth.back());
    }
  std::vector<std::array<int, 3>> tris;
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      tris.push_back({a, b, d});
      tris.push_back({a, d, c});
    }
  auto max_error = [&](int order) {
    std::vector<Eigen::Vector3d> faired = points;
    vcg_ext::HoleFairingParams params;
    params.order = order;
    params.iterations = 1;
    EXPECT_TRUE(vcg_ext::FairFreeVertices(faired, tris, is_free, params));
    double worst = 0;
    for (size_t v = 0; v < faired.size(); ++v) {
      if (!is_free[v]) EXPECT_EQ(faired[v], points[v]) << "a fixed vertex moved";
      worst = std::max(worst, (faired[v] - truth[v]).norm());
    }
    return worst;
  };
  const double thin_plate = max_error(2), tri_laplacian = max_error(3);
  EXPECT_GT(thin_plate, 0.002); // the quartic's own depth there is 0.006
  EXPECT_LT(tri_laplacian, 0.1 * thin_plate) << thin_plate;
}

} // namespace
