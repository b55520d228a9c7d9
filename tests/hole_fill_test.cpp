// The whole method on MeshLab's mesh type: the ground-truth oracle through the chain, the
// detail amplitude, the fake holes and their validation.
#include "validation/fake_holes.h"
#include "pipeline/fill_one_hole.h"
#include "pipeline/hole_fill.h"
#include "report/hole_report.h"
#include "io/mesh_io.h"
#include "inpaint/curvature_reading.h"
#include "pipeline/pipeline.h"
#include "symmetric_egg.h"

#include <vcg/complex/algorithms/create/platonic.h>
#include <vcg/simplex/face/distance.h>
#include <vcg_ext/curvature_colormap.h>
#include <vcg_ext/mesh_errors.h>
#include <vcg_ext/punch_hole.h>

#include <gtest/gtest.h>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <thread>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

namespace {

using curvature_inpaint::FillHoles;
using curvature_inpaint::HoleFillParams;

/// A hole's validation as the log gives it: what a failed expectation on its choice shows.
std::string Validation(const curvature_inpaint::HoleFillReport& r) {
  return curvature_inpaint::DescribeValidation(r.choice.validation);
}

// Bumps whose tip curvature (1 + 2 h / w^2) the colour map's range can hold.
const double kBumpHeight = 0.025, kBumpWidth = 0.2;

/// Directions of the bumps: three close together (the hole's), the rest spread.
std::vector<Eigen::Vector3d> BumpDirections() {
  std::vector<Eigen::Vector3d> d{{1, 0.2, 0}, {1, -0.1, 0.18}, {1, -0.1, -0.18},
                                 {0, 1, 0},   {0, -1, 0},      {0, 0, 1},
                                 {0, 0, -1},  {-1, 0, 0},      {-0.5, 0.7, 0.5}};
  for (auto& x : d) x.normalize();
  return d;
}

/// Unit sphere carrying Gaussian bumps of height kBumpHeight (radially).
void MakeBumpySphere(CMeshO& m, int subdiv = 5) {
  vcg::tri::Sphere(m, subdiv);
  for (auto& v : m.vert) {
    const Eigen::Vector3d p = Eigen::Vector3d(v.P()[0], v.P()[1], v.P()[2]).normalized();
    double r = 1;
    for (const auto& d : BumpDirections())
      r += kBumpHeight * std::exp(-(p - d).squaredNorm() / (kBumpWidth * kBumpWidth));
    v.P() = Point3m(Scalarm(r * p.x()), Scalarm(r * p.y()), Scalarm(r * p.z()));
  }
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
  vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
}

/// The sphere with the hole through the first three bumps.
void PunchThreeBumps(CMeshO& m) {
  vcg_ext::PunchHole(m, Point3m(1.02f, 0, 0), Scalarm(0.45));
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
}

/// Height above the unit sphere of the fill at each of the three bumps' tips.
std::vector<double> BumpHeights(const CMeshO& m, size_t first_new_vertex) {
  std::vector<double> heights;
  for (int b = 0; b < 3; ++b) {
    const Eigen::Vector3d d = BumpDirections()[size_t(b)];
    double best = -1, height = 0;
    for (size_t v = first_new_vertex; v < m.vert.size(); ++v) {
      const Eigen::Vector3d p(m.vert[v].cP()[0], m.vert[v].cP()[1], m.vert[v].cP()[2]);
      const double c = p.normalized().dot(d);
      if (c > best) best = c, height = p.norm() - 1;
    }
    heights.push_back(height);
  }
  return heights;
}

HoleFillParams SmallImages() {
  HoleFillParams p;
  p.images.image_size = 256;
  p.inpaint.variations = 2;
  p.measure_detail = true;
  return p;
}

/// `truth` holed through three bumps into `m` and filled with `p`, deformed to the truth's own
/// curvature images (the oracle).
curvature_inpaint::HoleFillResult FillFromTheTruth(const CMeshO& truth, HoleFillParams p,
                                                   CMeshO& m) {
  curvature_inpaint::CopyMesh(truth, m);
  PunchThreeBumps(m);
  const curvature_inpaint::GroundTruthOracle oracle(truth, m, p.images);
  p.oracle = &oracle;
  return FillHoles(m, p);
}

TEST(GroundTruthOracle, TheFillBringsBackEveryBumpOfTheTruth) {
  CMeshO truth, coarse;
  MakeBumpySphere(truth);
  curvature_inpaint::CopyMesh(truth, coarse);
  PunchThreeBumps(coarse);
  const size_t scan_vertices = coarse.vert.size();
  curvature_inpaint::CoarseFill(coarse, SmallImages().images.coarse);
  for (double h : BumpHeights(coarse, scan_vertices))
    EXPECT_LT(h, 0.5 * kBumpHeight) << "the smooth cap should miss the bumps";

  CMeshO m;
  const auto result = FillFromTheTruth(truth, SmallImages(), m);
  ASSERT_EQ(result.holes.size(), 1u);
  const auto& r = result.holes[0];
  ASSERT_TRUE(r.choice.problem.empty()) << r.choice.problem;
  for (double h : BumpHeights(m, scan_vertices)) EXPECT_NEAR(h, kBumpHeight, 0.2 * kBumpHeight);
  ASSERT_GT(r.truth_spread.truth, 0);
  EXPECT_GE(r.result_spread / r.truth_spread.truth, 0.8)
      << "image " << r.truth_spread.image << ", target " << r.target_spread << ", result "
      << r.result_spread << ", truth " << r.truth_spread.truth;
}

TEST(GroundTruthOracle, ApssPassesBringTheFillsCurvatureCloserToTheImage) {
  CMeshO truth;
  MakeBumpySphere(truth);
  std::vector<double> spreads;
  double target = 0;
  for (int passes : {0, 3}) {
    HoleFillParams p = SmallImages();
    p.direct.apss_passes = passes;
    CMeshO m;
    const auto result = FillFromTheTruth(truth, p, m);
    ASSERT_EQ(result.holes.size(), 1u);
    const auto& r = result.holes[0];
    ASSERT_TRUE(r.choice.problem.empty()) << r.choice.problem;
    for (double h : BumpHeights(m, m.vert.size() - size_t(r.new_vertices)))
      EXPECT_NEAR(h, kBumpHeight, 0.1 * kBumpHeight) << passes << " passes";
    spreads.push_back(r.result_spread);
    target = r.target_spread;
  }
  EXPECT_LT(std::abs(spreads[1] - target), 0.5 * std::abs(spreads[0] - target))
      << "the fill's curvature spread without the passes " << spreads[0] << ", with " << spreads[1]
      << ", the image's at the fill " << target;
}

TEST(Detail, TheAmplitudeChangesTheFillAndZeroIsTheSmoothContinuation) {
  CMeshO truth;
  MakeBumpySphere(truth);
  std::vector<std::vector<Point3m>> fills;
  std::vector<double> spreads;
  for (double detail : {0.0, 2.0}) {
    CMeshO m;
    curvature_inpaint::CopyMesh(truth, m);
    PunchThreeBumps(m);
    const size_t scan_vertices = m.vert.size();
    HoleFillParams p = SmallImages();
    p.validation.fake_holes = 0;
    p.inpaint.detail = detail;
    CMeshO preview;
    curvature_inpaint::CopyMesh(m, preview);
    const auto holes = curvature_inpaint::InpaintHoles(preview, p);
    ASSERT_EQ(holes.size(), 1u);
    ASSERT_GE(holes[0].variations.size(), 2u);
    ASSERT_EQ(holes[0].choice.kinds[0], "continuation");
    ASSERT_EQ(holes[0].choice.kinds[1], "continuation");
    if (detail == 0)
      EXPECT_EQ(holes[0].variations[0], holes[0].variations[1]) << "no detail, nothing random";
    else
      EXPECT_NE(holes[0].variations[0], holes[0].variations[1]) << "each seed its own detail";
    EXPECT_EQ(holes[0].detail, detail);
    // A re-roll (new seed) keeps the hole's own amplitude, whatever the amplitude passed.
    curvature_inpaint::HoleVariations again = holes[0];
    curvature_inpaint::InpaintParams reroll = p.inpaint;
    reroll.seed += 1000;
    reroll.detail = 2 - detail;
    curvature_inpaint::InpaintAgain(again, reroll);
    ASSERT_EQ(again.choice.kinds, holes[0].choice.kinds);
    EXPECT_EQ(again.variations[0] == again.variations[1], detail == 0);
    const auto result = FillHoles(m, p);
    ASSERT_TRUE(result.holes[0].choice.problem.empty()) << result.holes[0].choice.problem;
    fills.emplace_back();
    for (size_t v = scan_vertices; v < m.vert.size(); ++v) fills.back().push_back(m.vert[v].cP());
    spreads.push_back(result.holes[0].result_spread);
  }
  ASSERT_EQ(fills[0].size(), fills[1].size());
  double largest = 0;
  for (size_t i = 0; i < fills[0].size(); ++i)
    largest = std::max(largest, double(vcg::Distance(fills[0][i], fills[1][i])));
  EXPECT_GT(largest, 0.05 * kBumpHeight) << "detail 2 should move the fill";
  EXPECT_GT(spreads[1], 1.1 * spreads[0]) << "more detail, more curvature spread";
}

/// Centre and radius of a loop's vertices.
std::pair<Eigen::Vector3d, double> LoopBall(const CMeshO& m, const std::vector<int>& loop) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (int v : loop) c += Eigen::Vector3d(m.vert[v].cP()[0], m.vert[v].cP()[1], m.vert[v].cP()[2]);
  c /= double(loop.size());
  double r = 0;
  for (int v : loop)
    r = std::max(
        r, (Eigen::Vector3d(m.vert[v].cP()[0], m.vert[v].cP()[1], m.vert[v].cP()[2]) - c).norm());
  return {c, r};
}

