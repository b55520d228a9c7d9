// Preconditions shared by the stages that change topology.
#pragma once

#include "edge_census.h"
#include "mesh_errors.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <vector>

namespace vcg_ext {

namespace detail {
inline std::string Counted(size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}
} // namespace detail

/// Throws InvalidMeshError, naming the problem and what to run first, unless `m` has faces,
/// finite coordinates, edges shared by at most two faces, and no two boundary vertices at the
/// same position (an unwelded mesh). Faces that repeat a vertex are ignored (counted). Edges whose
/// two faces disagree on orientation are allowed (scans often have a few, far from any hole); the
/// census counts them. Returns the census so callers do not compute it twice.
template <class MeshType>
EdgeCensus ValidateForHoleFilling(const MeshType& m) {
  if (m.fn == 0 || m.vn == 0)
    throw InvalidMeshError("the mesh is empty: it has no faces to fill holes between");
  size_t non_finite = 0;
  for (const auto& v : m.vert) {
    if (v.IsD()) continue;
    for (int k = 0; k < 3; ++k)
      if (!std::isfinite(double(v.cP()[k]))) {
        ++non_finite;
        break;
      }
  }
  if (non_finite > 0)
    throw InvalidMeshError(detail::Counted(non_finite, "vertex has", "vertices have") +
                           " non-finite coordinates (NaN or infinity); remove them before "
                           "filling holes");
  EdgeCensus census = CensusEdges(m);
  if (census.non_manifold_edges > 0)
    throw InvalidMeshError(detail::Counted(census.non_manifold_edges, "edge is", "edges are") +
                           " shared by more than two faces; run MeshLab's \"Repair non "
                           "Manifold Edges\" first");
  // A mesh stored per face (each triangle with its own corners) has a "hole" along every
  // edge; filling those would double the surface. Such boundaries run through vertices that
  // sit exactly on other boundary vertices.
  std::vector<int> border;
  for (const auto& h : census.boundary) border.push_back(h.from);
  std::sort(border.begin(), border.end());
  border.erase(std::unique(border.begin(), border.end()), border.end());
  std::sort(border.begin(), border.end(), [&](int a, int b) {
    const auto &p = m.vert[a].cP(), &q = m.vert[b].cP();
    return std::make_tuple(p[0], p[1], p[2]) < std::make_tuple(q[0], q[1], q[2]);
  });
  size_t coincident = 0;
  for (size_t i = 1; i < border.size(); ++i)
    coincident += m.vert[border[i]].cP() == m.vert[border[i - 1]].cP();
  if (coincident > 0)
    throw InvalidMeshError(
        detail::Counted(coincident, "boundary vertex sits", "boundary vertices sit") +
        " exactly on another: the mesh is not welded, its borders are seams, "
        "not holes; run MeshLab's \"Merge Close Vertices\" first");
  return census;
}

} // namespace vcg_ext
