#include "validation/fake_holes.h"

#include "pipeline/pipeline.h"

#include <vcg_ext/edge_census.h>
#include <vcg_ext/hole_loops.h>
#include <vcg_ext/punch_hole.h>
#include <vcg_ext/unit_box.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <unordered_map>
#include <unordered_set>

namespace curvature_inpaint {

namespace {

/// Squared distance from p to triangle abc (Ericson, Real-Time Collision Detection, 5.1.5).
double PointTriangleDistance2(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                              const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.squaredNorm();
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.squaredNorm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).squaredNorm();
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.squaredNorm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).squaredNorm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
    return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).squaredNorm();
  const double denom = 1 / (va + vb + vc);
  return (p - (a + ab * (vb * denom) + ac * (vc * denom))).squaredNorm();
}

using Triangles = std::vector<std::array<Eigen::Vector3d, 3>>;

} // namespace

namespace detail {

/// Triangles bucketed on a uniform grid of cells as large as the longest edge, for nearest
/// queries from points close to them (a fill against the surface it replaces).
class TriangleGrid {
public:
  explicit TriangleGrid(const Triangles& tris)
      : tris_(tris), boxes_(tris.size()), seen_(tris.size(), 0) {
    for (const auto& t : tris)
      for (int k = 0; k < 3; ++k) cell_ = std::max(cell_, (t[k] - t[(k + 1) % 3]).norm());
    if (!(cell_ > 0)) cell_ = 1;
    for (size_t i = 0; i < tris.size(); ++i) {
      Eigen::Vector3d lo = tris[i][0], hi = tris[i][0];
      for (int k = 1; k < 3; ++k) lo = lo.cwiseMin(tris[i][k]), hi = hi.cwiseMax(tris[i][k]);
      boxes_[i] = {lo, hi};
      const auto a = Cell(lo), b = Cell(hi);
      for (int64_t x = a[0]; x <= b[0]; ++x)
        for (int64_t y = a[1]; y <= b[1]; ++y)
          for (int64_t z = a[2]; z <= b[2]; ++z) cells_[Key({x, y, z})].push_back(int(i));
    }
  }

  /// Squared distance from p to the nearest triangle; rings of cells grow until one is found
  /// and one more ring has been searched. Not thread-safe (it marks the triangles it visits).
  double Distance2(const Eigen::Vector3d& p) {
    const auto c = Cell(p);
    ++query_;
    double best = std::numeric_limits<double>::max();
    for (int ring = 0, found = -1; ring < 64 && (found < 0 || ring <= found + 1); ++ring) {
      for (int64_t x = c[0] - ring; x <= c[0] + ring; ++x)
        for (int64_t y = c[1] - ring; y <= c[1] + ring; ++y)
          for (int64_t z = c[2] - ring; z <= c[2] + ring; ++z) {
            if (std::max({std::abs(x - c[0]), std::abs(y - c[1]), std::abs(z - c[2])}) != ring)
              continue; // inner cells were searched by the smaller rings
            const auto it = cells_.find(Key({x, y, z}));
            if (it == cells_.end()) continue;
            for (int i : it->second) {
              // A triangle lies in up to eight cells of a ring: it is measured once. Its
              // bounding box is no farther than it, so one whose box is not nearer than the
              // nearest so far cannot change the minimum.
              if (seen_[size_t(i)] == query_) continue;
              seen_[size_t(i)] = query_;
              const auto& box = boxes_[size_t(i)];
              if ((p - p.cwiseMax(box[0]).cwiseMin(box[1])).squaredNorm() >= best) continue;
              const auto& t = tris_[size_t(i)];
              best = std::min(best, PointTriangleDistance2(p, t[0], t[1], t[2]));
            }
            if (found < 0) found = ring;
          }
    }
    return best;
  }

private:
  std::array<int64_t, 3> Cell(const Eigen::Vector3d& p) const {
    return {int64_t(std::floor(p.x() / cell_)), int64_t(std::floor(p.y() / cell_)),
            int64_t(std::floor(p.z() / cell_))};
  }
  static uint64_t Key(const std::array<int64_t, 3>& c) {
    return (uint64_t(c[0]) * 73856093u) ^ (uint64_t(c[1]) * 19349663u) ^
           (uint64_t(c[2]) * 83492791u);
  }
  const Triangles& tris_;
  std::vector<std::array<Eigen::Vector3d, 2>> boxes_; ///< per triangle: lowest, highest corner
  std::vector<uint32_t> seen_;                        ///< per triangle: the last query to visit it
  uint32_t query_ = 0;
  double cell_ = 0;
  std::unordered_map<uint64_t, std::vector<int>> cells_;
};

} // namespace detail