/// A wavy open sheet over [-3, 3]^2 (its outer border is no hole), mirror-symmetric across
/// y = 0, with holes of radius 0.25 punched at the vertices nearest to `at` (x, y) and
/// coarse-filled.
vcg_ext::CoarseFillResult WavySheetWithHoles(CMeshO& m, const std::vector<Point3m>& at) {
  vcg::tri::Grid(m, 121, 121, 6.0f, 6.0f); // [0, 6]^2
  for (auto& v : m.vert) {
    v.P()[0] -= 3, v.P()[1] -= 3;
    v.P()[2] = 0.2f * std::sin(2 * v.P()[0]) * std::cos(1.5f * v.P()[1]);
  }
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
  for (const Point3m& a : at) {
    Point3m on = m.vert[0].cP();
    for (const auto& v : m.vert)
      if (std::hypot(v.cP()[0] - a[0], v.cP()[1] - a[1]) < std::hypot(on[0] - a[0], on[1] - a[1]))
        on = v.cP();
    vcg_ext::PunchHole(m, on, Scalarm(0.25));
  }
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
  vcg_ext::CoarseFillParams cp;
  cp.keep_longest_open = true;
  return curvature_inpaint::CoarseFill(m, cp);
}

TEST(CurvatureReading, EveryPixelsValueAndHoleWhateverTheImagesFormat) {
  // Not square, the hole transparent (as in hole_<k>_rgba.png), one pixel off the colour map,
  // the mask in grey levels: the reading must not depend on any of it.
  const int w = 7, h = 5;
  QImage image(w, h, QImage::Format_ARGB32);
  QImage mask(w, h, QImage::Format_Grayscale8);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const vcg_ext::Rgb8 c = vcg_ext::CurvatureColormap::Color8((y * w + x) / double(w * h));
      const bool hole = x >= 2 && x < 5 && y >= 1 && y < 4;
      image.setPixel(x, y, qRgba(c.r, c.g, c.b, hole ? 0 : 255));
      mask.setPixel(x, y, hole ? qRgb(200, 200, 200) : qRgb(100, 100, 100));
    }
  image.setPixel(6, 4, qRgb(128, 128, 128));
  const auto r = curvature_inpaint::ReadCurvatureImage(image, mask);
  ASSERT_EQ(r.width, w);
  ASSERT_EQ(r.height, h);
  ASSERT_EQ(r.t.size(), size_t(w * h));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      EXPECT_EQ(bool(r.hole[i]), x >= 2 && x < 5 && y >= 1 && y < 4) << x << "," << y;
      if (x == 6 && y == 4) {
        EXPECT_GT(r.distance[i], 100) << "grey is far from the colour map";
        continue;
      }
      EXPECT_NEAR(r.t[i], i / double(w * h), 1.0 / 255) << x << "," << y;
      EXPECT_LT(r.distance[i], 1.0) << x << "," << y;
    }
}

TEST(FakeHoles, NeverOverlapARealHoleEachOtherOrTheBorder) {
  CMeshO m;
  const auto coarse = WavySheetWithHoles(m, {Point3m(-0.5f, -0.5f, 0), Point3m(0.7f, 0.4f, 0)});
  ASSERT_EQ(coarse.FilledCount(), 2);
  const vcg_ext::VertexFaces vf(m);
  for (int hole = 0; hole < int(coarse.holes.size()); ++hole) {
    if (!coarse.holes[size_t(hole)].filled) continue;
    curvature_inpaint::FakeHoleParams fp;
    std::string why;
    const auto fakes = curvature_inpaint::CutFakeHoles(m, vf, coarse, hole, fp, &why);
    EXPECT_EQ(int(fakes.size()), fp.count) << why;
    const auto own = LoopBall(m, coarse.holes[size_t(hole)].loop);
    const double piece = fp.piece * own.second;
    for (size_t i = 0; i < fakes.size(); ++i) {
      for (const auto& h : coarse.holes)
        if (h.filled) {
          const auto ball = LoopBall(m, h.loop);
          EXPECT_GT((fakes[i]->centre - ball.first).norm(), piece + ball.second);
        }
      for (size_t j = 0; j < i; ++j)
        EXPECT_GT((fakes[i]->centre - fakes[j]->centre).norm(), 2 * piece);
      // No vertex of the piece on the sheet's border.
      for (const auto& v : fakes[i]->truth.vert) {
        EXPECT_LT(std::abs(v.cP()[0]), 2.99f);
        EXPECT_LT(std::abs(v.cP()[1]), 2.99f);
      }
      EXPECT_EQ(curvature_inpaint::CountHoles(fakes[i]->holed).loop_edges.size(), 2u);
      EXPECT_FALSE(fakes[i]->cut.empty());
    }
  }
}

// A candidate whose fill ran off to infinity (coordinates that end as NaN) is the worst of
// all, not a distance to compute: the grid of its triangles would ask for memory without end.
TEST(FakeHoles, AFillOffToInfinityScoresWorstOfAll) {
  CMeshO m;
  const auto coarse = WavySheetWithHoles(m, {Point3m(-0.5f, -0.5f, 0)});
  ASSERT_EQ(coarse.FilledCount(), 1);
  const vcg_ext::VertexFaces vf(m);
  std::string why;
  const auto fakes =
      curvature_inpaint::CutFakeHoles(m, vf, coarse, 0, curvature_inpaint::FakeHoleParams(), &why);
  ASSERT_FALSE(fakes.empty()) << why;
  const Eigen::Vector3d nan = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  const std::vector<Eigen::Vector3d> points{fakes[0]->centre, nan, nan};
  EXPECT_TRUE(std::isinf(curvature_inpaint::FakeHoleError(*fakes[0], points, {{0, 1, 2}})));
}

/// Distance from p to triangle abc, as a brute force would measure it: to its plane where the
/// foot lies inside it, else to the nearest of its edges.
double DistanceToTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                          const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d n = (b - a).cross(c - a).normalized();
  const Eigen::Vector3d foot = p - (p - a).dot(n) * n;
  const bool inside = (b - a).cross(foot - a).dot(n) >= 0 && (c - b).cross(foot - b).dot(n) >= 0 &&
                      (a - c).cross(foot - c).dot(n) >= 0;
  if (inside) return (p - foot).norm();
  auto to_edge = [&p](const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
    const double s = std::max(0.0, std::min(1.0, (p - u).dot(v - u) / (v - u).squaredNorm()));
    return (p - (u + s * (v - u))).norm();
  };
  return std::min({to_edge(a, b), to_edge(b, c), to_edge(c, a)});
}

// The fake-hole error skips triangles it has measured already and those whose bounds lie
// farther than the nearest so far: it must still be the RMS distance every triangle gives.
TEST(FakeHoles, TheErrorIsTheDistanceToEveryTriangleMeasured) {
  CMeshO m;
  const auto coarse = WavySheetWithHoles(m, {Point3m(-0.5f, -0.5f, 0)});
  const vcg_ext::VertexFaces vf(m);
  std::string why;
  const auto fakes =
      curvature_inpaint::CutFakeHoles(m, vf, coarse, 0, curvature_inpaint::FakeHoleParams(), &why);
  ASSERT_FALSE(fakes.empty()) << why;
  const auto& cut = fakes[0]->cut;
  ASSERT_LT(cut.size(), 400u); // every triangle's centre is a sample
  // A fill: the cut surface raised and tilted, as a candidate that missed it would be.
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 3>> triangles;
  for (const auto& t : cut) {
    const int first = int(points.size());
    for (const auto& v : t) points.push_back(v + Eigen::Vector3d(0, 0, 0.01 + 0.2 * v.x()));
    triangles.push_back({first, first + 1, first + 2});
  }
  auto rms = [](const std::vector<std::array<Eigen::Vector3d, 3>>& from,
                const std::vector<std::array<Eigen::Vector3d, 3>>& to) {
    double sum = 0;
    for (const auto& f : from) {
      double nearest = std::numeric_limits<double>::infinity();
      for (const auto& t : to)
        nearest = std::min(nearest, DistanceToTriangle((f[0] + f[1] + f[2]) / 3, t[0], t[1], t[2]));
      sum += nearest * nearest;
    }
    return std::sqrt(sum / double(from.size()));
  };
  std::vector<std::array<Eigen::Vector3d, 3>> fill;
  for (const auto& t : triangles) fill.push_back({points[t[0]], points[t[1]], points[t[2]]});
  const double expected = 0.5 * (rms(fill, cut) + rms(cut, fill));
  ASSERT_GT(expected, 0.001);
  EXPECT_NEAR(curvature_inpaint::FakeHoleError(*fakes[0], points, triangles), expected,
              1e-9 * expected);
}

/// A closed surface of revolution about the z axis, radius `profile(z)` for z in [0, length]
/// (poles at both ends), `rings` rings of `around` vertices, faces facing out.
template <class Profile>
void MakeRevolved(CMeshO& m, double length, int rings, int around, Profile profile) {
  vcg::tri::Allocator<CMeshO>::AddVertices(m, size_t(rings * around + 2));
  for (int k = 0; k < rings; ++k)
    for (int j = 0; j < around; ++j) {
      const double z = length * (k + 1) / (rings + 1), a = 2 * M_PI * j / around;
      m.vert[size_t(k * around + j)].P() =
          Point3m(Scalarm(profile(z) * std::cos(a)), Scalarm(profile(z) * std::sin(a)), Scalarm(z));
    }
  const size_t bottom = size_t(rings * around), top = bottom + 1;
  m.vert[bottom].P() = Point3m(0, 0, 0);
  m.vert[top].P() = Point3m(0, 0, Scalarm(length));
  auto at = [&](int k, int j) { return &m.vert[size_t(k * around + (j % around))]; };
  auto add = [&](CVertexO* a, CVertexO* b, CVertexO* c) {
    auto f = vcg::tri::Allocator<CMeshO>::AddFaces(m, 1);
    f->V(0) = a, f->V(1) = b, f->V(2) = c;
  };
  for (int j = 0; j < around; ++j) {
    add(&m.vert[bottom], at(0, j + 1), at(0, j));
    add(&m.vert[top], at(rings - 1, j), at(rings - 1, j + 1));
    for (int k = 0; k + 1 < rings; ++k) {
      add(at(k, j), at(k, j + 1), at(k + 1, j + 1));
      add(at(k, j), at(k + 1, j + 1), at(k + 1, j));
    }
  }
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
}

