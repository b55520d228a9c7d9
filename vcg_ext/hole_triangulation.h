// Stage 2a: the initial triangulation of one hole loop.
//
// Small loops get Liepa's minimum-weight triangulation (Liepa 2003, after Barequet & Sharir):
// the dynamic programme over all triangulations of the polygon that minimises, in
// lexicographic order, the worst dihedral angle to the neighbouring triangles and then the
// total area. It is O(n^3) in time and O(n^2) in memory, so loops longer than
// `dp_max_edges` are closed by vcglib's ear cutting instead (vcg::tri::Hole with
// MinimumWeightEar, O(n log n)), which never hangs on loops of thousands of edges.
#pragma once

#include "hole_patch.h"

#include <vcg/complex/algorithms/hole.h>
#include <vcg/complex/complex.h>

#include <cmath>
#include <limits>
#include <string>
#include <mutex>
#include <vector>

namespace vcg_ext {

struct HoleTriangulationParams {
  /// Loops with at most this many edges use the O(n^3) dynamic programme.
  int dp_max_edges = 200;
};

struct HoleTriangulation {
  std::vector<std::array<int, 3>> triangles; ///< loop indices, oriented like the mesh
  std::string method;                        ///< "liepa-dp" or "vcg-ears"
  bool complete = false;                     ///< n-2 triangles closing the loop
};

namespace detail {

/// Liepa's weight of a (partial) triangulation, compared lexicographically: the worst
/// dihedral angle first, then the area. The angle is kept as its cosine (no acos in the
/// O(n^3) loop): a larger cosine is a smaller angle.
struct DpWeight {
  double cos_worst = 1; ///< cosine of the largest dihedral angle
  double area = 0;
  bool BetterThan(const DpWeight& o) const {
    return cos_worst != o.cos_worst ? cos_worst > o.cos_worst : area < o.area;
  }
  static DpWeight Impossible() {
    return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  }
  bool IsImpossible() const { return std::isinf(cos_worst); }
};

inline HoleTriangulation LiepaTriangulation(const std::vector<Eigen::Vector3d>& p,
                                            const std::vector<Eigen::Vector3d>& side_normals,
                                            const std::set<LocalEdge>& forbidden) {
  const int n = int(p.size());
  HoleTriangulation out;
  out.method = "liepa-dp";
  std::vector<DpWeight> w(size_t(n) * n);
  std::vector<int> best(size_t(n) * n, -1);
  std::vector<Eigen::Vector3d> top_normal(size_t(n) * n, Eigen::Vector3d::Zero());
  auto W = [&](int i, int j) -> DpWeight& { return w[size_t(i) * n + j]; };
  auto L = [&](int i, int j) -> int& { return best[size_t(i) * n + j]; };
  // The unit normal across edge (a,b), a<b, of the sub-polygon a..b: the mesh face beside a
  // loop edge, else the top triangle of the best sub-triangulation.
  auto across = [&](int a, int b) -> const Eigen::Vector3d& {
    return b == a + 1 ? side_normals[a] : top_normal[size_t(a) * n + b];
  };
  auto cosine = [](const Eigen::Vector3d& unit_a, const Eigen::Vector3d& b, double b_norm) {
    // A degenerate triangle on either side counts as a fold.
    return b_norm > 0 && unit_a.squaredNorm() > 0 ? unit_a.dot(b) / b_norm : -1.0;
  };

  for (int len = 2; len < n; ++len) {
    for (int i = 0; i + len < n; ++i) {
      const int j = i + len;
      const bool chord = !(i == 0 && j == n - 1);
      if (chord && forbidden.count(MakeLocalEdge(i, j))) {
        W(i, j) = DpWeight::Impossible();
        continue;
      }
      DpWeight best_w = DpWeight::Impossible();
      int best_k = -1;
      Eigen::Vector3d best_n = Eigen::Vector3d::Zero();
      for (int k = i + 1; k < j; ++k) {
        const DpWeight& a = W(i, k);
        const DpWeight& b = W(k, j);
        if ((k > i + 1 && a.IsImpossible()) || (j > k + 1 && b.IsImpossible())) continue;
        // Bound: the sub-triangulations alone are already no better than the best candidate
        // (the new triangle can only lower the cosine and add area).
        if (best_k >= 0) {
          const double sub_cos = std::min(a.cos_worst, b.cos_worst);
          if (sub_cos < best_w.cos_worst ||
              (sub_cos <= best_w.cos_worst && a.area + b.area >= best_w.area))
            continue;
        }
        // The fill triangle over chord (i,j) with apex k is the face (i, j, k): the loop runs
        // i -> i+1 in the neighbouring faces, so the fill must run the other way.
        const Eigen::Vector3d nt = TriangleNormal(p[i], p[j], p[k]);
        const double len_nt = nt.norm();
        double c = std::min(cosine(across(i, k), nt, len_nt), cosine(across(k, j), nt, len_nt));
        if (!chord) c = std::min(c, cosine(side_normals[n - 1], nt, len_nt));
        const DpWeight cand{std::min({c, a.cos_worst, b.cos_worst}),
                            a.area + b.area + 0.5 * len_nt};
        if (best_k < 0 || cand.BetterThan(best_w)) {
          best_w = cand;
          best_k = k;
          best_n = len_nt > 0 ? Eigen::Vector3d(nt / len_nt) : Eigen::Vector3d::Zero();
        }
      }
      W(i, j) = best_k < 0 ? DpWeight::Impossible() : best_w;
      L(i, j) = best_k;
      top_normal[size_t(i) * n + j] = best_n;
    }
  }
  if (L(0, n - 1) < 0 || W(0, n - 1).IsImpossible()) return out;
  std::vector<std::pair<int, int>> todo{{0, n - 1}};
  while (!todo.empty()) {
    const int i = todo.back().first, j = todo.back().second;
    todo.pop_back();
    const int k = L(i, j);
    out.triangles.push_back({i, j, k});
    if (k > i + 1) todo.emplace_back(i, k);
    if (j > k + 1) todo.emplace_back(k, j);
  }
  out.complete = int(out.triangles.size()) == n - 2;
  return out;
}

// vcglib's ear cutting needs a mesh with face-face adjacency around the loop. It runs on a
// private annulus instead of the caller's mesh: one triangle per loop edge carrying the normal
// of the real face beside it (that is all MinimumWeightEar looks at), joined by connector
// triangles. The annulus is manifold even where the real mesh is pinched.
class EarVertex;
class EarFace;
struct EarTypes
    : public vcg::UsedTypes<vcg::Use<EarVertex>::AsVertexType, vcg::Use<EarFace>::AsFaceType> {};
class EarVertex : public vcg::Vertex<EarTypes, vcg::vertex::Coord3d, vcg::vertex::Normal3d,
                                     vcg::vertex::BitFlags> {};
class EarFace : public vcg::Face<EarTypes, vcg::face::VertexRef, vcg::face::Normal3d,
                                 vcg::face::FFAdj, vcg::face::BitFlags> {};
class EarMesh : public vcg::tri::TriMesh<std::vector<EarVertex>, std::vector<EarFace>> {};

inline HoleTriangulation VcgEarTriangulation(const std::vector<Eigen::Vector3d>& p,
                                             const std::vector<Eigen::Vector3d>& side_normals,
                                             const std::vector<Eigen::Vector3d>& vertex_normals) {
  using vcg::Point3d;
  const int n = int(p.size());
  HoleTriangulation out;
  out.method = "vcg-ears";
  auto P = [](const Eigen::Vector3d& e) { return Point3d(e.x(), e.y(), e.z()); };

  EarMesh m;
  m.vert.reserve(2 * n);
  m.face.reserve(3 * n); // annulus (2n) + fill (n-2): no reallocation under vcg's Pos
  auto vi = vcg::tri::Allocator<EarMesh>::AddVertices(m, 2 * n);
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    const Eigen::Vector3d e = p[j] - p[i];
    // Outer apex of the triangle (i, j, o): its normal is +side_normals[i] by construction.
    const Eigen::Vector3d o = 0.5 * (p[i] + p[j]) + 0.5 * side_normals[i].cross(e);
    (vi + i)->P() = P(p[i]);
    (vi + i)->N() = P(vertex_normals[i]);
    (vi + n + i)->P() = P(o);
    (vi + n + i)->N() = P(side_normals[i]);
  }
  auto fi = vcg::tri::Allocator<EarMesh>::AddFaces(m, 2 * n);
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    EarFace& t = *(fi + i);
    t.V(0) = &m.vert[i];
    t.V(1) = &m.vert[j];
    t.V(2) = &m.vert[n + i];
    t.N() = P(side_normals[i]);
    EarFace& c = *(fi + n + i);
    c.V(0) = &m.vert[n + i];
    c.V(1) = &m.vert[j];
    c.V(2) = &m.vert[n + j];
    c.N() = P((side_normals[i] + side_normals[j]).normalized()); // never read by the ears
  }
  vcg::tri::UpdateTopology<EarMesh>::FaceFace(m);
  vcg::tri::UpdateFlags<EarMesh>::FaceBorderFromFF(m);

