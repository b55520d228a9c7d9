// Preconditions shared by the stages that change topology.
#pragma once

#include "edge_census.h"
#include "mesh_errors.h"

#include <cmath>
#include <string>

namespace vcg_ext {

namespace detail {
inline std::string Counted(size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}
} // namespace detail

/// Throws InvalidMeshError, naming the problem and what to run first, unless `m` has faces,
/// finite coordinates, and edges shared by at most two faces. Edges whose two faces disagree
/// on orientation are allowed (scans often have a few, far from any hole); the census counts
/// them. Returns the census so callers do not compute it twice.
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
  return census;
}

} // namespace vcg_ext
