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

namespace detail {

/// Flips triangles so that every pair sharing an edge runs it in opposite directions (scans
/// carry faces flipped against their neighbours; a disk can always be oriented). The first
/// triangle of each connected piece keeps its orientation.
inline void OrientConsistently(std::vector<std::array<int, 3>>& tris) {
  std::unordered_map<uint64_t, std::vector<int>> by_edge;
  for (int t = 0; t < int(tris.size()); ++t)
    for (int k = 0; k < 3; ++k) by_edge[EdgeKey(tris[t][k], tris[t][(k + 1) % 3])].push_back(t);
  std::vector<char> done(tris.size(), 0);
  for (int seed = 0; seed < int(tris.size()); ++seed) {
    if (done[seed]) continue;
    done[seed] = 1;
    std::vector<int> stack{seed};
    while (!stack.empty()) {
      const int t = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k) {
        const int a = tris[t][k], b = tris[t][(k + 1) % 3];
        for (int u : by_edge[EdgeKey(a, b)]) {
          if (u == t || done[u]) continue;
          // u must run the edge b -> a.
          for (int j = 0; j < 3; ++j)
            if (tris[u][j] == a && tris[u][(j + 1) % 3] == b) std::swap(tris[u][1], tris[u][2]);
          done[u] = 1;
          stack.push_back(u);
        }
      }
    }
  }
}

} // namespace detail

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
  detail::OrientConsistently(p.triangles);
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