// A ball (radius 1) with a stick (radius 0.15) ending in a knob (radius 0.5), a hole of radius
// 0.5 in the ball. The only places for fake holes of its size are on the stick, where one cuts
// it in two, and on the knob, whose piece (three hole radii around it) wraps the whole knob and
// ends in a ring around the stick: that ring is shorter than the hole's own loop, and the
// validation's coarse fill, which leaves the longest loop open as the piece's border, would
// cap the ring and leave the hole open. No fake hole is cut there.
TEST(FakeHoles, NoneIsCutWhereThePiecesBorderIsShorterThanTheHole) {
  CMeshO m;
  MakeRevolved(m, 6.0, 239, 48, [](double z) {
    const double ball = std::sqrt(std::max(0.0, 1 - (z - 1) * (z - 1)));
    const double knob = std::sqrt(std::max(0.0, 0.25 - (z - 5.5) * (z - 5.5)));
    return std::max({ball, knob, z > 1 && z < 5.5 ? 0.15 : 0.0});
  });
  ASSERT_TRUE(curvature_inpaint::CountHoles(m).loop_edges.empty());
  vcg_ext::PunchHole(m, Point3m(0.8f, 0, 1.6f), Scalarm(0.55));
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
  const auto coarse = curvature_inpaint::CoarseFill(m, vcg_ext::CoarseFillParams());
  ASSERT_EQ(coarse.FilledCount(), 1);
  const vcg_ext::VertexFaces vf(m);
  curvature_inpaint::FakeHoleParams fp;
  fp.piece = 3;     // a piece that wraps the knob
  fp.farthest = 10; // and places as far as the knob
  std::string why;
  const auto fakes = curvature_inpaint::CutFakeHoles(m, vf, coarse, 0, fp, &why);
  for (const auto& f : fakes) {
    // The loop a piece's coarse fill closes is the fake hole's, around its centre.
    CMeshO local;
    curvature_inpaint::CopyMesh(f->holed, local);
    vcg_ext::CoarseFillParams cp;
    cp.keep_longest_open = true;
    const auto filled = curvature_inpaint::CoarseFill(local, cp);
    for (const auto& h : filled.holes)
      if (h.filled)
        EXPECT_LT((LoopBall(local, h.loop).first - f->centre).norm(), 0.5) << f->centre.transpose();
  }
  EXPECT_TRUE(fakes.empty()) << fakes.size() << " cut, the first at "
                             << fakes[0]->centre.transpose();
  EXPECT_NE(why.find("no room"), std::string::npos) << why;
}

TEST(FakeHoles, OneIsCutAtTheMirrorPlaceWhereItIsKnownSurface) {
  CMeshO m;
  const auto coarse = WavySheetWithHoles(m, {Point3m(-0.5f, -0.8f, 0)});
  ASSERT_EQ(coarse.FilledCount(), 1);
  const vcg_ext::VertexFaces vf(m);
  const auto own = LoopBall(m, coarse.holes[0].loop);
  const Eigen::Vector3d twin(own.first.x(), -own.first.y(), own.first.z()); // across y = 0
  curvature_inpaint::FakeHoleParams fp;
  vcg_ext::SymmetryPlane plane; // y = 0
  plane.normal = Eigen::Vector3d::UnitY();
  fp.mirror_planes = {plane};
  std::string why;
  const auto fakes = curvature_inpaint::CutFakeHoles(m, vf, coarse, 0, fp, &why);
  ASSERT_EQ(int(fakes.size()), fp.count + 1) << why;
  EXPECT_TRUE(fakes.back()->at_mirror_place);
  EXPECT_LT((fakes.back()->centre - twin).norm(), own.second);
  for (size_t i = 0; i + 1 < fakes.size(); ++i) EXPECT_FALSE(fakes[i]->at_mirror_place);
  // A plane through the hole: its mirror place is the hole itself, and none is cut there.
  fp.mirror_planes[0].offset = own.first.y();
  const auto across = curvature_inpaint::CutFakeHoles(m, vf, coarse, 0, fp, &why);
  EXPECT_EQ(int(across.size()), fp.count) << why;
  for (const auto& f : across) EXPECT_FALSE(f->at_mirror_place);
}

TEST(FakeHoles, ASmallClosedPartFallsBackToTheVariationScoreAndSaysSo) {
  CMeshO m;
  vcg::tri::Sphere(m, 4);
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
  vcg_ext::PunchHole(m, Point3m(1, 0, 0), Scalarm(0.8)); // a hole 0.4 of the part wide
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
  HoleFillParams p = SmallImages();
  const auto result = FillHoles(m, p);
  ASSERT_EQ(result.holes.size(), 1u);
  const auto& r = result.holes[0];
  EXPECT_TRUE(r.choice.validation.candidates.empty());
  EXPECT_NE(r.choice.validation.note.find("no room"), std::string::npos)
      << r.choice.validation.note;
  EXPECT_NE(r.choice.validation.note.find("variation score"), std::string::npos)
      << r.choice.validation.note;
  // The report says so too, for those who read it instead of the log.
  const std::string json = curvature_inpaint::HoleFillReportJson(result, p);
  EXPECT_NE(json.find("\"validation\": {\"note\": \"no room"), std::string::npos) << json;
  EXPECT_TRUE(r.choice.problem.empty()) << r.choice.problem;
  EXPECT_GE(r.choice.pick, 1);
  const auto census = curvature_inpaint::CountHoles(m);
  EXPECT_TRUE(census.loop_edges.empty());
}

// The report's first hole as a JSON parser reads it (an empty object where it does not parse).
QJsonObject FirstHoleOfReport(const curvature_inpaint::HoleFillResult& result) {
  const std::string json = curvature_inpaint::HoleFillReportJson(result, SmallImages());
  QJsonParseError error;
  const QJsonDocument doc = QJsonDocument::fromJson(QByteArray::fromStdString(json), &error);
  EXPECT_EQ(error.error, QJsonParseError::NoError) << error.errorString().toStdString() << json;
  return doc.object()["holes"].toArray()[0].toObject();
}

// JSON has no infinity and no NaN: a value that is not finite (a candidate whose fill could
// not be scored, a score of a blank image) is written as null, so the report still parses.
TEST(Report, NumbersThatAreNotFiniteAreWrittenAsNull) {
  curvature_inpaint::HoleFillResult result;
  curvature_inpaint::HoleFillReport r;
  r.choice.scores = {std::numeric_limits<double>::quiet_NaN(), 0.25};
  r.choice.kinds = {"continuation", "continuation"};
  r.choice.pick = 2;
  r.choice.validation.candidates = {"coarse", "tri-laplacian"};
  r.choice.validation.errors = {0.5, std::numeric_limits<double>::infinity()};
  r.choice.validation.detail = {-1, -1};
  r.choice.validation.per_fake_hole = {{0.5, -std::numeric_limits<double>::infinity()}};
  r.choice.validation.fake_holes = 1;
  r.choice.validation.chosen = 0;
  r.deformation.max_move = std::numeric_limits<double>::quiet_NaN();
  result.holes.push_back(r);
  const QJsonObject hole = FirstHoleOfReport(result);
  EXPECT_TRUE(hole["scores"].toArray()[0].isNull());
  EXPECT_DOUBLE_EQ(hole["scores"].toArray()[1].toDouble(), 0.25);
  const QJsonObject validation = hole["validation"].toObject();
  EXPECT_TRUE(validation["candidates"].toArray()[1].toObject()["error"].isNull());
  EXPECT_DOUBLE_EQ(validation["candidates"].toArray()[0].toObject()["error"].toDouble(), 0.5);
  EXPECT_TRUE(validation["per_fake_hole"].toArray()[0].toArray()[1].isNull());
  EXPECT_TRUE(hole["max_move"].isNull());
}

TEST(Report, NotesReadBackExactlyWhateverCharactersTheyHold) {
  // A note may quote a file name or a server's message: quotes, backslashes, line breaks.
  const std::string note = "server said \"bad\" at C:\\scans\\a.ply\nthen\t\x01stopped";
  curvature_inpaint::HoleFillResult result;
  curvature_inpaint::HoleFillReport r;
  r.choice.kinds = {"symmetry \"mirrored\""};
  r.kind = r.choice.kinds[0];
  r.choice.validation.note = note;
  r.choice.priors.no_creases = note;
  r.choice.problem = note;
  result.holes.push_back(r);
  const QJsonObject hole = FirstHoleOfReport(result);
  EXPECT_EQ(hole["validation"].toObject()["note"].toString().toStdString(), note);
  EXPECT_EQ(hole["no_creases"].toString().toStdString(), note);
  EXPECT_EQ(hole["problem"].toString().toStdString(), note);
  EXPECT_EQ(hole["kind"].toString().toStdString(), r.kind);
  EXPECT_EQ(hole["kinds"].toArray()[0].toString().toStdString(), r.kind);
}

