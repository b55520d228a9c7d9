// Stage 1: find the holes of a mesh as simple boundary loops.
//
// A loop that passes a vertex twice (a pinch: two boundary fans meeting at one non-manifold
// vertex, like the falcon statue's bottom) is split there, so every loop handed to the
// triangulation is a simple polygon.
#pragma once

#include "edge_census.h"

#include <vcg/space/box3.h>

#include <algorithm>
#include <unordered_map>
#include <vector>

namespace vcg_ext {

struct HoleLoop {
  /// Vertex indices along the boundary, in the direction of the faces beside it: each
  /// vertices[i] -> vertices[i+1] is a half-edge of an existing face.
  std::vector<int> vertices;
  /// The face beside each boundary edge vertices[i] -> vertices[i+1].
  std::vector<int> faces;
  /// Whether that face runs the edge as vertices[i] -> vertices[i+1]; false only where a face
  /// is flipped against its neighbours.
  std::vector<char> face_agrees;
  /// True when one of the loop's vertices also lies on another part of the boundary.
  bool pinched = false;

  int EdgeCount() const { return int(vertices.size()); }
};

struct HoleLoopParams {
  int max_edges = 0;          ///< loops with more boundary edges are left open; 0 = no limit
  bool selected_only = false; ///< only loops with a selected face beside them
  /// Loops whose border spans more than this (the diagonal of its bounding box, in the mesh's
  /// units) are left open; 0 = no limit.
  double max_diameter = 0;
  /// The longest loop is the outer border of an open scan (a terrain, a relief, a face mask),
  /// not a hole: leave it open.
  bool keep_longest_open = false;
};

struct HoleLoops {
  std::vector<HoleLoop> holes;  ///< the loops to fill
  int skipped_by_size = 0;      ///< loops over max_edges or max_diameter
  int skipped_by_selection = 0; ///< loops with no selected face beside them
  int kept_as_border = 0;       ///< 1 when keep_longest_open left the longest loop open
};

/// Splits the boundary half-edges of `census` into simple loops and selects those `params`
/// asks for. Precondition: the census found no non-manifold edges.
template <class MeshType>
HoleLoops FindHoleLoops(const MeshType& m, const EdgeCensus& census,
                        const HoleLoopParams& params = {}) {
  // Boundary edges around each vertex; a pinch vertex has more than two. The walk ignores
  // the edges' directions: a face flipped against its neighbours (scans have a few) must not
  // break its hole's loop.
  const auto& boundary = census.boundary;
  std::unordered_map<int, std::vector<int>> incident;
  for (int i = 0; i < int(boundary.size()); ++i) {
    incident[boundary[i].from].push_back(i);
    incident[boundary[i].to].push_back(i);
  }

  struct Step {
    int edge; // index into census.boundary
    int from; // the vertex the walk leaves along it
  };
  std::vector<char> used(boundary.size(), 0);
  std::vector<std::vector<Step>> loops;
  for (int start = 0; start < int(boundary.size()); ++start) {
    if (used[start]) continue;
    // Walk until the start vertex is reached again. Every vertex has an even number of
    // boundary edges, so the walk cannot get stuck on a valid census.
    std::vector<Step> walk;
    const int start_vertex = boundary[start].from;
    int e = start, v = start_vertex;
    for (;;) {
      used[e] = 1;
      walk.push_back({e, v});
      v = boundary[e].from == v ? boundary[e].to : boundary[e].from;
      if (v == start_vertex) break;
      int next = -1;
      for (int cand : incident[v])
        if (!used[cand]) {
          next = cand;
          break;
        }
      if (next < 0) break;
      e = next;
    }
    if (v != start_vertex) continue; // an open chain: not a hole
    // Split at repeated vertices: whenever the walk returns to a vertex already on the
    // stack, the steps since then form a simple loop of their own.
    std::vector<Step> stack;
    std::unordered_map<int, int> position; // vertex -> index in stack of the step leaving it
    for (const Step& step : walk) {
      auto it = position.find(step.from);
      if (it != position.end()) {
        const int at = it->second;
        loops.emplace_back(stack.begin() + at, stack.end());
        for (size_t k = at; k < stack.size(); ++k) position.erase(stack[k].from);
        stack.resize(at);
      }
      position[step.from] = int(stack.size());
      stack.push_back(step);
    }
    if (!stack.empty()) loops.push_back(stack);
  }

  // The longest loop by length, for keep_longest_open.
  size_t longest = loops.size();
  if (params.keep_longest_open) {
    double best = -1;
    for (size_t l = 0; l < loops.size(); ++l) {
      double length = 0;
      for (const Step& step : loops[l]) {
        const HalfEdge& h = boundary[step.edge];
        length += double(vcg::Distance(m.vert[h.from].cP(), m.vert[h.to].cP()));
      }
      if (length > best) best = length, longest = l;
    }
  }

  HoleLoops result;
  for (size_t l = 0; l < loops.size(); ++l) {
    const auto& loop = loops[l];
    if (l == longest) {
      ++result.kept_as_border;
      continue;
    }
    HoleLoop hole;
    bool selected = false;
    int agreeing = 0;
    for (const Step& step : loop) {
      const HalfEdge& h = boundary[step.edge];
      hole.vertices.push_back(step.from);
      hole.faces.push_back(h.face);
      hole.face_agrees.push_back(h.from == step.from);
      agreeing += h.from == step.from;
      hole.pinched = hole.pinched || incident[step.from].size() > 2;
      selected = selected || m.face[h.face].IsS();
    }
    if (2 * agreeing < hole.EdgeCount()) { // run the loop the way most faces beside it do
      const int n = hole.EdgeCount();
      std::reverse(hole.vertices.begin() + 1, hole.vertices.end());
      std::reverse(hole.faces.begin(), hole.faces.end());
      std::reverse(hole.face_agrees.begin(), hole.face_agrees.end());
      for (int i = 0; i < n; ++i) hole.face_agrees[i] = !hole.face_agrees[i];
    }
    if (params.max_edges > 0 && hole.EdgeCount() > params.max_edges) {
      ++result.skipped_by_size;
      continue;
    }
    if (params.max_diameter > 0) {
      vcg::Box3<double> box;
      for (int v : hole.vertices) {
        const auto& p = m.vert[v].cP();
        box.Add(vcg::Point3<double>(p[0], p[1], p[2]));
      }
      if (box.Diag() > params.max_diameter) {
        ++result.skipped_by_size;
        continue;
      }
    }
    if (params.selected_only && !selected) {
      ++result.skipped_by_selection;
      continue;
    }
    result.holes.push_back(std::move(hole));
  }
  return result;
}

} // namespace vcg_ext
