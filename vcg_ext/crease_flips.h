// Edge flips that lay a fill's triangles along its creases. A fill whose vertices sit on the
// faces of a machined part, and on the lines where they meet, still cuts a crease off wherever
// one of its edges joins two faces across it: the two triangles of that edge form a chamfer,
// as deep as a fraction of an edge length, which is what a crease fill's Hausdorff distance
// to the part is made of. The other diagonal of their quad runs along the crease. Of the two,
// the one with less total bending over the quad's five edges (the sum of their absolute
// dihedral angles) is kept: bending that a chamfer spreads over three edges, the crease puts
// on one, so the L1 measure prefers the crease, while on a smooth surface the two diagonals
// bend alike and nothing flips.
#pragma once

#include <vcg/complex/complex.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace vcg_ext {

struct CreaseFlipParams {
  /// A flip must lower the quad's total bending by this much (degrees): the diagonals of a
  /// smooth, slightly bent quad differ by rounding, and flipping those would only churn.
  double min_gain = 5;
  /// Neither triangle of a flip may have an angle below this (degrees): a sliver's normal is
  /// noise.
  double min_angle = 5;
  int max_rounds = 10; ///< passes over the fill's edges
};

namespace detail {

template <class Coord>
Coord UnitNormal(const Coord& a, const Coord& b, const Coord& c) {
  Coord n = (b - a) ^ (c - a);
  const auto length = n.Norm();
  return length > 0 ? n / length : Coord(0, 0, 0);
}

/// The angle between two unit normals, degrees.
template <class Coord>
double BendDegrees(const Coord& n, const Coord& m) {
  return vcg::math::ToDeg(double(vcg::AngleN(n, m)));
}

/// The smallest angle of triangle abc, degrees (below 0 where an edge has no length).
template <class Coord>
double SmallestAngleDegrees(const Coord& a, const Coord& b, const Coord& c) {
  return vcg::math::ToDeg(double(
      std::min({vcg::Angle(b - a, c - a), vcg::Angle(c - b, a - b), vcg::Angle(a - c, b - c)})));
}

} // namespace detail

