// Stage 3: one disk-shaped patch per hole (paper, section 3.2).
//
// Each patch starts as the hole's coarse fill and grows ring by ring over the faces around it,
// all patches in step, so that none crosses another. A face joins only if the patch stays a
// topological disk: it must meet the patch along one edge with its third vertex new to the
// patch, or along two edges (closing a notch). A face that would touch the patch at a lone
// vertex or close a loop (a handle, an extra boundary) waits, and is never taken if it would
// break the disk, so the parameterizer only ever sees disks.
#pragma once

#include "unit_box.h"

#include <Eigen/Core>
#include <vcg/complex/complex.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace vcg_ext {

struct HoleSegmentationParams {
  /// Width of the known ring around each hole, as a multiple of the hole's radius (the paper's
  /// context for the inpainter). 1: the ring is as wide as the hole is large.
  double context = 1.0;
  int max_rings = 64; ///< hard bound on the rings of any patch
};

/// A hole as the later stages see it: its loop and the faces of its coarse fill.
struct FilledHole {
  std::vector<int> loop;       ///< mesh vertex indices of the hole's border
  std::vector<int> fill_faces; ///< mesh face indices of its coarse fill
};

/// One hole's patch in mesh indices.
struct HoleRegion {
  std::vector<int> faces;  ///< the patch's faces, fill faces first
  int fill_face_count = 0; ///< faces[0, fill_face_count) are the hole's coarse fill
  int rings = 0;           ///< rings grown around the fill
  int target_rings = 0;    ///< rings the context asked for
};

/// Vertex -> incident faces of a mesh, in compressed rows: one O(F) pass, shared by all holes.
class VertexFaces {
public:
  template <class MeshType>
  explicit VertexFaces(const MeshType& m) : start_(m.vert.size() + 1, 0) {
    for (const auto& f : m.face)
      if (!f.IsD())
        for (int k = 0; k < 3; ++k) ++start_[vcg::tri::Index(m, f.cV(k)) + 1];
    for (size_t i = 1; i < start_.size(); ++i) start_[i] += start_[i - 1];
    faces_.resize(start_.back());
    std::vector<int> fill(start_.begin(), start_.end() - 1);
    for (size_t fi = 0; fi < m.face.size(); ++fi)
      if (!m.face[fi].IsD())
        for (int k = 0; k < 3; ++k) faces_[fill[vcg::tri::Index(m, m.face[fi].cV(k))]++] = int(fi);
  }
  template <class F>
  void ForEach(int v, F f) const {
    for (int i = start_[v]; i < start_[v + 1]; ++i) f(faces_[i]);
  }

private:
  std::vector<int> start_;
  std::vector<int> faces_;
};

namespace detail {

inline uint64_t EdgeKey(int a, int b) {
  return (uint64_t(std::min(a, b)) << 32) | uint64_t(std::max(a, b));
}

/// The growing patch of one hole: its faces, how many of them each vertex has, and its
/// boundary edges (edges with one patch face).
struct GrowingPatch {
  std::vector<int> faces;
  std::unordered_map<int, int> vertex_faces;
  std::unordered_map<uint64_t, int> edge_faces;
  bool active = true;

  template <class MeshType>
  void Add(const MeshType& m, int f) {
    faces.push_back(f);
    const auto& face = m.face[f];
    for (int k = 0; k < 3; ++k) {
      ++vertex_faces[int(vcg::tri::Index(m, face.cV(k)))];
      ++edge_faces[EdgeKey(int(vcg::tri::Index(m, face.cV(k))),
                           int(vcg::tri::Index(m, face.cV((k + 1) % 3))))];
    }
  }
  bool IsBoundaryEdge(int a, int b) const {
    auto it = edge_faces.find(EdgeKey(a, b));
    return it != edge_faces.end() && it->second == 1;
  }
  bool HasVertex(int v) const { return vertex_faces.count(v) > 0; }
};

} // namespace detail