namespace {

using detail::TriangleGrid;

/// RMS distance from the centres of `from` (at most `samples` of them, evenly strided) to the
/// surface in `to`.
double RmsDistance(const Triangles& from, TriangleGrid& to, size_t samples = 400) {
  if (from.empty()) return 0.0;
  const size_t stride = std::max<size_t>(1, from.size() / samples);
  double sum = 0;
  size_t n = 0;
  for (size_t i = 0; i < from.size(); i += stride, ++n) {
    const auto& t = from[i];
    sum += to.Distance2((t[0] + t[1] + t[2]) / 3);
  }
  return std::sqrt(sum / double(n));
}

Eigen::Vector3d ToEigen(const Point3m& p) {
  return {p[0], p[1], p[2]};
}

/// Whether, of a holed piece's two `loops`, the longer is the piece's border (farther from the
/// fake hole's centre on average): the validation's coarse fill leaves the longest loop open.
/// Where a piece wraps a thin part (an ear, a leg), the hole's loop can be the longer one; its
/// coarse fill would then cap the piece's border and leave the hole open, and every candidate
/// would be scored on that cap, two hole radii away from the surface cut out.
bool HoleIsShorterThanBorder(const CMeshO& holed, const vcg_ext::HoleLoops& loops,
                             const Eigen::Vector3d& centre) {
  double length[2] = {0, 0}, distance[2] = {0, 0};
  for (int l = 0; l < 2; ++l) {
    const std::vector<int>& v = loops.holes[size_t(l)].vertices;
    for (size_t i = 0; i < v.size(); ++i) {
      const Eigen::Vector3d p = ToEigen(holed.vert[size_t(v[i])].cP());
      length[l] += (ToEigen(holed.vert[size_t(v[(i + 1) % v.size()])].cP()) - p).norm();
      distance[l] += (p - centre).norm() / double(v.size());
    }
  }
  const int longer = length[1] > length[0] ? 1 : 0;
  return distance[longer] > distance[1 - longer];
}

/// A loop as a ball: its centroid and the farthest of its vertices.
struct Ball {
  Eigen::Vector3d centre;
  double radius;
};

Ball BallOf(const CMeshO& m, const std::vector<int>& loop) {
  Ball b{Eigen::Vector3d::Zero(), 0};
  for (int v : loop) b.centre += ToEigen(m.vert[v].cP());
  b.centre /= double(loop.size());
  for (int v : loop) b.radius = std::max(b.radius, (ToEigen(m.vert[v].cP()) - b.centre).norm());
  return b;
}

/// Where fake holes of hole `hole` (`real`, radius r) may be cut, in the order they are tried
/// (vertex, at a mirror place): the scan vertices outside its piece and within params.farthest
/// radii, shuffled by the seed; then, at each mirror plane's image of the hole, the scan vertex
/// nearest to it, if one lies within a hole radius (elsewhere the mirror image of the hole is
/// not on the known surface).
std::vector<std::pair<int, bool>> FakeHolePlaces(const CMeshO& m, size_t scan_vertices,
                                                 const Ball& real, double piece, int hole,
                                                 const FakeHoleParams& params) {
  const double r = real.radius;
  std::vector<Eigen::Vector3d> mirror_places;
  for (const auto& plane : params.mirror_planes)
    mirror_places.push_back(plane.Reflect(real.centre));
  std::vector<int> mirror_vertices(mirror_places.size(), -1);
  std::vector<double> mirror_d2(mirror_places.size(), r * r);
  std::vector<int> places;
  for (size_t v = 0; v < scan_vertices; ++v) {
    if (m.vert[v].IsD()) continue;
    const Eigen::Vector3d q = ToEigen(m.vert[v].cP());
    const double d = (q - real.centre).norm();
    if (d > piece + r && d <= params.farthest * r) places.push_back(int(v));
    for (size_t k = 0; k < mirror_places.size(); ++k) {
      const double d2 = (q - mirror_places[k]).squaredNorm();
      if (d2 < mirror_d2[k]) mirror_d2[k] = d2, mirror_vertices[k] = int(v);
    }
  }
  std::mt19937 rng(params.seed * 1000003u + uint32_t(hole));
  std::shuffle(places.begin(), places.end(), rng);
  std::vector<std::pair<int, bool>> tries;
  for (int v : places) tries.emplace_back(v, false);
  for (int v : mirror_vertices)
    if (v >= 0) tries.emplace_back(v, true);
  return tries;
}

/// The piece around scan vertex v (at p): the scan faces with every corner within `piece` of
/// p, grown from p. False where an edge of the mesh's border (an open scan's outer border, a
/// hole left open) lies in it: no place for a fake hole.
bool GrowPiece(const CMeshO& m, const vcg_ext::VertexFaces& vf, size_t scan_faces, int v,
               const Eigen::Vector3d& p, double piece, std::vector<int>* faces) {
  std::vector<int> stack{v};
  std::unordered_set<int> seen_vertex{v}, taken;
  bool on_border = false;
  while (!stack.empty()) {
    const int u = stack.back();
    stack.pop_back();
    vf.ForEach(u, [&](int f) {
      if (size_t(f) >= scan_faces || !taken.insert(f).second) return;
      const auto& face = m.face[f];
      for (int k = 0; k < 3; ++k)
        if ((ToEigen(face.cP(k)) - p).norm() > piece) return;
      for (int k = 0; k < 3; ++k) {
        const int a = int(vcg::tri::Index(m, face.cV(k)));
        const auto* b = face.cV((k + 1) % 3);
        int sharing = 0;
        vf.ForEach(a, [&](int g) {
          for (int j = 0; j < 3; ++j) sharing += m.face[g].cV(j) == b;
        });
        if (sharing < 2) on_border = true;
      }
      faces->push_back(f);
      for (int k = 0; k < 3; ++k) {
        const int w = int(vcg::tri::Index(m, face.cV(k)));
        if (seen_vertex.insert(w).second) stack.push_back(w);
      }
    });
  }
  return !on_border;
}

/// A fake hole of radius r cut at scan vertex v into the piece `faces`; null where the piece
/// is not a disk, or the cut would leave a non-manifold edge or not one hole inside its border.
std::unique_ptr<FakeHole> CutPiece(const CMeshO& m, const std::vector<int>& faces, int v,
                                   double r) {
  std::vector<int> order;
  std::unordered_map<int, int> local;
  for (int f : faces)
    for (int k = 0; k < 3; ++k) {
      const int w = int(vcg::tri::Index(m, m.face[f].cV(k)));
      if (local.emplace(w, int(order.size())).second) order.push_back(w);
    }
  auto made = std::make_unique<FakeHole>();
  FakeHole& fake = *made;
  vcg::tri::Allocator<CMeshO>::AddVertices(fake.truth, order.size());
  for (size_t i = 0; i < order.size(); ++i) fake.truth.vert[i].P() = m.vert[order[i]].cP();
  vcg::tri::Allocator<CMeshO>::AddFaces(fake.truth, faces.size());
  for (size_t i = 0; i < faces.size(); ++i)
    for (int k = 0; k < 3; ++k)
      fake.truth.face[i].V(k) =
          &fake.truth.vert[local[int(vcg::tri::Index(m, m.face[faces[i]].cV(k)))]];
  vcg::tri::UpdateBounding<CMeshO>::Box(fake.truth);
  const HoleCensus piece_census = CountHoles(fake.truth);
  if (piece_census.loop_edges.size() != 1 || piece_census.non_manifold_edges > 0) return nullptr;
  CopyMesh(fake.truth, fake.holed);
  const Point3m centre = m.vert[v].cP();
  vcg_ext::PunchHole(fake.holed, centre, Scalarm(r));
  vcg::tri::UpdateBounding<CMeshO>::Box(fake.holed);
  const vcg_ext::EdgeCensus holed_edges = vcg_ext::CensusEdges(fake.holed);
  if (holed_edges.non_manifold_edges > 0) return nullptr;
  const vcg_ext::HoleLoops holed_loops = vcg_ext::FindHoleLoops(fake.holed, holed_edges);
  if (holed_loops.holes.size() != 2 ||
      !HoleIsShorterThanBorder(fake.holed, holed_loops, ToEigen(centre)))
    return nullptr;
  const vcg_ext::UnitBox box = vcg_ext::ComputeUnitBox(fake.holed);
  for (const auto& f : fake.truth.face) {
    bool inside = false;
    for (int k = 0; k < 3 && !inside; ++k) inside = vcg::Distance(f.cP(k), centre) < Scalarm(r);
    if (inside) fake.cut.push_back({box.ToUnit(f.cP(0)), box.ToUnit(f.cP(1)), box.ToUnit(f.cP(2))});
  }
  for (size_t i = 0; i < fake.truth.vert.size(); ++i)
    if (vcg::Distance(fake.truth.vert[i].cP(), centre) < Scalarm(r))
      fake.cut_vertices.push_back(int(i));
  fake.radius = r * box.scale;
  fake.centre = ToEigen(centre);
  return made;
}

} // namespace