/// Flips edges between the faces `fill` of `m` (the fills of holes, their vertices in place)
/// where the other diagonal of their quad bends the surface less in total (see above), round
/// after round until none does. Only the fill's faces change, and only which of their vertices
/// they join: no vertex moves, the fill stays oriented as it was, and an edge the mesh already
/// has is never made. Faces that are not triangles of `fill` are read, never changed. One call
/// serves every hole: it reads the whole mesh once. Adjacency the mesh keeps (face-face,
/// vertex-face) is stale afterwards for the fill's faces; the caller updates it where it is
/// enabled. Returns the flips made; `flipped`, if given, gets the two faces of each.
template <class MeshType>
int FlipFillEdgesOntoCreases(MeshType& m, const std::vector<int>& fill,
                             const CreaseFlipParams& params = {},
                             std::vector<int>* flipped = nullptr) {
  using Coord = typename MeshType::CoordType;
  if (fill.size() < 2) return 0;
  // The fill's faces and every face around its vertices, as vertex indices: those are all the
  // faces a flip reads (the neighbours across a quad's sides) or must not duplicate an edge of.
  std::unordered_set<int> fill_vertices;
  for (int f : fill)
    for (int k = 0; k < 3; ++k) fill_vertices.insert(int(vcg::tri::Index(m, m.face[f].cV(k))));
  std::vector<std::array<int, 3>> tris;
  std::vector<int> mesh_face;
  std::vector<char> is_fill;
  std::unordered_set<int> fill_set(fill.begin(), fill.end());
  for (size_t f = 0; f < m.face.size(); ++f) {
    const auto& face = m.face[f];
    if (face.IsD()) continue;
    std::array<int, 3> t;
    bool near = false;
    for (int k = 0; k < 3; ++k) {
      t[size_t(k)] = int(vcg::tri::Index(m, face.cV(k)));
      near = near || fill_vertices.count(t[size_t(k)]) > 0;
    }
    if (!near) continue;
    tris.push_back(t);
    mesh_face.push_back(int(f));
    is_fill.push_back(fill_set.count(int(f)) > 0);
  }
  auto point = [&](int v) { return m.vert[size_t(v)].cP(); };
  auto normal = [&](const std::array<int, 3>& t) {
    return detail::UnitNormal(point(t[0]), point(t[1]), point(t[2]));
  };
  using Edge = std::pair<int, int>;
  auto key = [](int a, int b) { return Edge{std::min(a, b), std::max(a, b)}; };
  std::map<Edge, std::vector<int>> faces_of;
  auto add_edges = [&](int t) {
    for (int k = 0; k < 3; ++k)
      faces_of[key(tris[size_t(t)][size_t(k)], tris[size_t(t)][size_t((k + 1) % 3)])].push_back(t);
  };
  auto remove_edges = [&](int t) {
    for (int k = 0; k < 3; ++k) {
      const auto it =
          faces_of.find(key(tris[size_t(t)][size_t(k)], tris[size_t(t)][size_t((k + 1) % 3)]));
      it->second.erase(std::remove(it->second.begin(), it->second.end(), t), it->second.end());
      if (it->second.empty()) faces_of.erase(it);
    }
  };
  for (size_t t = 0; t < tris.size(); ++t) add_edges(int(t));
  // The face across edge ab from face t, or -1.
  auto across = [&](int a, int b, int t) {
    const auto it = faces_of.find(key(a, b));
    if (it == faces_of.end() || it->second.size() != 2) return -1;
    return it->second[0] == t ? it->second[1] : it->second[0];
  };
  int flips = 0;
  for (int round = 0; round < params.max_rounds; ++round) {
    int flips_this_round = 0;
    for (size_t t1 = 0; t1 < tris.size(); ++t1) {
      if (!is_fill[t1]) continue;
      for (int k = 0; k < 3; ++k) {
        const int a = tris[t1][size_t(k)], b = tris[t1][size_t((k + 1) % 3)],
                  c = tris[t1][size_t((k + 2) % 3)];
        const int t2 = across(a, b, int(t1));
        if (t2 < 0 || !is_fill[size_t(t2)]) continue;
        int d = -1;
        for (int v : tris[size_t(t2)])
          if (v != a && v != b) d = v;
        if (d < 0 || d == c || faces_of.count(key(c, d))) continue;
        // t1 = (a, b, c), t2 = (b, a, d); flipped: (a, d, c), (d, b, c).
        const std::array<int, 3> n1{a, d, c}, n2{d, b, c};
        const Coord before1 = normal(tris[t1]), before2 = normal(tris[size_t(t2)]);
        const Coord after1 = normal(n1), after2 = normal(n2);
        const Coord facing = before1 + before2;
        if (!(after1 * facing > 0) || !(after2 * facing > 0)) continue; // it would turn over
        if (detail::SmallestAngleDegrees(point(a), point(d), point(c)) < params.min_angle ||
            detail::SmallestAngleDegrees(point(d), point(b), point(c)) < params.min_angle)
          continue;
        // The bending over the quad's sides, each against the face beyond it, and over its
        // diagonal, both ways.
        double bend_before = detail::BendDegrees(before1, before2),
               bend_after = detail::BendDegrees(after1, after2);
        bool closed = true;
        auto side = [&](int u, int v, int inside, const Coord& before, const Coord& after) {
          const int beyond = across(u, v, inside);
          if (beyond < 0) {
            closed = false;
            return;
          }
          const Coord n = normal(tris[size_t(beyond)]);
          bend_before += detail::BendDegrees(before, n);
          bend_after += detail::BendDegrees(after, n);
        };
        side(b, c, int(t1), before1, after2);
        side(c, a, int(t1), before1, after1);
        side(a, d, t2, before2, after1);
        side(d, b, t2, before2, after2);
        if (!closed || !(bend_after + params.min_gain < bend_before)) continue;
        remove_edges(int(t1));
        remove_edges(t2);
        tris[t1] = n1;
        tris[size_t(t2)] = n2;
        add_edges(int(t1));
        add_edges(t2);
        if (flipped) flipped->insert(flipped->end(), {mesh_face[t1], mesh_face[size_t(t2)]});
        ++flips_this_round;
        break; // t1 changed: its other edges are looked at next round
      }
    }
    flips += flips_this_round;
    if (flips_this_round == 0) break;
  }
  for (size_t t = 0; t < tris.size(); ++t)
    if (is_fill[t])
      for (int k = 0; k < 3; ++k)
        m.face[size_t(mesh_face[t])].V(k) = &m.vert[size_t(tris[t][size_t(k)])];
  return flips;
}

} // namespace vcg_ext