/// Grows the patches of `holes` on `m` (which holds their coarse fills). `vf` is the mesh's
/// vertex-face incidence. Patches are face- and vertex-disjoint apart from vertices the holes
/// already shared, and each is a topological disk.
template <class MeshType>
std::vector<HoleRegion> SegmentHolePatches(const MeshType& m, const VertexFaces& vf,
                                           const std::vector<FilledHole>& holes, const UnitBox& box,
                                           const HoleSegmentationParams& params = {}) {
  const int count = int(holes.size());
  std::vector<detail::GrowingPatch> patches(count);
  std::vector<HoleRegion> regions(count);
  std::unordered_map<int, int> face_owner, vertex_owner;
  for (int h = 0; h < count; ++h) {
    for (int f : holes[h].fill_faces) {
      patches[h].Add(m, f);
      face_owner[f] = h;
      for (int k = 0; k < 3; ++k) vertex_owner.emplace(int(vcg::tri::Index(m, m.face[f].cV(k))), h);
    }
    regions[h].fill_face_count = int(holes[h].fill_faces.size());
    // Rings wanted: the hole's radius over the edge length around it, times the context.
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int v : holes[h].loop) centre += box.ToUnit(m.vert[v].cP());
    centre /= double(std::max<size_t>(holes[h].loop.size(), 1));
    double radius = 0, edge = 0;
    for (size_t i = 0; i < holes[h].loop.size(); ++i) {
      const Eigen::Vector3d p = box.ToUnit(m.vert[holes[h].loop[i]].cP());
      radius = std::max(radius, (p - centre).norm());
      edge += (p - box.ToUnit(m.vert[holes[h].loop[(i + 1) % holes[h].loop.size()]].cP())).norm();
    }
    edge /= double(std::max<size_t>(holes[h].loop.size(), 1));
    regions[h].target_rings =
        std::min(params.max_rings,
                 std::max(1, int(std::ceil(params.context * radius / std::max(edge, 1e-12)))));
  }

  auto vertex_of = [&](int f, int k) { return int(vcg::tri::Index(m, m.face[f].cV(k))); };
  for (int ring = 1; ring <= params.max_rings; ++ring) {
    bool any_active = false;
    for (int h = 0; h < count; ++h) {
      detail::GrowingPatch& patch = patches[h];
      if (!patch.active || ring > regions[h].target_rings) continue;
      any_active = true;
      // Faces beside the boundary as it stands at the start of this ring.
      std::vector<int> candidates;
      std::unordered_set<int> seen;
      for (int f : patch.faces)
        for (int k = 0; k < 3; ++k) {
          const int a = vertex_of(f, k), b = vertex_of(f, (k + 1) % 3);
          if (!patch.IsBoundaryEdge(a, b)) continue;
          vf.ForEach(a, [&](int g) {
            if (face_owner.count(g) || seen.count(g)) return;
            for (int j = 0; j < 3; ++j)
              if (vertex_of(g, j) == b) {
                seen.insert(g);
                candidates.push_back(g);
              }
          });
        }
      int added = 0;
      // Two passes: a face refused in the first may close a notch the first opened.
      for (int pass = 0; pass < 2; ++pass)
        for (int& g : candidates) {
          if (g < 0 || face_owner.count(g)) continue;
          int shared = 0, lone = -1;
          bool foreign = false;
          for (int j = 0; j < 3; ++j) {
            const int a = vertex_of(g, j), b = vertex_of(g, (j + 1) % 3);
            if (patch.IsBoundaryEdge(a, b)) ++shared;
            auto ow = vertex_owner.find(a);
            foreign = foreign || (ow != vertex_owner.end() && ow->second != h);
          }
          if (foreign || shared == 0 || shared == 3) continue;
          if (shared == 1) {
            // The vertex opposite the shared edge must be new to the patch.
            for (int j = 0; j < 3; ++j)
              if (patch.IsBoundaryEdge(vertex_of(g, j), vertex_of(g, (j + 1) % 3)))
                lone = vertex_of(g, (j + 2) % 3);
            if (patch.HasVertex(lone)) continue;
          }
          patch.Add(m, g);
          face_owner[g] = h;
          for (int j = 0; j < 3; ++j) vertex_owner.emplace(vertex_of(g, j), h);
          g = -1;
          ++added;
        }
      if (added == 0)
        patch.active = false; // surrounded, or at the mesh's end
      else
        regions[h].rings = ring;
    }
    if (!any_active) break;
  }
  for (int h = 0; h < count; ++h) regions[h].faces = std::move(patches[h].faces);
  return regions;
}

} // namespace vcg_ext
