// The whole method on MeshLab's mesh type (pipeline/hole_fill.h): the ground-truth oracle through
// the chain, the detail amplitude, the report, cancelling, flat caps.
#include "hole_fill_fixtures.h"
#include "silent_server.h"

#include <atomic>
#include <set>
#include <thread>

namespace {

using namespace fixtures;

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
    ASSERT_EQ(holes[0].choice.kinds[0], curvature_inpaint::FillKind::kContinuation);
    ASSERT_EQ(holes[0].choice.kinds[1], curvature_inpaint::FillKind::kContinuation);
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
  r.choice.kinds = {curvature_inpaint::FillKind::kContinuation,
                    curvature_inpaint::FillKind::kContinuation};
  r.choice.pick = 2;
  r.choice.validation.candidates = {{curvature_inpaint::FillKind::kCoarse},
                                    {curvature_inpaint::FillKind::kTriLaplacian}};
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
  r.choice.kinds = {curvature_inpaint::FillKind::kSymmetrySurface};
  r.kind = r.choice.kinds[0];
  r.choice.validation.note = note;
  r.choice.priors.no_creases = note;
  r.choice.problem = note;
  result.holes.push_back(r);
  const QJsonObject hole = FirstHoleOfReport(result);
  EXPECT_EQ(hole["validation"].toObject()["note"].toString().toStdString(), note);
  EXPECT_EQ(hole["no_creases"].toString().toStdString(), note);
  EXPECT_EQ(hole["problem"].toString().toStdString(), note);
  EXPECT_EQ(hole["kind"].toString().toStdString(), "symmetry surface");
  EXPECT_EQ(hole["kinds"].toArray()[0].toString().toStdString(), "symmetry surface");
}

std::thread::id g_caller;
std::atomic<int> g_callbacks{0}, g_callbacks_elsewhere{0};

/// Fills `m` (or previews a fill of a copy) with `cb` as MeshLab's callback: "stopped" where
/// it came out as a stop, else what went wrong ("" where it ran to the end).
std::string RunWithCallback(CMeshO& m, const HoleFillParams& p, bool preview,
                            vcg::CallBackPos* cb) {
  CMeshO scratch;
  curvature_inpaint::CopyMesh(m, scratch);
  try {
    if (preview)
      curvature_inpaint::InpaintHoles(scratch, p, cb);
    else
      FillHoles(m, p, cb);
  } catch (const vcg_ext::CancelledError&) {
    return "stopped";
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

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
  p.inpaint.backend = curvature_inpaint::Backend::kComfyUi;
  p.inpaint.urls = {a.Url(), b.Url()}; // both holes in flight at once, one on another thread
  p.inpaint.http.max_retries = 0;
  g_caller = std::this_thread::get_id();
  for (bool preview : {false, true}) {
    g_callbacks = 0;
    g_callbacks_elsewhere = 0;
    // A stop is no failure of the servers: it comes out as the stop it is, and the pool does
    // not move on to the next server ("every one of the 2 servers failed").
    EXPECT_EQ(RunWithCallback(m, p, preview, StopAfterAFewCalls), "stopped") << preview;
    EXPECT_GE(g_callbacks, 20) << preview;
    EXPECT_EQ(g_callbacks_elsewhere, 0) << preview;
  }
  ASSERT_EQ(m.vert.size(), before.size());
  for (size_t i = 0; i < before.size(); ++i) ASSERT_EQ(m.vert[i].cP(), before[i]) << i;
}

/// MeshLab's callback: asks to stop the first time it is asked while the only hole is being
/// filled (no hole done yet: only the hole's own path asks then), and counts those calls.
std::atomic<int> g_within_the_hole{0};
bool StopWithinTheHole(int, const char* what) {
  if (std::this_thread::get_id() != g_caller) ++g_callbacks_elsewhere;
  const std::string message = what;
  if (message != "Curvature Inpaint: hole 0 of 1" &&
      message != "Curvature Inpaint: inpainted hole 0 of 1")
    return true;
  ++g_within_the_hole;
  return false;
}

// A big hole's validation takes seconds: a stop asked while it runs is heard between two
// candidates' fills, not once the hole is done, on every thread its fake holes run on, and
// the mesh is left as it was.
TEST(Cancel, AStopAskedWhileAHoleIsValidatedIsHeardBeforeTheHoleIsDone) {
  CMeshO m;
  MakeBumpySphere(m);
  PunchThreeBumps(m);
  std::vector<Point3m> before;
  for (const auto& v : m.vert) before.push_back(v.cP());
  const size_t faces = m.face.size();
  g_caller = std::this_thread::get_id();
  for (bool preview : {false, true}) {
    g_within_the_hole = 0;
    g_callbacks_elsewhere = 0;
    HoleFillParams p = SmallImages();
    p.images.coarse.threads = 2; // the fake holes on two threads
    EXPECT_EQ(RunWithCallback(m, p, preview, StopWithinTheHole), "stopped") << preview;
    // Asked once: the stop it answered reached the fake holes on the other thread without
    // asking again.
    EXPECT_EQ(g_within_the_hole, 1) << preview;
    EXPECT_EQ(g_callbacks_elsewhere, 0) << preview;
  }
  ASSERT_EQ(m.vert.size(), before.size());
  ASSERT_EQ(m.face.size(), faces);
  for (size_t i = 0; i < before.size(); ++i) ASSERT_EQ(m.vert[i].cP(), before[i]) << i;
}

// Without detail the embedded inpainter's continuations are the one smooth continuation: a
// preview (and a fill without fake holes, which scores them all) paints and scores it once and
// shares it; with detail each is a picture of its own.
TEST(Variations, ContinuationsWithoutDetailAreOnePicturePaintedOnce) {
  CMeshO m;
  MakeBumpySphere(m);
  PunchThreeBumps(m);
  for (double detail : {0.0, 1.0}) {
    CMeshO scratch;
    curvature_inpaint::CopyMesh(m, scratch);
    HoleFillParams p = SmallImages();
    p.validation.fake_holes = 0;
    p.inpaint.variations = 4;
    p.inpaint.detail = detail;
    const auto holes = curvature_inpaint::InpaintHoles(scratch, p);
    ASSERT_EQ(holes.size(), 1u);
    const auto& v = holes[0].variations;
    ASSERT_GE(v.size(), 4u);
    std::set<qint64> pictures;
    for (size_t j = 0; j < 4; ++j) {
      EXPECT_EQ(holes[0].choice.kinds[j], curvature_inpaint::FillKind::kContinuation);
      pictures.insert(v[j].cacheKey());
    }
    EXPECT_EQ(pictures.size(), detail > 0 ? 4u : 1u) << detail;
    if (detail == 0)
      for (size_t j = 1; j < 4; ++j)
        EXPECT_EQ(holes[0].choice.scores[j], holes[0].choice.scores[0]);
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

} // namespace