std::vector<std::unique_ptr<FakeHole>> CutFakeHoles(const CMeshO& m, const vcg_ext::VertexFaces& vf,
                                                    const vcg_ext::CoarseFillResult& coarse,
                                                    int hole, const FakeHoleParams& params,
                                                    std::string* why) {
  std::vector<std::unique_ptr<FakeHole>> fakes;
  const auto& loop = coarse.holes[size_t(hole)].loop;
  if (loop.empty() || params.count <= 0) return fakes;
  const ScanPart scan = ScanPartOf(m, coarse);
  std::vector<Ball> holes;
  for (const auto& h : coarse.holes)
    if (!h.loop.empty()) holes.push_back(BallOf(m, h.loop));
  const Ball real = BallOf(m, loop);
  const double r = real.radius, piece = params.piece * r;
  if (!(r > 0)) return fakes;

  int attempts = 0, near = 0;
  for (const auto& place : FakeHolePlaces(m, scan.vertices, real, piece, hole, params)) {
    const int v = place.first;
    const bool at_mirror = place.second;
    if (!at_mirror && (near == params.count || attempts == params.max_attempts)) continue;
    const Eigen::Vector3d p = ToEigen(m.vert[v].cP());
    bool apart = true;
    for (const auto& b : holes) apart = apart && (p - b.centre).norm() > piece + b.radius;
    // The one at a mirror place may overlap those near the hole (each is filled on its own
    // copy of its piece), so that it takes no room from them.
    for (const auto& f : fakes)
      if (f->at_mirror_place == at_mirror) apart = apart && (p - f->centre).norm() > 2 * piece;
    if (!apart) continue;
    if (!at_mirror) ++attempts;
    std::vector<int> faces;
    if (!GrowPiece(m, vf, scan.faces, v, p, piece, &faces) || faces.size() < 50) continue;
    std::unique_ptr<FakeHole> fake = CutPiece(m, faces, v, r);
    if (!fake) continue;
    fake->at_mirror_place = at_mirror;
    near += !at_mirror;
    fakes.push_back(std::move(fake));
  }
  // A fake hole at the mirror place cannot validate the mirror image (its own is the real
  // hole): alone, it would judge the symmetry prior by the other candidates.
  if (near == 0) fakes.clear();
  if (why && near < params.count)
    *why = near == 0 ? "no room for fake holes of its size on the known surface near it"
                     : "room for " + std::to_string(near) + " fake hole" + (near == 1 ? "" : "s") +
                           " near it only";
  return fakes;
}

FakeHoleScorer::FakeHoleScorer(const FakeHole& fake) : fake_(fake) {
  if (!fake.cut.empty()) cut_ = std::make_unique<detail::TriangleGrid>(fake.cut);
}

FakeHoleScorer::~FakeHoleScorer() = default;

double FakeHoleScorer::Error(const std::vector<Eigen::Vector3d>& points,
                             const std::vector<std::array<int, 3>>& triangles) {
  // A fill that went off to infinity is the worst candidate (and would not fit a grid).
  for (const auto& p : points)
    if (!p.allFinite()) return std::numeric_limits<double>::infinity();
  Triangles fill;
  for (const auto& t : triangles) fill.push_back({points[t[0]], points[t[1]], points[t[2]]});
  if (fill.empty() || !cut_) return std::numeric_limits<double>::infinity();
  TriangleGrid fill_grid(fill);
  return 0.5 * (RmsDistance(fill, *cut_) + RmsDistance(fake_.cut, fill_grid));
}

double FakeHoleError(const FakeHole& fake, const std::vector<Eigen::Vector3d>& points,
                     const std::vector<std::array<int, 3>>& triangles) {
  return FakeHoleScorer(fake).Error(points, triangles);
}

} // namespace curvature_inpaint