  using Hole = vcg::tri::Hole<EarMesh>;
  typename Hole::PosType start(&m.face[0], 0, m.face[0].V(0));
  std::vector<EarFace**> update{&start.f};
  {
    // vcglib's Hole keeps static state (a flag bit, an adjacency ring): one at a time when
    // holes are filled in parallel.
    static std::mutex vcg_hole_state;
    std::lock_guard<std::mutex> lock(vcg_hole_state);
    Hole::FillHoleEar<vcg::tri::MinimumWeightEar<EarMesh>>(m, start, update);
  }

  for (size_t f = 2 * size_t(n); f < m.face.size(); ++f) {
    if (m.face[f].IsD()) continue;
    std::array<int, 3> t;
    for (int k = 0; k < 3; ++k) t[k] = int(vcg::tri::Index(m, m.face[f].V(k)));
    if (t[0] >= n || t[1] >= n || t[2] >= n) return out; // walked off the loop: refuse
    out.triangles.push_back(t);
  }
  out.complete = int(out.triangles.size()) == n - 2;
  return out;
}

} // namespace detail

/// Triangulates a simple hole loop.
///
/// `points` are the loop's vertices in loop order (each i -> i+1 an edge of the face beside
/// it), `side_normals[i]` the unit normal of that face, `vertex_normals` the loop vertices'
/// normals, and `forbidden` the chords that already are mesh edges. Returns triangles over
/// loop indices with `complete` false when no valid triangulation was found (the hole should
/// then stay open). Precondition: at least three points.
inline HoleTriangulation TriangulateHole(const std::vector<Eigen::Vector3d>& points,
                                         const std::vector<Eigen::Vector3d>& side_normals,
                                         const std::vector<Eigen::Vector3d>& vertex_normals,
                                         const std::set<LocalEdge>& forbidden,
                                         const HoleTriangulationParams& params = {}) {
  if (points.size() < 3) return {};
  if (int(points.size()) <= params.dp_max_edges)
    return detail::LiepaTriangulation(points, side_normals, forbidden);
  return detail::VcgEarTriangulation(points, side_normals, vertex_normals);
}

} // namespace vcg_ext
