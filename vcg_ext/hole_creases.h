// The crease lines of the known surface that run into a hole. A machined part's crease is a
// line of sharp edges, several in a row, that reaches the hole's loop and goes on beyond it;
// the noise of a scanned organic surface makes sharp edges too, but one here and one there,
// never in a line. What is a crease here decides whether a fill's edges may be flipped onto
// its bends (crease_flips.h): on an organic surface they are no creases, and flipping onto
// them carves ridges into it.
#pragma once

#include "patch_extraction.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <utility>
#include <vector>

namespace vcg_ext {

struct HoleCreaseParams {
  double crease_angle = 30; ///< degrees between the normals of two faces that meet at a crease
  /// Crease edges in one connected line: a lone one is noise. The patch's known ring is about
  /// a hole radius wide, two or three edges of a coarse mesh, so a line cannot be asked to be
  /// longer.
  int min_run = 2;
};

/// How many crease lines of the known surface of `patch` reach its hole: connected sets of at
/// least `min_run` crease edges between known triangles (not `patch.is_fill`) with a vertex on
/// the hole's loop. A crease that crosses the hole reaches it twice, a corner's three creases
/// three times.
/// \pre patch.is_fill has one entry per triangle.
inline int CreaseLinesIntoHole(const PatchMesh& patch, const HoleCreaseParams& params = {}) {
  using Edge = std::pair<int, int>;
  const std::vector<Eigen::Vector3d>& p = patch.points;
  std::vector<char> on_loop(p.size(), 0); // vertices of the fill's triangles: new or the loop's
  std::map<Edge, std::vector<Eigen::Vector3d>> normals_at; // known triangles' normals per edge
  for (size_t t = 0; t < patch.triangles.size(); ++t) {
    const auto& tri = patch.triangles[t];
    if (patch.is_fill[t]) {
      for (int v : tri) on_loop[size_t(v)] = 1;
      continue;
    }
    const Eigen::Vector3d n = (p[size_t(tri[1])] - p[size_t(tri[0])])
                                  .cross(p[size_t(tri[2])] - p[size_t(tri[0])])
                                  .normalized();
    for (int k = 0; k < 3; ++k) {
      const int a = tri[size_t(k)], b = tri[size_t((k + 1) % 3)];
      normals_at[{std::min(a, b), std::max(a, b)}].push_back(n);
    }
  }
  // The crease edges, joined into lines where they share a vertex (union-find on vertices).
  const double cos_crease = std::cos(params.crease_angle * M_PI / 180);
  std::vector<int> parent(p.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&parent](int v) {
    while (parent[size_t(v)] != v) v = parent[size_t(v)] = parent[size_t(parent[size_t(v)])];
    return v;
  };
  std::vector<Edge> creases;
  for (const auto& e : normals_at) {
    const std::vector<Eigen::Vector3d>& n = e.second;
    if (n.size() != 2 || !(n[0].dot(n[1]) < cos_crease)) continue;
    creases.push_back(e.first);
    parent[size_t(root(e.first.first))] = root(e.first.second);
  }
  std::map<int, int> edges_in_line;
  std::set<int> reaching; // the lines with a vertex on the loop (crease edges are known ones)
  for (const Edge& e : creases) {
    const int line = root(e.first);
    ++edges_in_line[line];
    if (on_loop[size_t(e.first)] || on_loop[size_t(e.second)]) reaching.insert(line);
  }
  return int(std::count_if(reaching.begin(), reaching.end(),
                           [&](int line) { return edges_in_line[line] >= params.min_run; }));
}

} // namespace vcg_ext