TEST(FakeHoles, TheValidatedChoiceIsTheSameForAnyThreadCount) {
  CMeshO truth;
  MakeBumpySphere(truth);
  std::vector<std::vector<Point3m>> results;
  std::vector<std::vector<std::string>> choices;
  std::vector<std::vector<curvature_inpaint::HoleVariations>> previews;
  // 8 threads over the 3 holes leave each hole's fake holes 2 of their own.
  for (int threads : {1, 2, 8}) {
    CMeshO m;
    curvature_inpaint::CopyMesh(truth, m);
    for (const Point3m at : {Point3m(1.02f, 0, 0), Point3m(-1, 0.1f, 0), Point3m(0, 0.1f, -1)})
      vcg_ext::PunchHole(m, at, Scalarm(0.12));
    vcg::tri::UpdateBounding<CMeshO>::Box(m);
    HoleFillParams p = SmallImages();
    p.images.coarse.threads = threads;
    // The dialog's preview: its holes run in parallel too.
    CMeshO scratch;
    curvature_inpaint::CopyMesh(m, scratch);
    previews.push_back(curvature_inpaint::InpaintHoles(scratch, p));
    const auto result = FillHoles(m, p);
    choices.emplace_back();
    ASSERT_EQ(previews.back().size(), result.holes.size());
    for (size_t k = 0; k < result.holes.size(); ++k) {
      const auto& h = result.holes[k];
      ASSERT_FALSE(h.choice.validation.candidates.empty()) << h.choice.validation.note;
      choices.back().push_back(h.choice.validation.candidates[size_t(h.choice.validation.chosen)]);
      // The preview validates as the fill does.
      EXPECT_EQ(previews.back()[k].choice.validation.candidates, h.choice.validation.candidates)
          << threads << " " << k;
      EXPECT_EQ(previews.back()[k].choice.validation.errors, h.choice.validation.errors)
          << threads << " " << k;
      EXPECT_EQ(previews.back()[k].choice.validation.chosen, h.choice.validation.chosen)
          << threads << " " << k;
    }
    results.emplace_back();
    for (const auto& v : m.vert) results.back().push_back(v.cP());
  }
  for (size_t run = 1; run < results.size(); ++run) {
    EXPECT_EQ(choices[0], choices[run]) << run;
    for (size_t k = 0; k < previews[0].size(); ++k) {
      EXPECT_EQ(previews[0][k].variations, previews[run][k].variations) << run << " " << k;
      EXPECT_EQ(previews[0][k].choice.pick, previews[run][k].choice.pick) << run << " " << k;
    }
    ASSERT_EQ(results[0].size(), results[run].size());
    for (size_t i = 0; i < results[0].size(); ++i)
      ASSERT_EQ(results[0][i], results[run][i]) << run << " " << i;
  }
}

/// A port on 127.0.0.1 whose connections are taken by the kernel and never answered: a
/// service that hangs.
class SilentServer {
public:
  SilentServer() {
    fd_ = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t len = sizeof a;
    if (fd_ < 0 || bind(fd_, reinterpret_cast<sockaddr*>(&a), len) != 0 || listen(fd_, 8) != 0 ||
        getsockname(fd_, reinterpret_cast<sockaddr*>(&a), &len) != 0)
      throw std::runtime_error("no local port");
    port_ = ntohs(a.sin_port);
  }
  ~SilentServer() { close(fd_); }
  SilentServer(const SilentServer&) = delete;
  SilentServer& operator=(const SilentServer&) = delete;
  std::string Url() const { return "http://127.0.0.1:" + std::to_string(port_); }

private:
  int fd_ = -1;
  int port_ = 0;
};

std::thread::id g_caller;
std::atomic<int> g_callbacks{0}, g_callbacks_elsewhere{0};

/// MeshLab's callback: counts where it runs, and asks to stop after a few calls.
bool StopAfterAFewCalls(int, const char*) {
  if (std::this_thread::get_id() != g_caller) ++g_callbacks_elsewhere;
  return ++g_callbacks < 20;
}

TEST(Cancel, HolesOnSeveralServersStopTogetherAndTheCallbackRunsOnTheCallersThreadOnly) {
  CMeshO m;
  MakeBumpySphere(m);
  for (const Point3m at : {Point3m(1.02f, 0, 0), Point3m(-1, 0.1f, 0)})
    vcg_ext::PunchHole(m, at, Scalarm(0.12));
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
  std::vector<Point3m> before;
  for (const auto& v : m.vert) before.push_back(v.cP());
  SilentServer a, b;
  HoleFillParams p = SmallImages();
  p.inpaint.backend = "comfyui";
  p.inpaint.urls = {a.Url(), b.Url()}; // both holes in flight at once, one on another thread
  p.inpaint.http.max_retries = 0;
  g_caller = std::this_thread::get_id();
  for (bool preview : {false, true}) {
    g_callbacks = 0;
    g_callbacks_elsewhere = 0;
    CMeshO scratch;
    curvature_inpaint::CopyMesh(m, scratch);
    // A stop is no failure of the servers: it comes out as the stop it is, and the pool does
    // not move on to the next server ("every one of the 2 servers failed").
    std::string error;
    bool stopped = false;
    try {
      if (preview)
        curvature_inpaint::InpaintHoles(scratch, p, StopAfterAFewCalls);
      else
        FillHoles(m, p, StopAfterAFewCalls);
    } catch (const vcg_ext::CancelledError&) {
      stopped = true;
    } catch (const std::exception& e) {
      error = e.what();
    }
    EXPECT_TRUE(stopped) << preview << ": " << error;
    EXPECT_GE(g_callbacks, 20) << preview;
    EXPECT_EQ(g_callbacks_elsewhere, 0) << preview;
  }
  ASSERT_EQ(m.vert.size(), before.size());
  for (size_t i = 0; i < before.size(); ++i) ASSERT_EQ(m.vert[i].cP(), before[i]) << i;
}

/// A unit sphere covered with bumps everywhere but around (1, 0, 0): a smooth spot among
/// curved surroundings, like a flat stretch between a machined part's fillets.
void MakeSphereBumpyAroundASmoothSpot(CMeshO& m) {
  vcg::tri::Sphere(m, 5);
  const Eigen::Vector3d spot(1, 0, 0);
  std::vector<Eigen::Vector3d> bumps;
  const int count = 200; // a Fibonacci sphere's directions
  for (int i = 0; i < count; ++i) {
    const double z = 1 - (2 * i + 1.0) / count, ring = std::sqrt(1 - z * z);
    const double angle = i * M_PI * (3 - std::sqrt(5.0));
    const Eigen::Vector3d d(ring * std::cos(angle), ring * std::sin(angle), z);
    if (std::acos(d.dot(spot)) > 0.65) bumps.push_back(d);
  }
  for (auto& v : m.vert) {
    const Eigen::Vector3d p = Eigen::Vector3d(v.P()[0], v.P()[1], v.P()[2]).normalized();
    double r = 1;
    for (const auto& d : bumps) r += 0.02 * std::exp(-(p - d).squaredNorm() / (0.12 * 0.12));
    v.P() = Point3m(Scalarm(r * p.x()), Scalarm(r * p.y()), Scalarm(r * p.z()));
  }
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
  vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
}

// The fake holes near a hole in a smooth spot all land on bumps: what validates there (a fill
// that bends as the bumps bend) says nothing of the spot, which keeps its smooth fill.
TEST(FakeHoles, AHoleFarFlatterAroundThanItsFakeHolesKeepsTheSmoothFill) {
  CMeshO truth;
  MakeSphereBumpyAroundASmoothSpot(truth);
  for (double max_flatter : {8.0, 0.0}) {
    CMeshO m;
    curvature_inpaint::CopyMesh(truth, m);
    vcg_ext::PunchHole(m, Point3m(1, 0, 0), Scalarm(0.2));
    vcg::tri::UpdateBounding<CMeshO>::Box(m);
    HoleFillParams p = SmallImages();
    p.validation.max_flatter = max_flatter;
    const auto result = FillHoles(m, p);
    ASSERT_EQ(result.holes.size(), 1u);
    const auto& r = result.holes[0];
    ASSERT_GT(r.choice.validation.fake_holes, 0) << r.choice.validation.note;
    const bool kept = r.choice.validation.note.find("times flatter") != std::string::npos;
    if (max_flatter > 0) {
      EXPECT_TRUE(kept) << r.choice.validation.note;
      EXPECT_EQ(r.choice.validation.candidates[size_t(r.choice.validation.chosen)], "coarse");
      EXPECT_EQ(r.choice.pick, 0) << "the coarse fill, not a variation";
    } else {
      EXPECT_FALSE(kept) << r.choice.validation.note;
    }
  }
}

/// The symmetric egg in `m` with a hole over its first bump; returns its vertex count (the
/// fill's vertices come after).
size_t EggHoledOverItsFirstBump(CMeshO& m) {
  test::MakeSymmetricEgg(m);
  test::PunchBump(m, test::EggBumps()[0]);
  return m.vert.size();
}

