#include "pipeline/pipeline.h"

#include <vcg/complex/algorithms/update/bounding.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <map>

namespace curvature_inpaint {

vcg_ext::CoarseFillResult CoarseFill(CMeshO& m, const vcg_ext::CoarseFillParams& params,
                                     vcg::CallBackPos* cb) {
  vcg_ext::CoarseFillResult result = vcg_ext::CoarseFill(m, params, cb);
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
  return result;
}

MeshCheckpoint::MeshCheckpoint(CMeshO& m) : m_(m), vn_(m.vert.size()), fn_(m.face.size()) {
  for (const auto& f : m.face) selected_.push_back(f.IsS());
}

void CopyMesh(const CMeshO& from, CMeshO& to) {
  to.Clear();
  std::vector<int> index(from.vert.size(), -1);
  int live = 0;
  for (size_t v = 0; v < from.vert.size(); ++v)
    if (!from.vert[v].IsD()) index[v] = live++;
  auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(to, live);
  for (size_t v = 0; v < from.vert.size(); ++v)
    if (!from.vert[v].IsD()) {
      vi->P() = from.vert[v].cP();
      (vi++)->N() = from.vert[v].cN();
    }
  int faces = 0;
  for (const auto& f : from.face) faces += !f.IsD();
  auto fi = vcg::tri::Allocator<CMeshO>::AddFaces(to, faces);
  for (const auto& f : from.face) {
    if (f.IsD()) continue;
    for (int k = 0; k < 3; ++k) fi->V(k) = &to.vert[index[vcg::tri::Index(from, f.cV(k))]];
    if (f.IsS()) fi->SetS();
    ++fi;
  }
  vcg::tri::UpdateBounding<CMeshO>::Box(to);
}

void MeshCheckpoint::Restore() {
  for (size_t f = fn_; f < m_.face.size(); ++f)
    if (!m_.face[f].IsD()) vcg::tri::Allocator<CMeshO>::DeleteFace(m_, m_.face[f]);
  for (size_t v = vn_; v < m_.vert.size(); ++v)
    if (!m_.vert[v].IsD()) vcg::tri::Allocator<CMeshO>::DeleteVertex(m_, m_.vert[v]);
  vcg::tri::Allocator<CMeshO>::CompactEveryVector(m_);
  for (size_t f = 0; f < fn_; ++f) selected_[f] ? m_.face[f].SetS() : m_.face[f].ClearS();
  vcg::tri::UpdateBounding<CMeshO>::Box(m_);
}

std::vector<std::string> DescribeCoarseFill(const vcg_ext::CoarseFillResult& result) {
  std::vector<std::string> lines;
  char buf[512];
  int new_vertices = 0, new_faces = 0;
  for (size_t h = 0; h < result.holes.size(); ++h) {
    const auto& r = result.holes[h];
    new_vertices += int(r.new_vertices.size());
    new_faces += int(r.new_faces.size());
    if (r.filled) {
      std::snprintf(buf, sizeof buf,
                    "hole %zu: %d edges%s, %s, %zu new vertices, %zu faces, %s, %.1f ms%s%s", h + 1,
                    r.boundary_edges, r.pinched ? " (pinched)" : "", r.triangulation.c_str(),
                    r.new_vertices.size(), r.new_faces.size(),
                    r.planar_cap ? "flat cap"
                    : r.faired   ? "faired"
                                 : "not faired",
                    1000 * r.seconds, r.problem.empty() ? "" : ": ", r.problem.c_str());
    } else {
      std::snprintf(buf, sizeof buf, "hole %zu: %d edges%s, left open: %s", h + 1, r.boundary_edges,
                    r.pinched ? " (pinched)" : "", r.problem.c_str());
    }
    lines.emplace_back(buf);
  }
  std::snprintf(buf, sizeof buf,
                "filled %d of %zu holes with %d vertices and %d faces; left open: %d over the "
                "size limit, %d away from the selection%s",
                result.FilledCount(), result.holes.size(), new_vertices, new_faces,
                result.skipped_by_size, result.skipped_by_selection,
                result.kept_as_border ? ", the longest loop as the scan's outer border" : "");
  lines.emplace_back(buf);
  if (result.inconsistent_edges > 0) {
    std::snprintf(buf, sizeof buf,
                  "warning: %zu edges join faces of opposite orientation (left as they are; "
                  "MeshLab's \"Re-Orient all faces coherently\" repairs them)",
                  result.inconsistent_edges);
    lines.emplace_back(buf);
  }
  return lines;
}

HoleCensus CountHoles(const CMeshO& m) {
  HoleCensus census;
  census.vertices = m.vn;
  census.faces = m.fn;
  const vcg_ext::EdgeCensus edges = vcg_ext::CensusEdges(m);
  census.non_manifold_edges = edges.non_manifold_edges;
  census.inconsistent_edges = edges.inconsistent_edges;
  if (census.non_manifold_edges == 0) {
    const vcg_ext::HoleLoops loops = vcg_ext::FindHoleLoops(m, edges);
    for (const auto& l : loops.holes) census.loop_edges.push_back(l.EdgeCount());
  }
  std::sort(census.loop_edges.begin(), census.loop_edges.end(), std::greater<int>());
  return census;
}

std::vector<HoleSummary> ListHoles(const CMeshO& m, const vcg_ext::CoarseFillParams& selection) {
  std::vector<HoleSummary> list;
  const vcg_ext::EdgeCensus edges = vcg_ext::CensusEdges(m);
  if (edges.non_manifold_edges != 0) return list;
  vcg_ext::HoleLoopParams chosen;
  chosen.max_edges = selection.max_hole_edges;
  chosen.selected_only = selection.selected_only;
  chosen.keep_longest_open = selection.keep_longest_open;
  chosen.max_diameter = selection.max_hole_diameter * double(m.bbox.Diag());
  // The loops come in the same order with and without a selection; a loop is known by its
  // first vertex, where every walk of it starts.
  std::map<int, int> number_of;
  const vcg_ext::HoleLoops filled = vcg_ext::FindHoleLoops(m, edges, chosen);
  for (size_t k = 0; k < filled.holes.size(); ++k)
    number_of[filled.holes[k].vertices[0]] = int(k) + 1;
  for (const vcg_ext::HoleLoop& loop : vcg_ext::FindHoleLoops(m, edges, {}).holes) {
    HoleSummary h;
    const auto it = number_of.find(loop.vertices[0]);
    h.number = it == number_of.end() ? 0 : it->second;
    h.edges = loop.EdgeCount();
    vcg::Box3d box;
    for (int v : loop.vertices) {
      const vcg::Point3d p = vcg::Point3d::Construct(m.vert[size_t(v)].cP());
      box.Add(p);
      h.centre += p / double(loop.vertices.size());
    }
    h.diameter = box.Diag();
    list.push_back(h);
  }
  return list;
}

ScanPart ScanPartOf(const CMeshO& m, const vcg_ext::CoarseFillResult& coarse) {
  ScanPart scan{m.vert.size(), m.face.size()};
  for (const auto& h : coarse.holes) {
    for (int v : h.new_vertices) scan.vertices = std::min(scan.vertices, size_t(v));
    for (int f : h.new_faces) scan.faces = std::min(scan.faces, size_t(f));
  }
  return scan;
}

} // namespace curvature_inpaint
