// The ways to fill a patch (candidates/): one kind each, and the mirror image, the creases and the
// tri-Laplacian fill through the whole method.
#include "candidates/fill_candidate.h"
#include "hole_fill_fixtures.h"
#include "report/hole_words.h"
#include "symmetric_egg.h"

#include <map>
#include <random>
#include <set>

namespace {

using namespace fixtures;

using curvature_inpaint::FillCandidate;
using curvature_inpaint::FillCandidates;
using curvature_inpaint::FillKind;
using curvature_inpaint::FillKindName;

TEST(FillCandidates, EveryKindHasANameOfItsOwnAndWordsForALog) {
  std::set<std::string> names;
  for (int k = int(FillKind::kCoarse); k <= int(FillKind::kFace); ++k) {
    const std::string name = FillKindName(FillKind(k));
    EXPECT_TRUE(names.insert(name).second) << name << " names two kinds";
    EXPECT_NE(curvature_inpaint::KindInWords(FillKind(k)), name) << name << " has no words";
    // --pick reads a variation's kind back from its name.
    FillKind read = FillKind::kCoarse;
    EXPECT_EQ(curvature_inpaint::VariationKindNamed(name, &read), FillKind(k) != FillKind::kCoarse)
        << name;
    if (FillKind(k) != FillKind::kCoarse) EXPECT_EQ(read, FillKind(k));
  }
  const std::vector<FillKind> variations = curvature_inpaint::VariationKinds();
  EXPECT_EQ(variations.size(), names.size() - 1);
  EXPECT_EQ(std::count(variations.begin(), variations.end(), FillKind::kCoarse), 0);
}

TEST(FillCandidates, EachKindComesFromOneCandidateAndOnlyTheCoarseFillIsNoVariation) {
  // Without a patch the crease prior names its "creases"; inside one face it is "face".
  const curvature_inpaint::PatchWork none;
  std::map<FillKind, int> offered;
  for (const FillCandidate* c : FillCandidates()) {
    ++offered[c->KindAt(none)];
    EXPECT_EQ(c->IsVariation(), c->KindAt(none) != FillKind::kCoarse);
  }
  for (FillKind kind : curvature_inpaint::VariationKinds())
    if (kind != FillKind::kFace) EXPECT_EQ(offered[kind], 1) << FillKindName(kind);
  EXPECT_EQ(offered[FillKind::kCoarse], 1);
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
  EXPECT_TRUE(r.kind == FillKind::kSymmetry || r.kind == FillKind::kSymmetrySurface)
      << "chose " << FillKindName(r.kind) << ": " << Validation(r);
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
    EXPECT_EQ(TriedOfKind(r.choice.validation, FillKind::kSymmetry), 0);
    EXPECT_EQ(r.choice.validation.mirror_fake_holes, 0) << "the mirror place is the other hole";
    EXPECT_LT(r.choice.priors.mirror_covered, 0) << "its mirror image is in the other hole";
    if (r.choice.problem.empty())
      EXPECT_TRUE(r.kind == FillKind::kContinuation || r.kind == FillKind::kTriLaplacian);
  }
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

/// Fills the one hole punched in `m` as FillWithoutSymmetry does; whether the crease prior's
/// variation filled it (a failure recorded where not).
bool FillsOneHoleWithCreases(CMeshO& m, FillKind pick_kind = FillKind::kCoarse) {
  const auto result = FillWithoutSymmetry(m, pick_kind);
  if (result.holes.size() != 1) {
    ADD_FAILURE() << result.holes.size() << " holes";
    return false;
  }
  const auto& r = result.holes[0];
  if (!r.choice.problem.empty() || r.kind != FillKind::kCreases) {
    ADD_FAILURE() << "filled as " << FillKindName(r.kind) << ": " << r.choice.problem << "; "
                  << r.choice.priors.no_creases << "; " << Validation(r);
    return false;
  }
  return true;
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
  p.pick_kind = FillKind::kCreases;
  p.validation.fake_holes = 0;
  const auto result = FillHoles(m, p);
  EXPECT_EQ(result.holes.size(), 1u);
  if (result.holes.size() != 1 || result.holes[0].kind != FillKind::kCreases) {
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
    EXPECT_EQ(r.kind, FillKind::kCreases) << Validation(r);
    EXPECT_TRUE(r.choice.priors.has_creases);
    EXPECT_GT(r.crease_flips, 0);
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

/// The largest |distance(p)| over the fill's vertices (those from `first` on).
template <class Distance>
double WorstFillDistance(const CMeshO& m, size_t first, Distance distance) {
  double worst = 0;
  for (size_t v = first; v < m.vert.size(); ++v)
    worst = std::max(worst, std::abs(double(distance(m.vert[v].cP()))));
  return worst;
}

// A hole on a plate's corner takes the whole vertical edge there, top to bottom: no crease edge
// of the two side faces is left beside it, yet they must meet at that edge, not run on through
// each other.
// On an organic surface (a scan's noise on a sphere) a fill's bends are no creases: flipping
// its edges onto them would carve ridges into it. No crease runs into these holes, so none of
// their fills' edges is flipped, whatever the fill.
TEST(Creases, AFillOnAnOrganicSurfaceIsNeverFlippedOntoCreases) {
  CMeshO m;
  vcg::tri::Sphere(m, 5);
  std::mt19937 noise(7);
  std::uniform_real_distribution<double> radius(0.997, 1.003);
  for (auto& v : m.vert) v.P() *= Scalarm(radius(noise));
  for (const Point3m at : {Point3m(1, 0, 0), Point3m(0, 1, 0), Point3m(0, 0, -1)})
    vcg_ext::PunchHole(m, at, Scalarm(0.3));
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
  HoleFillParams p = SmallImages();
  p.validation.fake_holes = 0;
  for (FillKind kind : {FillKind::kContinuation, FillKind::kTriLaplacian}) {
    CMeshO filled;
    curvature_inpaint::CopyMesh(m, filled);
    p.pick_kind = kind;
    p.inpaint.detail = 2; // the boldest bends the continuation makes
    const auto result = FillHoles(filled, p);
    ASSERT_EQ(result.holes.size(), 3u);
    for (const auto& r : result.holes) {
      EXPECT_EQ(r.kind, kind);
      EXPECT_FALSE(r.choice.priors.has_creases) << r.choice.priors.no_creases;
      EXPECT_EQ(r.crease_flips, 0) << FillKindName(kind);
    }
  }
}

TEST(Creases, AHoleThatTakesAPlatesWholeCornerEdgeBringsItBack) {
  CMeshO m;
  MakeCube(m, 24);
  const Scalarm half_thickness = Scalarm(0.25);
  for (auto& v : m.vert) v.P()[2] *= half_thickness;
  vcg_ext::PunchHole(m, Point3m(1, 1, 0), Scalarm(0.4));
  const size_t scan_vertices = m.vert.size();
  ASSERT_TRUE(FillsOneHoleWithCreases(m));
  const double worst = WorstFillDistance(m, scan_vertices, [&](const Point3m& p) {
    return BoxDistance(p, Eigen::Vector3d(1, 1, half_thickness));
  });
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
  const double worst = WorstFillDistance(
      m, scan_vertices, [](const Point3m& p) { return double(p[2]) - StepHeight(double(p[0])); });
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
  ASSERT_TRUE(FillsOneHoleWithCreases(m, FillKind::kCreases));
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
  ASSERT_TRUE(FillsOneHoleWithCreases(m, FillKind::kCreases));
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
    p.pick_kind = FillKind::kFace;
    p.crease_fill.face_without_crease = face;
    const auto result = FillHoles(m, p);
    ASSERT_EQ(result.holes.size(), 1u);
    const auto& r = result.holes[0];
    if (!face) {
      EXPECT_EQ(r.choice.priors.no_creases, "no crease runs into it");
      EXPECT_NE(r.kind, FillKind::kFace);
      continue;
    }
    ASSERT_TRUE(r.choice.problem.empty()) << r.choice.problem;
    EXPECT_EQ(r.kind, FillKind::kFace) << r.choice.priors.no_creases;
    ASSERT_GT(m.vert.size(), scan_vertices);
    for (size_t v = scan_vertices; v < m.vert.size(); ++v)
      EXPECT_NEAR(std::hypot(m.vert[v].cP()[0], m.vert[v].cP()[1]), 1, 0.005) << v;
  }
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
  pick.pick_kind = FillKind::kTriLaplacian;
  const auto direct = FillHoles(picked, pick);
  ASSERT_EQ(direct.holes.size(), 1u);
  EXPECT_EQ(direct.holes[0].kind, FillKind::kTriLaplacian);
  EXPECT_LT(rms(picked), 0.5 * rms(coarse)) << rms(coarse);

  const auto validated = FillHoles(m, p);
  ASSERT_EQ(validated.holes.size(), 1u);
  const auto& r = validated.holes[0];
  EXPECT_EQ(r.kind, FillKind::kTriLaplacian) << Validation(r);
  EXPECT_EQ(TriedOfKind(r.choice.validation, FillKind::kTriLaplacian), 1);
  // Off: neither a candidate nor a variation.
  p.tri_laplacian = false;
  const auto off = FillHoles(holed, p);
  EXPECT_EQ(TriedOfKind(off.holes[0].choice.validation, FillKind::kTriLaplacian), 0);
  EXPECT_EQ(std::count(off.holes[0].choice.kinds.begin(), off.holes[0].choice.kinds.end(),
                       FillKind::kTriLaplacian),
            0);
}

} // namespace