/// The egg's one hole (over `bump`, `m` filled into `result`) took a symmetry candidate, and
/// the fill is as high as its twin.
void ExpectTheBumpBackFromItsTwin(const curvature_inpaint::HoleFillResult& result, const CMeshO& m,
                                  size_t scan_vertices, const Eigen::Vector3d& bump) {
  ASSERT_EQ(result.holes.size(), 1u);
  const auto& r = result.holes[0];
  ASSERT_TRUE(r.choice.problem.empty()) << r.choice.problem;
  ASSERT_FALSE(r.choice.validation.candidates.empty()) << r.choice.validation.note;
  EXPECT_EQ(r.kind.rfind("symmetry", 0), 0u) << "chose " << r.kind << ": " << Validation(r);
  // The twin's height is the bump's: the mirror image brings it back.
  EXPECT_NEAR(test::FillHeight(m, scan_vertices, bump), test::kEggBump, 0.1 * test::kEggBump);
  // The egg's halves are exact twins: the image covers the fill, its ring lies on the ring.
  EXPECT_GE(r.choice.priors.mirror_covered, 0.8);
  EXPECT_GE(r.choice.priors.mirror_ring_residual, 0);
  EXPECT_LT(r.choice.priors.mirror_ring_residual, 0.02);
  std::string log;
  for (const std::string& line : curvature_inpaint::DescribeHoleFill(result)) log += line + "\n";
  EXPECT_NE(log.find("mirror image on "), std::string::npos) << log;
  EXPECT_NE(curvature_inpaint::HoleFillReportJson(result, HoleFillParams())
                .find("\"mirror_image\": {\"covered\": "),
            std::string::npos);
}

TEST(Symmetry, AHoleOverABumpComesBackLikeItsTwin) {
  CMeshO m;
  const Eigen::Vector3d bump = test::EggBumps()[0];
  const size_t scan_vertices = EggHoledOverItsFirstBump(m);
  HoleFillParams p = SmallImages();
  CMeshO coarse;
  curvature_inpaint::CopyMesh(m, coarse);
  curvature_inpaint::CoarseFill(coarse, p.images.coarse);
  EXPECT_LT(test::FillHeight(coarse, scan_vertices, bump), 0.5 * test::kEggBump)
      << "the cap misses the bump";
  const auto result = FillHoles(m, p);
  ASSERT_TRUE(result.symmetry_detected);
  ASSERT_FALSE(result.symmetry.empty());
  EXPECT_GT(std::abs(result.symmetry[0].normal.x()), std::cos(M_PI / 180));
  ExpectTheBumpBackFromItsTwin(result, m, scan_vertices, bump);
}

TEST(Symmetry, APartialSymmetryServesAHoleWhoseSurroundingsItMirrors) {
  CMeshO m;
  const Eigen::Vector3d bump = test::EggBumps()[0];
  const size_t scan_vertices = EggHoledOverItsFirstBump(m);
  HoleFillParams p = SmallImages();
  // No plane can make the object symmetric: the egg's own is found as a partial symmetry.
  p.symmetry.detection.min_coverage = 1;
  p.symmetry.detection.min_partial_coverage = 0.5;
  const auto result = FillHoles(m, p);
  ASSERT_TRUE(result.symmetry_detected);
  EXPECT_TRUE(result.symmetry.empty());
  ASSERT_FALSE(result.symmetry_partial.empty());
  EXPECT_GT(std::abs(result.symmetry_partial[0].normal.x()), std::cos(M_PI / 180));
  std::string log;
  for (const std::string& line : curvature_inpaint::DescribeHoleFill(result)) log += line + "\n";
  EXPECT_NE(log.find("symmetry: none of the whole object; partial"), std::string::npos) << log;
  ExpectTheBumpBackFromItsTwin(result, m, scan_vertices, bump);
}

TEST(Symmetry, AHoleWhoseTwinIsMissingTooKeepsTheContinuation) {
  CMeshO m;
  test::MakeSymmetricEgg(m);
  test::PunchBump(m, test::EggBumps()[0]);
  test::PunchBump(m, test::EggBumps()[1]); // the twin
  HoleFillParams p = SmallImages();
  p.exemplar = false; // the choice is then coarse, a continuation or the tri-Laplacian
  const auto result = FillHoles(m, p);
  ASSERT_EQ(result.holes.size(), 2u);
  for (const auto& r : result.holes) {
    ASSERT_TRUE(r.choice.problem.empty() ||
                r.choice.problem.find("coarse fill validated") != std::string::npos)
        << r.choice.problem;
    EXPECT_EQ(std::count(r.choice.validation.candidates.begin(),
                         r.choice.validation.candidates.end(), "symmetry"),
              0);
    EXPECT_EQ(r.choice.validation.mirror_fake_holes, 0) << "the mirror place is the other hole";
    EXPECT_LT(r.choice.priors.mirror_covered, 0) << "its mirror image is in the other hole";
    if (r.choice.problem.empty())
      EXPECT_TRUE(r.kind == "continuation" || r.kind == "tri-laplacian");
  }
}

/// The cells of the cube [-1, 1]^3 split into n^3 that `solid` (of i, j, k in 0..n-1) keeps, as
/// a mesh: each square between a kept cell and one that is not split into two triangles,
/// outward.
template <class Solid>
void MakeBlock(CMeshO& m, int n, Solid solid) {
  auto kept = [&](int i, int j, int k) {
    return i >= 0 && j >= 0 && k >= 0 && i < n && j < n && k < n && solid(i, j, k);
  };
  std::map<std::array<int, 3>, int> index; // grid coordinates (0..n) -> vertex
  std::vector<Point3m> points;
  std::vector<std::array<int, 3>> faces;
  auto vertex = [&](const std::array<int, 3>& g) {
    const auto it = index.find(g);
    if (it != index.end()) return it->second;
    points.emplace_back(Scalarm(2.0 * g[0] / n - 1), Scalarm(2.0 * g[1] / n - 1),
                        Scalarm(2.0 * g[2] / n - 1));
    return index[g] = int(points.size()) - 1;
  };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        if (!kept(i, j, k)) continue;
        for (size_t axis = 0; axis < 3; ++axis)
          for (int side : {0, 1}) {
            std::array<int, 3> cell{i, j, k};
            cell[axis] += side ? 1 : -1;
            if (kept(cell[0], cell[1], cell[2])) continue;
            // The square between the cell and its empty neighbour; (u, w) follow the axis
            // cyclically, so a, b, c turn about +axis.
            const size_t u = (axis + 1) % 3, w = (axis + 2) % 3;
            std::array<int, 3> a{i, j, k};
            a[axis] += side;
            std::array<int, 3> b = a, c = a, d = a;
            ++b[u], ++c[u], ++c[w], ++d[w];
            const int va = vertex(a), vb = vertex(b), vc = vertex(c), vd = vertex(d);
            if (side)
              faces.push_back({va, vb, vc}), faces.push_back({va, vc, vd});
            else
              faces.push_back({va, vc, vb}), faces.push_back({va, vd, vc});
          }
      }
  vcg::tri::BuildMeshFromCoordVectorIndexVector(m, points, faces);
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
  vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
}

/// The cube [-1, 1]^3, each face an n x n grid of squares split into two triangles, outward.
void MakeCube(CMeshO& m, int n) {
  MakeBlock(m, n, [](int, int, int) { return true; });
}

/// The angle between the normals of the faces of `m` nearest `a` and `b` (per-face normals
/// up to date), in degrees: two points either side of an edge read its dihedral angle.
double DihedralDegrees(const CMeshO& m, const Point3m& a, const Point3m& b) {
  auto nearest_face_normal = [&m](const Point3m& q) {
    Scalarm best = std::numeric_limits<Scalarm>::max();
    Point3m normal(0, 0, 0);
    for (const auto& f : m.face) {
      Scalarm d = best;
      Point3m closest;
      if (vcg::face::PointDistanceBase(f, q, d, closest) && d < best) best = d, normal = f.cN();
    }
    return normal;
  };
  const double c = double(nearest_face_normal(a) * nearest_face_normal(b));
  return std::acos(std::max(-1.0, std::min(1.0, c))) * 180 / M_PI;
}

/// Signed distance of p to the surface of the box [-half, half] (negative inside).
double BoxDistance(const Point3m& p, const Eigen::Vector3d& half) {
  const Eigen::Vector3d q(std::abs(p[0]) - half.x(), std::abs(p[1]) - half.y(),
                          std::abs(p[2]) - half.z());
  const double outside = q.cwiseMax(0.0).norm();
  return outside > 0 ? outside : -q.maxCoeff();
}

/// Distance of p to the cube's surface.
double CubeDistance(const Point3m& p) {
  return BoxDistance(p, Eigen::Vector3d::Ones());
}

/// Fills the holes punched in `m` with the small images and without the mirror prior (the
/// boxes and the cylinder below are symmetric: their mirror image would restore what the prior
/// under test should), taking the variation of `pick_kind` where one is given.
curvature_inpaint::HoleFillResult FillWithoutSymmetry(CMeshO& m,
                                                      const std::string& pick_kind = "") {
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
  HoleFillParams p = SmallImages();
  p.symmetry.enabled = false;
  p.pick_kind = pick_kind;
  return FillHoles(m, p);
}

/// Fills the one hole punched in `m` as FillWithoutSymmetry does; whether the crease prior's
/// variation filled it (a failure recorded where not).
bool FillsOneHoleWithCreases(CMeshO& m, const std::string& pick_kind = "") {
  const auto result = FillWithoutSymmetry(m, pick_kind);
  if (result.holes.size() != 1) {
    ADD_FAILURE() << result.holes.size() << " holes";
    return false;
  }
  const auto& r = result.holes[0];
  if (!r.choice.problem.empty() || r.kind != "creases") {
    ADD_FAILURE() << "filled as " << r.kind << ": " << r.choice.problem << "; "
                  << r.choice.priors.no_creases << "; " << Validation(r);
    return false;
  }
  return true;
}

/// The distance of each of `points` to the surface of `truth`, over `unit`.
std::vector<double> DistancesTo(const CMeshO& truth, const std::vector<Eigen::Vector3d>& points,
                                double unit) {
  std::vector<double> distances;
  for (const Eigen::Vector3d& q : points) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& f : truth.face) {
      Eigen::Vector3d c[3];
      for (int k = 0; k < 3; ++k) c[k] = Eigen::Vector3d(f.cP(k)[0], f.cP(k)[1], f.cP(k)[2]);
      nearest = std::min(nearest, DistanceToTriangle(q, c[0], c[1], c[2]));
    }
    distances.push_back(nearest / unit);
  }
  return distances;
}

