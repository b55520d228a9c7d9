// Between stages 3 and 6: a hole's patch as a standalone indexed disk in unit-box
// coordinates, with its boundary loop in order, ready for parameterization and rasterization.
#pragma once

#include "hole_segmentation.h"

#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace vcg_ext {

struct PatchMesh {
  std::vector<int> vertices;                 ///< mesh index of each local vertex
  std::vector<Eigen::Vector3d> points;       ///< unit-box positions
  std::vector<std::array<int, 3>> triangles; ///< local indices
  std::vector<char> is_fill;                 ///< per triangle: part of the hole's coarse fill
  std::vector<int> boundary;                 ///< the boundary loop, local indices in order
  int euler = 0;                             ///< V - E + F: 1 for a disk
  int boundary_loops = 0;
  bool IsDisk() const { return euler == 1 && boundary_loops == 1; }
};

/// Builds the local disk of `region`. Ears of context faces (a face with two boundary edges)
/// are peeled first: all three of their corners would land on the square's border, flat.
template <class MeshType>
PatchMesh ExtractPatch(const MeshType& m, const HoleRegion& region, const UnitBox& box) {
  PatchMesh p;
  std::vector<int> faces = region.faces;
  std::vector<char> fill(faces.size(), 0);
  for (int i = 0; i < region.fill_face_count; ++i) fill[i] = 1;

  auto corner = [&](int f, int k) { return int(vcg::tri::Index(m, m.face[f].cV(k))); };
  for (bool peeled = true; peeled;) {
    peeled = false;
    std::unordered_map<uint64_t, int> edges;
    for (int f : faces)
      for (int k = 0; k < 3; ++k) ++edges[detail::EdgeKey(corner(f, k), corner(f, (k + 1) % 3))];
    std::vector<int> kept_faces;
    std::vector<char> kept_fill;
    for (size_t i = 0; i < faces.size(); ++i) {
      int boundary_edges = 0;
      for (int k = 0; k < 3; ++k)
        boundary_edges +=
            edges[detail::EdgeKey(corner(faces[i], k), corner(faces[i], (k + 1) % 3))] == 1;
      if (!fill[i] && boundary_edges == 2) {
        peeled = true;
        continue;
      }
      kept_faces.push_back(faces[i]);
      kept_fill.push_back(fill[i]);
    }
    if (!peeled) break;
    faces.swap(kept_faces);
    fill.swap(kept_fill);
  }

  std::unordered_map<int, int> local;
  for (size_t i = 0; i < faces.size(); ++i) {
    std::array<int, 3> t;
    for (int k = 0; k < 3; ++k) {
      const int v = corner(faces[i], k);
      auto it = local.find(v);
      if (it == local.end()) {
        it = local.emplace(v, int(p.vertices.size())).first;
        p.vertices.push_back(v);
        p.points.push_back(box.ToUnit(m.vert[v].cP()));
      }
      t[k] = it->second;
    }
    p.triangles.push_back(t);
    p.is_fill.push_back(fill[i]);
  }
  // Boundary: half-edges whose reverse is not in the patch, chained into loops.
  std::unordered_map<uint64_t, int> directed;
  for (const auto& t : p.triangles)
    for (int k = 0; k < 3; ++k)
      ++directed[(uint64_t(uint32_t(t[k])) << 32) | uint32_t(t[(k + 1) % 3])];
  std::unordered_map<int, int> next;
  int edge_count = 0;
  for (const auto& t : p.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      if (!directed.count((uint64_t(uint32_t(b)) << 32) | uint32_t(a)))
        next[a] = b, ++edge_count;
      else if (a < b)
        ++edge_count;
    }
  p.euler = int(p.points.size()) - edge_count + int(p.triangles.size());
  std::unordered_set<int> visited;
  for (const auto& kv : next) {
    if (visited.count(kv.first)) continue;
    ++p.boundary_loops;
    std::vector<int> loop;
    for (int v = kv.first; !visited.count(v) && next.count(v); v = next[v]) {
      visited.insert(v);
      loop.push_back(v);
    }
    if (loop.size() > p.boundary.size()) p.boundary = loop;
  }
  return p;
}

} // namespace vcg_ext
