// Makes a hole for evaluation: removes every face with a vertex inside a ball, as the
// benchmark cases of the hole-filling literature do. Not a pipeline stage.
#pragma once

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/complex.h>

namespace vcg_ext {

/// Deletes the faces of `m` with any vertex within `radius` of `center`, then drops vertices
/// no face uses and compacts, keeping the order of the remaining vertices. Returns the number
/// of faces removed.
template <class MeshType>
int PunchHole(MeshType& m, const typename MeshType::CoordType& center,
              typename MeshType::ScalarType radius) {
  int removed = 0;
  for (auto& f : m.face) {
    if (f.IsD()) continue;
    bool inside = false;
    for (int k = 0; k < 3 && !inside; ++k) inside = vcg::Distance(f.cV(k)->cP(), center) < radius;
    if (inside) {
      vcg::tri::Allocator<MeshType>::DeleteFace(m, f);
      ++removed;
    }
  }
  vcg::tri::Clean<MeshType>::RemoveUnreferencedVertex(m);
  vcg::tri::Allocator<MeshType>::CompactEveryVector(m);
  return removed;
}

} // namespace vcg_ext