Eigen::Vector3d ToEigen(const Point3m& p) {
  return Eigen::Vector3d(double(p[0]), double(p[1]), double(p[2]));
}

/// The distance of each vertex of `m` from `first` on (a fill's) to the surface of `truth`,
/// over `unit`.
std::vector<double> FillErrors(const CMeshO& truth, const CMeshO& m, size_t first, double unit) {
  std::vector<Eigen::Vector3d> points;
  for (size_t v = first; v < m.vert.size(); ++v) points.push_back(ToEigen(m.vert[v].cP()));
  return DistancesTo(truth, points, unit);
}

/// The same for the middle and the edge midpoints of each triangle of `m` with a vertex from
/// `first` on: where the fill's surface, not only its vertices, lies.
std::vector<double> FillSurfaceErrors(const CMeshO& truth, const CMeshO& m, size_t first,
                                      double unit) {
  std::vector<Eigen::Vector3d> points;
  for (const auto& f : m.face) {
    if (f.IsD()) continue;
    bool is_new = false;
    for (int k = 0; k < 3; ++k) is_new = is_new || size_t(vcg::tri::Index(m, f.cV(k))) >= first;
    if (!is_new) continue;
    const Eigen::Vector3d a = ToEigen(f.cP(0)), b = ToEigen(f.cP(1)), c = ToEigen(f.cP(2));
    for (const Eigen::Vector3d& q : {Eigen::Vector3d((a + b + c) / 3), Eigen::Vector3d((a + b) / 2),
                                     Eigen::Vector3d((b + c) / 2), Eigen::Vector3d((c + a) / 2)})
      points.push_back(q);
  }
  return DistancesTo(truth, points, unit);
}

/// The distance of each fill vertex to the fandisk when a hole of `radius_frac` of its diagonal
/// around `seed_vertex` is filled with the crease prior's variation, in diagonals.
std::vector<double> FandiskCreaseFillErrors(int seed_vertex, double radius_frac = 0.05,
                                            bool surface = false) {
  CMeshO truth;
  curvature_inpaint::LoadMesh(std::string(CI_SHARED_MESHES) + "/fandisk.ply", truth);
  vcg::tri::UpdateBounding<CMeshO>::Box(truth);
  const double diagonal = truth.bbox.Diag();
  CMeshO m;
  curvature_inpaint::CopyMesh(truth, m);
  vcg_ext::PunchHole(m, m.vert[size_t(seed_vertex)].cP(), Scalarm(radius_frac * diagonal));
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
  const size_t scan_vertices = m.vert.size();
  HoleFillParams p = SmallImages();
  p.pick_kind = "creases";
  p.validation.fake_holes = 0;
  const auto result = FillHoles(m, p);
  EXPECT_EQ(result.holes.size(), 1u);
  if (result.holes.size() != 1 || result.holes[0].kind != "creases") {
    ADD_FAILURE() << "no crease fill: "
                  << (result.holes.empty() ? "" : result.holes[0].choice.problem);
    return {};
  }
  return surface ? FillSurfaceErrors(truth, m, scan_vertices, diagonal)
                 : FillErrors(truth, m, scan_vertices, diagonal);
}

// Two holes in the fandisk (from draws of the benchmark's rule outside its table) where the
// faces' extensions, each fill vertex projected on its own, piled vertices up on the creases'
// lines and folded the triangles between them: backed off half its way, the fill came back
// 1.1 and 1.6 % of the diagonal off the part, the creases 30-36 degrees rounder. Spread over
// the faces, every fill vertex lies within 0.6 % of the part.
TEST(Creases, AFillThatFoldsOnItsCreasesIsSpreadOverTheFacesNotBackedOff) {
  for (int seed_vertex : {2625, 158}) {
    SCOPED_TRACE(seed_vertex);
    const std::vector<double> errors = FandiskCreaseFillErrors(seed_vertex);
    ASSERT_FALSE(errors.empty());
    EXPECT_LT(*std::max_element(errors.begin(), errors.end()), 0.006);
  }
}

// Two more fandisk holes where several creases cross and the crease fill, even spread, folds
// where they crowd: backed off as a whole, every crease came back rounded (13 and 19 degrees
// off); backed off where it folds, the rest of the fill stays on the part.
TEST(Creases, AFillThatFoldsInOneCornerIsBackedOffThereNotAsAWhole) {
  for (int seed_vertex : {2451, 4515}) {
    SCOPED_TRACE(seed_vertex);
    const std::vector<double> errors = FandiskCreaseFillErrors(seed_vertex);
    ASSERT_FALSE(errors.empty());
    const double on_part =
        double(std::count_if(errors.begin(), errors.end(), [](double e) { return e < 0.001; })) /
        double(errors.size());
    // 0.99 and 0.88 of them within 0.1 % of the diagonal; backed off as a whole, 0.45 and 0.58.
    EXPECT_GT(on_part, 0.8);
  }
}

// A fandisk hole (development seed 9035 of the benchmark's rule) where a wall's crease with the
// top lies wholly in the hole and the top runs on past the wall's surface beyond another
// crease: paired from all their vertices, the two faces did not meet there, and the fill's
// surface came back up to 0.64 % of the diagonal off the part, 293 of its 332 sample points
// (triangle middles and edge midpoints) within 0.1 %. Paired from their vertices near the
// hole: 0.32 %, 315 of 332.
TEST(Creases, FacesArePairedFromHowTheyLieNearTheHole) {
  const std::vector<double> errors = FandiskCreaseFillErrors(2067, 0.035, true);
  ASSERT_FALSE(errors.empty());
  EXPECT_LT(*std::max_element(errors.begin(), errors.end()), 0.0045);
  const double near =
      double(std::count_if(errors.begin(), errors.end(), [](double e) { return e < 0.001; })) /
      double(errors.size());
  EXPECT_GT(near, 0.92);
}

TEST(Creases, AHoleOnACubesEdgeAndOneOnItsCornerComeBackSharp) {
  CMeshO m;
  MakeCube(m, 24);
  vcg_ext::PunchHole(m, Point3m(0.2f, 1, 1), Scalarm(0.3)); // on an edge
  vcg_ext::PunchHole(m, Point3m(-1, -1, 1), Scalarm(0.35)); // on a corner
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
  const size_t scan_vertices = m.vert.size();
  HoleFillParams p = SmallImages();
  p.symmetry.enabled = false; // the cube's mirror image would restore them too
  CMeshO coarse;
  curvature_inpaint::CopyMesh(m, coarse);
  curvature_inpaint::CoarseFill(coarse, p.images.coarse);
  double cap = 0;
  for (size_t v = scan_vertices; v < coarse.vert.size(); ++v)
    cap = std::max(cap, CubeDistance(coarse.vert[v].cP()));
  EXPECT_GT(cap, 0.05) << "the smooth cap rounds the edge and the corner";
  const auto result = FillHoles(m, p);
  ASSERT_EQ(result.holes.size(), 2u);
  for (const auto& r : result.holes) {
    ASSERT_TRUE(r.choice.problem.empty()) << r.choice.problem;
    EXPECT_EQ(r.kind, "creases") << Validation(r);
  }
  // Every fill vertex on the cube (the edge straight, the corner where the three faces meet)
  // within 1 % of the edge's length; every fill triangle has its corners on one face and lies
  // in it (normal within 5 degrees: the faces meet at the cube's own 90). Without the flips
  // that lay the triangles along the creases, a row of them straddles each crease (8 here).
  for (size_t v = scan_vertices; v < m.vert.size(); ++v)
    EXPECT_LT(CubeDistance(m.vert[v].cP()), 0.02) << v;
  int straddling = 0, on_a_face = 0;
  for (const auto& f : m.face) {
    bool is_new = false;
    for (int k = 0; k < 3; ++k)
      is_new = is_new || size_t(vcg::tri::Index(m, f.cV(k))) >= scan_vertices;
    if (!is_new) continue;
    int face_axis = -1;
    for (int axis = 0; axis < 3 && face_axis < 0; ++axis) {
      bool all = true;
      for (int k = 0; k < 3; ++k) all = all && std::abs(std::abs(f.cP(k)[axis]) - 1) < 2e-3;
      if (all && f.cP(0)[axis] * f.cP(1)[axis] > 0 && f.cP(0)[axis] * f.cP(2)[axis] > 0)
        face_axis = axis;
    }
    if (face_axis < 0) {
      ++straddling;
      continue;
    }
    ++on_a_face;
    const Point3m n = vcg::TriangleNormal(f).Normalize();
    EXPECT_GT(std::abs(n[face_axis]), std::cos(5 * M_PI / 180));
  }
  EXPECT_EQ(straddling, 0) << "of " << on_a_face + straddling;
  // No fill triangle cuts the edge or the corner off: the fill's surface, not only its
  // vertices, lies on the cube (without the flips, 0.043 inside: half the grid's spacing).
  double deepest = 0;
  for (const auto& f : m.face) {
    bool is_new = false;
    for (int k = 0; k < 3; ++k)
      is_new = is_new || size_t(vcg::tri::Index(m, f.cV(k))) >= scan_vertices;
    if (!is_new) continue;
    for (const Point3m& q : {(f.cP(0) + f.cP(1)) / 2, (f.cP(1) + f.cP(2)) / 2,
                             (f.cP(2) + f.cP(0)) / 2, (f.cP(0) + f.cP(1) + f.cP(2)) / 3})
      deepest = std::max(deepest, CubeDistance(q));
  }
  EXPECT_LT(deepest, 0.005);
  // The edge is as sharp as the cube's: the faces nearest two points a third of the grid's
  // spacing off it, one on each side, meet at its 90 degrees (a chamfer of fill triangles
  // that straddle the edge, one fill edge wide, would read about 45).
  vcg::tri::UpdateNormal<CMeshO>::PerFaceNormalized(m);
  const Scalarm off = Scalarm(2.0 / 24 / 3);
  for (Scalarm x : {Scalarm(0.1), Scalarm(0.2), Scalarm(0.3)})
    EXPECT_NEAR(DihedralDegrees(m, Point3m(x, 1, 1 - off), Point3m(x, 1 - off, 1)), 90, 5)
        << "at x = " << x;
}

