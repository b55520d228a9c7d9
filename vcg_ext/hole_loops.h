// Stage 1: find the holes of a mesh as simple boundary loops.
//
// A loop that passes a vertex twice (a pinch: two boundary fans meeting at one non-manifold
// vertex, like the falcon statue's bottom) is split there, so every loop handed to the
// triangulation is a simple polygon.
#pragma once

#include "edge_census.h"

#include <unordered_map>
#include <vector>

namespace vcg_ext {

struct HoleLoop {
  /// Vertex indices along the boundary, in the direction of the faces beside it: each
  /// vertices[i] -> vertices[i+1] is a half-edge of an existing face.
  std::vector<int> vertices;
  /// The face beside each boundary edge vertices[i] -> vertices[i+1].
  std::vector<int> faces;
  /// True when one of the loop's vertices also lies on another part of the boundary.
  bool pinched = false;

  int EdgeCount() const { return int(vertices.size()); }
};

struct HoleLoopParams {
  int max_edges = 0;          ///< loops with more boundary edges are left open; 0 = no limit
  bool selected_only = false; ///< only loops with a selected face beside them
};

struct HoleLoops {
  std::vector<HoleLoop> holes;  ///< the loops to fill
  int skipped_by_size = 0;      ///< loops over max_edges
  int skipped_by_selection = 0; ///< loops with no selected face beside them
};

/// Splits the boundary half-edges of `census` into simple loops and selects those `params`
/// asks for. Precondition: the census found no non-manifold or inconsistent edges.
template <class MeshType>
HoleLoops FindHoleLoops(const MeshType& m, const EdgeCensus& census,
                        const HoleLoopParams& params = {}) {
  // Outgoing boundary half-edges per vertex; a pinch vertex has more than one.
  std::unordered_map<int, std::vector<int>> outgoing;
  for (int i = 0; i < int(census.boundary.size()); ++i)
    outgoing[census.boundary[i].from].push_back(i);

  std::vector<char> used(census.boundary.size(), 0);
  std::vector<std::vector<int>> loops; // as lists of half-edge indices
  for (int start = 0; start < int(census.boundary.size()); ++start) {
    if (used[start]) continue;
    // Walk until the start vertex is reached again. Every vertex has as many outgoing as
    // incoming boundary half-edges, so the walk cannot get stuck.
    std::vector<int> walk;
    int e = start;
    const int start_vertex = census.boundary[start].from;
    for (;;) {
      used[e] = 1;
      walk.push_back(e);
      const int v = census.boundary[e].to;
      if (v == start_vertex) break;
      int next = -1;
      for (int cand : outgoing[v])
        if (!used[cand]) {
          next = cand;
          break;
        }
      if (next < 0) break; // cannot happen on a valid census; keep what was walked
      e = next;
    }
    if (census.boundary[walk.back()].to != start_vertex) continue;
    // Split at repeated vertices: whenever the walk returns to a vertex already on the
    // stack, the half-edges since then form a simple loop of their own.
    std::vector<int> stack;
    std::unordered_map<int, int> position; // vertex -> index in stack of the edge leaving it
    for (int he : walk) {
      const int from = census.boundary[he].from;
      auto it = position.find(from);
      if (it != position.end()) {
        const int at = it->second;
        loops.emplace_back(stack.begin() + at, stack.end());
        for (size_t k = at; k < stack.size(); ++k) position.erase(census.boundary[stack[k]].from);
        stack.resize(at);
      }
      position[from] = int(stack.size());
      stack.push_back(he);
    }
    if (!stack.empty()) loops.push_back(stack);
  }

  HoleLoops result;
  for (const auto& loop : loops) {
    HoleLoop hole;
    bool selected = false;
    for (int he : loop) {
      const HalfEdge& h = census.boundary[he];
      hole.vertices.push_back(h.from);
      hole.faces.push_back(h.face);
      hole.pinched = hole.pinched || outgoing[h.from].size() > 1;
      selected = selected || m.face[h.face].IsS();
    }
    if (params.max_edges > 0 && hole.EdgeCount() > params.max_edges) {
      ++result.skipped_by_size;
      continue;
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
