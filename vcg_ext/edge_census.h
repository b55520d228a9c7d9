// Classifies every edge of a triangle mesh by the faces around it, in O(F log F) and without
// vcglib's optional adjacency components (which a caller's mesh may not have enabled).
#pragma once

#include <vcg/complex/complex.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace vcg_ext {

/// A directed edge of a face: `from` -> `to` in the face's vertex order.
struct HalfEdge {
  int from = -1;
  int to = -1;
  int face = -1;
};

struct EdgeCensus {
  std::vector<HalfEdge> boundary; ///< half-edges whose undirected edge has one face
  size_t non_manifold_edges = 0;  ///< undirected edges with three or more faces
  size_t inconsistent_edges = 0;  ///< two faces running the edge in the same direction
  size_t degenerate_faces = 0;    ///< faces that repeat a vertex
};

/// Census of the live faces of `m`. Indices are positions in m.vert and m.face.
template <class MeshType>
EdgeCensus CensusEdges(const MeshType& m) {
  struct Entry {
    int lo, hi, face;
    bool forward; // from == lo
  };
  std::vector<Entry> entries;
  entries.reserve(m.face.size() * 3);
  EdgeCensus census;
  for (size_t fi = 0; fi < m.face.size(); ++fi) {
    const auto& f = m.face[fi];
    if (f.IsD()) continue;
    std::array<int, 3> v;
    for (int j = 0; j < 3; ++j) v[j] = int(vcg::tri::Index(m, f.cV(j)));
    if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) {
      ++census.degenerate_faces;
      continue;
    }
    for (int j = 0; j < 3; ++j) {
      const int a = v[j], b = v[(j + 1) % 3];
      entries.push_back({std::min(a, b), std::max(a, b), int(fi), a < b});
    }
  }
  std::sort(entries.begin(), entries.end(), [](const Entry& x, const Entry& y) {
    return x.lo != y.lo ? x.lo < y.lo : x.hi < y.hi;
  });
  for (size_t i = 0; i < entries.size();) {
    size_t j = i + 1;
    while (j < entries.size() && entries[j].lo == entries[i].lo && entries[j].hi == entries[i].hi)
      ++j;
    const size_t count = j - i;
    if (count == 1) {
      const Entry& e = entries[i];
      census.boundary.push_back(e.forward ? HalfEdge{e.lo, e.hi, e.face}
                                          : HalfEdge{e.hi, e.lo, e.face});
    } else if (count == 2) {
      if (entries[i].forward == entries[i + 1].forward) ++census.inconsistent_edges;
    } else {
      ++census.non_manifold_edges;
    }
    i = j;
  }
  return census;
}

} // namespace vcg_ext