// A hole on a plate's corner takes the whole vertical edge there, top to bottom: no crease edge
// of the two side faces is left beside it, yet they must meet at that edge, not run on through
// each other.
TEST(Creases, AHoleThatTakesAPlatesWholeCornerEdgeBringsItBack) {
  CMeshO m;
  MakeCube(m, 24);
  const Scalarm half_thickness = Scalarm(0.25);
  for (auto& v : m.vert) v.P()[2] *= half_thickness;
  vcg_ext::PunchHole(m, Point3m(1, 1, 0), Scalarm(0.4));
  const size_t scan_vertices = m.vert.size();
  ASSERT_TRUE(FillsOneHoleWithCreases(m));
  double worst = 0;
  for (size_t v = scan_vertices; v < m.vert.size(); ++v)
    worst = std::max(worst,
                     std::abs(BoxDistance(m.vert[v].cP(), Eigen::Vector3d(1, 1, half_thickness))));
  EXPECT_LT(worst, 0.02) << "a side face runs on through the other";
  // The edge between the side faces is as sharp as the plate's (the faces nearest two points
  // a third of the grid's spacing off it read 90 degrees; a chamfer reads about 45).
  vcg::tri::UpdateNormal<CMeshO>::PerFaceNormalized(m);
  const Scalarm off = Scalarm(2.0 / 24 / 3);
  for (Scalarm z : {Scalarm(-0.1), Scalarm(0), Scalarm(0.1)})
    EXPECT_NEAR(DihedralDegrees(m, Point3m(1, 1 - off, z), Point3m(1 - off, 1, z)), 90, 5)
        << "at z = " << z;
}

// A fandisk hole (development seed 9054 of the benchmark's rule) through the part's thin rim:
// the side face between top and bottom is narrower than the fill's edges, so few fill vertices
// land on it, and edges from the top to the bottom cut it off as a groove (1.14 times CGAL's
// RMS). With their ends on the creases with the side face: 0.66 times. Of the fill surface's
// 728 sample points (triangle middles and edge midpoints), 661 were within 0.1 % of the
// diagonal, RMS 0.42 %; now 678, RMS 0.37 %. What is left is where the coarse fill spans the
// rim as a wall from the top's border to the bottom's (smaller than the faces around it), which
// moving vertices cannot undo.
TEST(Creases, EdgesAcrossAThinRimsSideFaceRunOverIt) {
  std::vector<double> errors = FandiskCreaseFillErrors(5855, 0.05, true);
  ASSERT_FALSE(errors.empty());
  double squares = 0;
  for (double e : errors) squares += e * e;
  EXPECT_LT(std::sqrt(squares / double(errors.size())), 0.004);
  const double near =
      double(std::count_if(errors.begin(), errors.end(), [](double e) { return e < 0.001; })) /
      double(errors.size());
  EXPECT_GT(near, 0.92);
}

/// The height of the step below: 1 up to x = 0, down a 45-degree slope to 0.5 at x = 0.5, and
/// on at 0.5.
double StepHeight(double x) {
  return 1 - std::min(0.5, std::max(0.0, x));
}

// A step: the cube's top runs down a 45-degree slope from a convex crease (x = 0) to a
// concave one (x = 0.5) and on at half its height. A hole over the slope takes both creases;
// the faces' solid must be their intersection at the convex crease and their union at the
// concave one, both in the same fill.
TEST(Creases, AHoleOverAStepBringsBackItsConvexAndConcaveCreases) {
  CMeshO m;
  MakeCube(m, 24);
  for (auto& v : m.vert)
    if (v.cP()[2] == 1) v.P()[2] = Scalarm(StepHeight(double(v.cP()[0])));
  vcg_ext::PunchHole(m, Point3m(0.25f, 0, 0.75f), Scalarm(0.45));
  const size_t scan_vertices = m.vert.size();
  ASSERT_TRUE(FillsOneHoleWithCreases(m));
  double worst = 0;
  for (size_t v = scan_vertices; v < m.vert.size(); ++v)
    worst = std::max(worst,
                     std::abs(double(m.vert[v].cP()[2]) - StepHeight(double(m.vert[v].cP()[0]))));
  EXPECT_LT(worst, 0.02) << "a fill vertex off the step (height)";
  vcg::tri::UpdateNormal<CMeshO>::PerFaceNormalized(m);
  const Scalarm off = Scalarm(2.0 / 24 / 3);
  for (Scalarm y : {Scalarm(-0.1), Scalarm(0), Scalarm(0.1)}) {
    EXPECT_NEAR(DihedralDegrees(m, Point3m(-off, y, 1), Point3m(off, y, 1 - off)), 45, 5)
        << "the convex crease at y = " << y;
    EXPECT_NEAR(DihedralDegrees(m, Point3m(Scalarm(0.5) - off, y, Scalarm(0.5) + off),
                                Point3m(Scalarm(0.5) + off, y, Scalarm(0.5))),
                45, 5)
        << "the concave crease at y = " << y;
  }
}

/// The cube [-1, 1]^3 without its octant x, y, z > 0, each square of its surface split into two
/// triangles, outward. At (0, 0, 1) the top meets two walls at convex creases, and the walls
/// meet each other at a concave one.
void MakeNotchedCube(CMeshO& m, int n) {
  // A cell is cut where its centre lies in the octant.
  MakeBlock(m, n, [n](int i, int j, int k) { return !(2 * i >= n && 2 * j >= n && 2 * k >= n); });
}

// A hole where the notched cube's top meets both walls of its notch: the top covers the
// solid on either side of the concave crease between the walls, so the solid there is the top
// intersected with the union of the walls. Taken pair by pair (the top's convex crease with
// each wall, the walls' concave one), it was the top intersected with both walls: the fill
// came back with 80 of its 136 vertices within 0.01 of the solid, one 0.21 off, and the top
// meeting the walls at 5-31 degrees instead of 90.
TEST(Creases, AHoleWhereConvexAndConcaveCreasesMeetComesBackOnTheSolid) {
  CMeshO truth;
  MakeNotchedCube(truth, 24);
  CMeshO m;
  curvature_inpaint::CopyMesh(truth, m);
  vcg_ext::PunchHole(m, Point3m(0, 0, 1), Scalarm(0.4));
  const size_t scan_vertices = m.vert.size();
  ASSERT_TRUE(FillsOneHoleWithCreases(m));
  // 128 of 136 within 0.01, the rest (backed off where the corner's triangles fold) within
  // 0.05.
  const std::vector<double> errors = FillErrors(truth, m, scan_vertices, 1.0);
  ASSERT_FALSE(errors.empty());
  const double on_solid =
      double(std::count_if(errors.begin(), errors.end(), [](double e) { return e < 0.01; })) /
      double(errors.size());
  EXPECT_GT(on_solid, 0.9);
  EXPECT_LT(*std::max_element(errors.begin(), errors.end()), 0.06);
  // The walls meet at the notch's 90 degrees below the top, and the top meets each wall.
  vcg::tri::UpdateNormal<CMeshO>::PerFaceNormalized(m);
  const Scalarm off = Scalarm(2.0 / 24 / 3);
  EXPECT_NEAR(DihedralDegrees(m, Point3m(off, 2 * off, Scalarm(0.85)),
                              Point3m(2 * off, off, Scalarm(0.85))),
              90, 5)
      << "the concave crease";
  for (Scalarm t : {Scalarm(0.1), Scalarm(0.2)}) {
    EXPECT_NEAR(DihedralDegrees(m, Point3m(-off, t, 1), Point3m(off, t, 1 - off)), 90, 5)
        << "the top and the wall x = 0 at y = " << t;
    EXPECT_NEAR(DihedralDegrees(m, Point3m(t, -off, 1), Point3m(t, off, 1 - off)), 90, 5)
        << "the top and the wall y = 0 at x = " << t;
  }
}

// The step through the whole box (every height above the middle scaled into the step's, so the
// side faces keep their planes), a hole where the slope meets the side face y = 1: the side
// face's outline is not convex, and at one of the hole's corners the concave crease at the
// slope's foot runs into it, and no crease edge pairs the side face with the slope. Pair by
// pair, the fill's vertices were backed off where its triangles folded, up to 0.075 inside the
// box. As one solid, every fill vertex is on it; with the side face and the slope paired as
// the solid's formula meets them, so is every fill triangle (0.035 deep across their crease
// before: no fill vertex lay on its line).
TEST(Creases, AHoleWhereAStepMeetsASideFaceComesBackOnTheSolid) {
  CMeshO truth;
  MakeCube(truth, 24);
  for (auto& v : truth.vert)
    if (v.cP()[2] > 0) v.P()[2] = Scalarm(double(v.cP()[2]) * StepHeight(double(v.cP()[0])));
  CMeshO m;
  curvature_inpaint::CopyMesh(truth, m);
  vcg_ext::PunchHole(m, Point3m(0.25f, 1, 0.75f), Scalarm(0.4));
  const size_t scan_vertices = m.vert.size();
  ASSERT_TRUE(FillsOneHoleWithCreases(m, "creases"));
  const std::vector<double> errors = FillErrors(truth, m, scan_vertices, 1.0);
  ASSERT_FALSE(errors.empty());
  EXPECT_LT(*std::max_element(errors.begin(), errors.end()), 0.005);
  const std::vector<double> surface = FillSurfaceErrors(truth, m, scan_vertices, 1.0);
  EXPECT_LT(*std::max_element(surface.begin(), surface.end()), 0.005);
}

// A hole in a cylinder's side a ring below the edge where the flat end meets it: one face all
// around the hole, a crease beyond it. The crease prior offers that face extended across the
// hole (before, it offered nothing: "fewer than two smooth faces meet at it").
TEST(Creases, AHoleInOneFaceBesideAnEdgeGetsTheFaceExtended) {
  CMeshO m;
  MakeRevolved(m, 2.0, 40, 64, [](double) { return 1.0; });
  vcg_ext::PunchHole(m, Point3m(1, 0, 1.65f), Scalarm(0.25));
  const size_t scan_vertices = m.vert.size();
  ASSERT_TRUE(FillsOneHoleWithCreases(m, "creases"));
  ASSERT_GT(m.vert.size(), scan_vertices);
  for (size_t v = scan_vertices; v < m.vert.size(); ++v)
    EXPECT_NEAR(std::hypot(m.vert[v].cP()[0], m.vert[v].cP()[1]), 1, 0.005) << v;
}

// A hole in the middle of a cylinder's side, no crease within its context: the crease prior
// offers the one face around it extended ("face"), on the cylinder; without
// `face_without_crease` it offers nothing, as before.
TEST(Creases, AHoleInOneFaceWithNoCreaseNearGetsTheFaceExtended) {
  for (bool face : {true, false}) {
    SCOPED_TRACE(face);
    CMeshO m;
    MakeRevolved(m, 2.0, 40, 64, [](double) { return 1.0; });
    vcg_ext::PunchHole(m, Point3m(1, 0, 1), Scalarm(0.25));
    vcg::tri::UpdateBounding<CMeshO>::Box(m);
    const size_t scan_vertices = m.vert.size();
    HoleFillParams p = SmallImages();
    p.symmetry.enabled = false;
    p.pick_kind = "face";
    p.crease_fill.face_without_crease = face;
    const auto result = FillHoles(m, p);
    ASSERT_EQ(result.holes.size(), 1u);
    const auto& r = result.holes[0];
    ASSERT_TRUE(r.choice.problem.empty()) << r.choice.problem;
    if (!face) {
      EXPECT_EQ(r.choice.priors.no_creases, "no crease runs into it");
      EXPECT_NE(r.kind, "face");
      continue;
    }
    EXPECT_EQ(r.kind, "face") << r.choice.priors.no_creases;
    ASSERT_GT(m.vert.size(), scan_vertices);
    for (size_t v = scan_vertices; v < m.vert.size(); ++v)
      EXPECT_NEAR(std::hypot(m.vert[v].cP()[0], m.vert[v].cP()[1]), 1, 0.005) << v;
  }
}

// A hole in one of a cube's faces, two grid cells from its edge: the coarse fill's flat cap is
// the face itself; the continuation and the tri-Laplacian read the curvature of the edge
// nearby and bent it off the face.
TEST(FlatCaps, AHoleInAFaceBesideAnEdgeStaysInTheFace) {
  CMeshO m;
  MakeCube(m, 24);
  vcg_ext::PunchHole(m, Point3m(0.55f, 0, 1), Scalarm(0.3));
  const size_t scan_vertices = m.vert.size();
  const auto result = FillWithoutSymmetry(m);
  ASSERT_EQ(result.holes.size(), 1u);
  EXPECT_NE(result.holes[0].choice.problem.find("flat cap"), std::string::npos)
      << result.holes[0].choice.problem;
  ASSERT_GT(m.vert.size(), scan_vertices);
  for (size_t v = scan_vertices; v < m.vert.size(); ++v)
    EXPECT_NEAR(m.vert[v].cP()[2], 1, 1e-6) << v;
}

/// An ellipsoid (semi-axes 1, 0.7, 0.5) and a point's distance to it (first order).
void MakeEllipsoid(CMeshO& m) {
  vcg::tri::Sphere(m, 5);
  for (auto& v : m.vert)
    v.P() = Point3m(v.P()[0], Scalarm(0.7) * v.P()[1], Scalarm(0.5) * v.P()[2]);
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
}

double EllipsoidDistance(const Point3m& p) {
  const Eigen::Vector3d q(p[0], p[1] / 0.7, p[2] / 0.5);
  const Eigen::Vector3d gradient(2 * p[0], 2 * p[1] / 0.49, 2 * p[2] / 0.25);
  return std::abs(q.squaredNorm() - 1) / gradient.norm();
}

// Where the curvature changes across a hole (an ellipsoid's side, between its flat and its
// sharp end), the thin plate leaves the change out and the tri-Laplacian carries it on: its
// variation is offered on every hole, closer to the surface than the coarse fill, and the fake
// holes choose it.
TEST(TriLaplacian, AHoleOnAnEllipsoidComesBackCloserThanTheThinPlate) {
  CMeshO m;
  MakeEllipsoid(m);
  vcg_ext::PunchHole(m, Point3m(0.6f, 0.5f, 0.1f), Scalarm(0.3));
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
  const size_t scan_vertices = m.vert.size();
  CMeshO holed;
  curvature_inpaint::CopyMesh(m, holed);
  auto rms = [&](const CMeshO& filled) {
    double sum = 0;
    for (size_t v = scan_vertices; v < filled.vert.size(); ++v)
      sum += std::pow(EllipsoidDistance(filled.vert[v].cP()), 2);
    return std::sqrt(sum / double(filled.vert.size() - scan_vertices));
  };
  HoleFillParams p = SmallImages();
  p.symmetry.enabled = false; // the ellipsoid's mirror image would restore it too
  CMeshO coarse;
  curvature_inpaint::CopyMesh(m, coarse);
  curvature_inpaint::CoarseFill(coarse, p.images.coarse);

  CMeshO picked;
  curvature_inpaint::CopyMesh(m, picked);
  HoleFillParams pick = p;
  pick.validation.fake_holes = 0;
  pick.pick_kind = "tri-laplacian";
  const auto direct = FillHoles(picked, pick);
  ASSERT_EQ(direct.holes.size(), 1u);
  EXPECT_EQ(direct.holes[0].kind, "tri-laplacian");
  EXPECT_LT(rms(picked), 0.5 * rms(coarse)) << rms(coarse);

  const auto validated = FillHoles(m, p);
  ASSERT_EQ(validated.holes.size(), 1u);
  const auto& r = validated.holes[0];
  EXPECT_EQ(r.kind, "tri-laplacian") << Validation(r);
  EXPECT_EQ(std::count(r.choice.validation.candidates.begin(), r.choice.validation.candidates.end(),
                       "tri-laplacian"),
            1);
  // Off: neither a candidate nor a variation.
  p.tri_laplacian = false;
  const auto off = FillHoles(holed, p);
  EXPECT_EQ(std::count(off.holes[0].choice.validation.candidates.begin(),
                       off.holes[0].choice.validation.candidates.end(), "tri-laplacian"),
            0);
  EXPECT_EQ(std::count(off.holes[0].choice.kinds.begin(), off.holes[0].choice.kinds.end(),
                       "tri-laplacian"),
            0);
}

// rocker_arm_603 of the benchmark's tuning half: a near-flat stretch of the rocker arm among
// its fillets. Its fake holes, cut on the fillets, rewarded the tri-Laplacian for bending the
// fill, which bent the real hole's fill 8 times further from the part than CGAL's cap; the
// smooth coarse fill, kept because the hole's surroundings are far flatter, is the closer one.
TEST(FakeHoles, TheRockerArmsFlatStretchKeepsTheSmoothFillItsFakeHolesWouldBend) {
  CMeshO truth;
  curvature_inpaint::LoadMesh(std::string(CI_SHARED_MESHES) + "/rocker_arm.ply", truth);
  vcg::tri::UpdateBounding<CMeshO>::Box(truth);
  const double diagonal = truth.bbox.Diag();
  double rms[2] = {0, 0};
  for (int gated = 1; gated >= 0; --gated) {
    CMeshO m;
    curvature_inpaint::CopyMesh(truth, m);
    vcg_ext::PunchHole(m, m.vert[2700].cP(), Scalarm(0.05 * diagonal));
    vcg::tri::UpdateBounding<CMeshO>::Box(m);
    const size_t scan_vertices = m.vert.size();
    HoleFillParams p;
    if (!gated) p.validation.max_flatter = 0;
    const auto result = FillHoles(m, p);
    ASSERT_EQ(result.holes.size(), 1u);
    const auto& r = result.holes[0];
    const std::string described = Validation(r);
    ASSERT_FALSE(r.choice.validation.candidates.empty()) << described;
    const bool kept = r.choice.validation.note.find("times flatter") != std::string::npos;
    EXPECT_EQ(kept, bool(gated)) << described;
    EXPECT_EQ(r.choice.validation.candidates[size_t(r.choice.validation.chosen)],
              gated ? "coarse" : "tri-laplacian")
        << described;
    double sum = 0;
    const std::vector<double> errors = FillErrors(truth, m, scan_vertices, diagonal);
    for (double e : errors) sum += e * e;
    rms[gated] = std::sqrt(sum / double(std::max<size_t>(errors.size(), 1)));
  }
  EXPECT_LT(rms[1], 0.5 * rms[0]) << "kept smooth " << rms[1] << ", bent " << rms[0];
}

} // namespace
