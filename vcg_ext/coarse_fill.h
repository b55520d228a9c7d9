// Stages 0-2: the coarse fill. Finds the holes of a mesh and closes each with a triangulation
// refined to the surrounding density and faired (Liepa 2003), in the mesh's own coordinates.
//
// Every hole is computed on a detached patch first and written to the mesh only when all of
// them are done, so an exception (invalid input, cancellation) leaves the mesh untouched.
#pragma once

#include "flat_base.h"
#include "hole_fairing.h"
#include "hole_loops.h"
#include "hole_refinement.h"
#include "hole_triangulation.h"
#include "mesh_checks.h"
#include "parallel_for.h"
#include "unit_box.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/selection.h>
#include <wrap/callback.h>

#include <chrono>
#include <string>
#include <unordered_map>
#include <vector>

namespace vcg_ext {

struct CoarseFillParams {
  int max_hole_edges = 0; ///< holes with more boundary edges stay open; 0 = fill all
  /// Holes whose border spans more than this fraction of the mesh's bounding-box diagonal
  /// stay open; 0 = fill all.
  double max_hole_diameter = 0;
  bool keep_longest_open = false; ///< leave the longest loop (an open scan's border) open
  bool selected_only = false;     ///< fill only holes with a selected face on their border
  int dp_max_edges = 200;         ///< larger loops use vcglib's ears instead of Liepa's O(n^3) DP
  bool refine = true;             ///< match the surrounding edge density
  double density_alpha = 1.41421356; ///< Liepa's alpha: larger gives a denser fill
  bool fair = true;                  ///< bi-Laplacian fairing of the inserted vertices
  /// A planar loop whose surroundings meet its plane at a crease (the cut bottom of a statue,
  /// a window), or a cut base (IsFlatBase), is closed by a flat membrane instead of a thin
  /// plate, which would bulge to continue the walls around it.
  bool flat_planar_caps = true;
  bool select_new_faces = true; ///< replace the face selection with the new faces
  int threads = 0;              ///< holes filled at once; 0: one per core
};

/// Throws InvalidParameterError naming the first parameter out of its range.
inline void CheckCoarseFillParams(const CoarseFillParams& p) {
  RequireRange(p.max_hole_edges, 0, 1e9, "the maximum hole size (edges)");
  RequireRange(p.max_hole_diameter, 0, 1e9, "the maximum hole diameter");
  // Liepa's triangulation is cubic in the loop's length: beyond this it would take minutes.
  RequireRange(p.dp_max_edges, 3, 1000, "the largest hole for the optimal triangulation");
  RequireRange(p.density_alpha, 0.1, 10, "the refinement density");
  RequireRange(p.threads, 0, 1024, "the thread count");
}

/// What the coarse fill did with one hole.
struct CoarseHoleReport {
  int boundary_edges = 0;
  bool pinched = false; ///< the loop was split at a non-manifold vertex
  bool filled = false;
  std::string triangulation; ///< "liepa-dp" or "vcg-ears"
  bool faired = false;
  bool planar_cap = false; ///< closed flat (IsPlanarCap, IsFlatBase) rather than as a thin plate
  std::string problem;     ///< why the hole stayed open or was not faired; empty if none
  double seconds = 0;
  std::vector<int> loop;         ///< the loop's vertex indices in the mesh
  std::vector<int> new_vertices; ///< indices in m.vert of the vertices added for this hole
  std::vector<int> new_faces;    ///< indices in m.face of the faces added for this hole
};

struct CoarseFillResult {
  std::vector<CoarseHoleReport> holes; ///< every hole considered, filled or not
  int skipped_by_size = 0;
  int skipped_by_selection = 0;
  int kept_as_border = 0;        ///< the longest loop, left open by keep_longest_open
  size_t inconsistent_edges = 0; ///< edges whose faces disagree on orientation (left as is)
  UnitBox box;
  int FilledCount() const {
    int c = 0;
    for (const auto& h : holes) c += h.filled;
    return c;
  }
};

namespace detail {

/// Collects, for every hole, the mesh faces around its loop in local indices (one pass over
/// the faces for all holes together).
template <class MeshType>
std::vector<HoleCollar> BuildCollars(const MeshType& m, const std::vector<HoleLoop>& holes,
                                     const UnitBox& box) {
  std::unordered_map<int, std::vector<std::pair<int, int>>> on_loop; // vertex -> (hole, local)
  for (int h = 0; h < int(holes.size()); ++h)
    for (int i = 0; i < holes[h].EdgeCount(); ++i) on_loop[holes[h].vertices[i]].push_back({h, i});

  std::vector<std::vector<int>> faces(holes.size());
  for (int f = 0; f < int(m.face.size()); ++f) {
    if (m.face[f].IsD()) continue;
    for (int k = 0; k < 3; ++k) {
      auto it = on_loop.find(int(vcg::tri::Index(m, m.face[f].cV(k))));
      if (it == on_loop.end()) continue;
      for (const auto& hl : it->second)
        if (faces[hl.first].empty() || faces[hl.first].back() != f) faces[hl.first].push_back(f);
    }
  }

  std::vector<HoleCollar> collars(holes.size());
  for (int h = 0; h < int(holes.size()); ++h) {
    const HoleLoop& loop = holes[h];
    const int n = loop.EdgeCount();
    HoleCollar& c = collars[h];
    std::unordered_map<int, int> local; // mesh vertex -> collar index (>= 0 loop, < 0 outer)
    for (int i = 0; i < n; ++i) local[loop.vertices[i]] = i;
    std::vector<Eigen::Vector3d> loop_points(n);
    for (int i = 0; i < n; ++i) loop_points[i] = box.ToUnit(m.vert[loop.vertices[i]].cP());
    c.edge_scale.assign(n, 0.0);
    std::vector<int> edge_count(n, 0);
    for (int f : faces[h]) {
      std::array<int, 3> t;
      for (int k = 0; k < 3; ++k) {
        const int v = int(vcg::tri::Index(m, m.face[f].cV(k)));
        auto it = local.find(v);
        if (it == local.end()) {
          c.outer_points.push_back(box.ToUnit(m.vert[v].cP()));
          it = local.emplace(v, -int(c.outer_points.size())).first;
        }
        t[k] = it->second;
      }
      if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) continue; // degenerate face
      c.triangles.push_back(t);
      auto point = [&](int i) { return i >= 0 ? loop_points[i] : c.outer_points[-i - 1]; };
      for (int k = 0; k < 3; ++k) {
        const int a = t[k], b = t[(k + 1) % 3];
        const double len = (point(a) - point(b)).norm();
        for (int e : {a, b})
          if (e >= 0) c.edge_scale[e] += len, ++edge_count[e];
      }
    }
    for (int i = 0; i < n; ++i)
      if (edge_count[i] > 0) c.edge_scale[i] /= edge_count[i];
    c.side_normals.resize(n);
    for (int i = 0; i < n; ++i) {
      const auto& f = m.face[loop.faces[i]];
      c.side_normals[i] = TriangleNormal(box.ToUnit(f.cV(0)->cP()), box.ToUnit(f.cV(1)->cP()),
                                         box.ToUnit(f.cV(2)->cP()))
                              .normalized();
      if (!loop.face_agrees[i]) c.side_normals[i] = -c.side_normals[i];
      if (!c.side_normals[i].allFinite()) c.side_normals[i].setZero();
    }
  }
  return collars;
}

/// Loops up to this size fall back to the dynamic programme when the ears fail.
constexpr int kDpFallbackMaxEdges = 600;
/// Fills with more inserted vertices are faired by one solve only.
constexpr int kIteratedFairingMaxVertices = 20000;

/// Whether a loop (`plane`: its FitLoopPlane) is planar (within 0.5 % of its size) and the faces
/// beside it either lie in its plane (within 0.25 degrees on average) or leave it at a crease (more
/// than 35 degrees): then the missing surface is a flat cap, which a membrane reproduces exactly
/// and a thin plate would bulge to continue the walls. In between, the surroundings curve smoothly
/// into the hole (a small hole on a sphere has a planar loop too) and the thin plate is right: on
/// the fandisk's gently curved faces the sides tilt about 0.9 degrees, a flat face's 0.01.
inline bool IsPlanarCap(const LoopPlane& plane, const std::vector<Eigen::Vector3d>& side_normals) {
  double alignment = 0;
  for (const auto& n : side_normals) alignment += std::abs(n.dot(plane.normal));
  alignment /= double(side_normals.size());
  const bool crease = alignment < std::cos(35 * M_PI / 180);
  const bool coplanar = alignment > std::cos(0.25 * M_PI / 180);
  return plane.off_plane <= 0.005 * plane.size && (crease || coplanar);
}

/// Builds one hole's patch: triangulation, refinement, fairing; `flat_cap`: closed by a flat
/// membrane (IsPlanarCap, IsFlatBase).
inline HolePatch FillOneHole(const std::vector<Eigen::Vector3d>& loop_points,
                             const HoleCollar& collar, bool flat_cap,
                             const CoarseFillParams& params, CoarseHoleReport& report) {
  const int n = int(loop_points.size());
  HolePatch patch;
  patch.boundary_count = n;
  patch.points = loop_points;
  auto point = [&](int i) { return i >= 0 ? loop_points[i] : collar.outer_points[-i - 1]; };
  std::vector<Eigen::Vector3d> vertex_normals(n, Eigen::Vector3d::Zero());
  for (const auto& t : collar.triangles) {
    const Eigen::Vector3d nt = TriangleNormal(point(t[0]), point(t[1]), point(t[2]));
    for (int k = 0; k < 3; ++k) {
      if (t[k] >= 0) vertex_normals[t[k]] += nt;
      const int a = t[k], b = t[(k + 1) % 3];
      if (a >= 0 && b >= 0 && !patch.IsBoundaryEdge(a, b))
        patch.forbidden_edges.insert(MakeLocalEdge(a, b));
    }
  }
  for (auto& vn : vertex_normals)
    if (vn.norm() > 0) vn.normalize();

  // A planar cap ends up flat whatever its initial triangulation (the benchmark's falcon
  // bottom: the same distances either way), so it takes the fast ears.
  report.planar_cap = flat_cap;
  HoleTriangulationParams tp;
  tp.dp_max_edges = report.planar_cap ? 0 : params.dp_max_edges;
  HoleTriangulation tri =
      TriangulateHole(loop_points, collar.side_normals, vertex_normals, patch.forbidden_edges, tp);
  // The ears can get stuck on a contorted loop; the dynamic programme never does, and up to a
  // few hundred edges it still takes well under a second.
  if (!tri.complete && n <= kDpFallbackMaxEdges && n > tp.dp_max_edges)
    tri = detail::LiepaTriangulation(loop_points, collar.side_normals, patch.forbidden_edges);
  report.triangulation = tri.method;
  if (!tri.complete) {
    report.problem = "no valid triangulation of the loop was found";
    return patch;
  }
  patch.triangles = tri.triangles;
  if (params.refine) {
    HoleRefinementParams rp;
    rp.alpha = params.density_alpha;
    RefineHolePatch(patch, collar.edge_scale, rp);
  } else {
    RelaxHolePatch(patch);
  }
  for (const auto& t : patch.triangles)
    for (int k = 0; k < 3; ++k)
      if (patch.forbidden_edges.count(MakeLocalEdge(t[k], t[(k + 1) % 3]))) {
        report.problem = "every triangulation would duplicate an edge of the mesh";
        patch.triangles.clear();
        return patch;
      }
  report.filled = true;
  if (params.fair && patch.NewVertexCount() > 0) {
    HoleFairingParams fp;
    if (report.planar_cap) fp.order = 1, fp.iterations = 1; // weights cannot bend a plane
    // Re-estimating the weights costs a factorisation each time: on very large fills (tens of
    // thousands of inserted vertices) the first solve has to do.
    if (patch.NewVertexCount() > kIteratedFairingMaxVertices) fp.iterations = 1;
    report.faired = FairHolePatch(patch, collar, fp);
    if (!report.faired) report.problem = "fairing failed on a degenerate neighbourhood; kept flat";
  }
  return patch;
}

template <class MeshType>
void ApplyPatches(MeshType& m, const std::vector<HoleLoop>& loops,
                  const std::vector<HolePatch>& patches, const UnitBox& box,
                  const CoarseFillParams& params, std::vector<CoarseHoleReport>& reports) {
  using VertexType = typename MeshType::VertexType;
  using ScalarType = typename MeshType::ScalarType;
  size_t nv = 0, nf = 0;
  for (size_t h = 0; h < patches.size(); ++h)
    if (reports[h].filled) nv += patches[h].NewVertexCount(), nf += patches[h].triangles.size();
  if (params.select_new_faces) vcg::tri::UpdateSelection<MeshType>::FaceClear(m);
  if (nf == 0) return;

  const size_t v_base = m.vert.size();
  const size_t f_base = m.face.size();
  vcg::tri::Allocator<MeshType>::AddVertices(m, nv);
  vcg::tri::Allocator<MeshType>::AddFaces(m, nf);
  size_t vnext = v_base, fnext = f_base;
  for (size_t h = 0; h < patches.size(); ++h) {
    if (!reports[h].filled) continue;
    const HolePatch& patch = patches[h];
    const HoleLoop& loop = loops[h];
    std::vector<int> global(patch.points.size());
    for (int i = 0; i < patch.boundary_count; ++i) global[i] = loop.vertices[i];
    for (int i = patch.boundary_count; i < int(patch.points.size()); ++i) {
      const int g = int(vnext++);
      global[i] = g;
      reports[h].new_vertices.push_back(g);
      VertexType& v = m.vert[g];
      v.P() = box.FromUnit<ScalarType>(patch.points[i]);
      // Interpolate colour and quality from the triangle the vertex was inserted into.
      const auto& par = patch.parents[i - patch.boundary_count];
      if (vcg::tri::HasPerVertexColor(m)) {
        int sum[4] = {0, 0, 0, 0};
        for (int p : par)
          for (int c = 0; c < 4; ++c) sum[c] += m.vert[global[p]].C()[c];
        for (int c = 0; c < 4; ++c) v.C()[c] = (unsigned char)((sum[c] + 1) / 3);
      }
      if (vcg::tri::HasPerVertexQuality(m)) {
        double q = 0;
        for (int p : par) q += m.vert[global[p]].Q();
        v.Q() = typename VertexType::QualityType(q / 3);
      }
      if (vcg::tri::HasPerVertexNormal(m)) v.N().SetZero();
    }
    const auto& side = m.face[loop.faces[0]];
    for (const auto& t : patch.triangles) {
      const int g = int(fnext++);
      reports[h].new_faces.push_back(g);
      auto& f = m.face[g];
      for (int k = 0; k < 3; ++k) f.V(k) = &m.vert[global[t[k]]];
      if (vcg::tri::HasPerFaceColor(m)) f.C() = side.cC();
      if (vcg::tri::HasPerFaceQuality(m)) f.Q() = side.cQ();
      const auto area_normal = vcg::TriangleNormal(f);
      if (vcg::tri::HasPerFaceNormal(m)) f.N() = vcg::Point3<ScalarType>(area_normal).Normalize();
      if (vcg::tri::HasPerVertexNormal(m))
        for (int k = 0; k < 3; ++k)
          if (global[t[k]] >= int(v_base)) f.V(k)->N() += area_normal;
      if (params.select_new_faces) f.SetS();
    }
  }
  if (vcg::tri::HasPerVertexNormal(m))
    for (size_t g = v_base; g < m.vert.size(); ++g) m.vert[g].N().Normalize();
}

} // namespace detail

/// Fills the holes of `m` (stages 0-2 of the pipeline).
///
/// Preconditions, checked before anything is written (InvalidMeshError otherwise): at least
/// one face, finite coordinates, every edge shared by at most two faces; parameters in their
/// ranges (InvalidParameterError otherwise).
/// Loops are split at pinch vertices. Holes that cannot be closed without a non-manifold edge
/// stay open and say why in their report. Existing vertices and faces keep their positions and
/// attributes; new vertices interpolate colour and quality. `cb` receives progress; returning
/// false cancels (CancelledError) with the mesh untouched.
template <class MeshType>
CoarseFillResult CoarseFill(MeshType& m, const CoarseFillParams& params = {},
                            vcg::CallBackPos* cb = nullptr) {
  CheckCoarseFillParams(params);
  const EdgeCensus census = ValidateForHoleFilling(m);
  HoleLoopParams lp;
  lp.max_edges = params.max_hole_edges;
  lp.selected_only = params.selected_only;
  lp.keep_longest_open = params.keep_longest_open;
  if (params.max_hole_diameter > 0) {
    vcg::tri::UpdateBounding<MeshType>::Box(m);
    lp.max_diameter = params.max_hole_diameter * double(m.bbox.Diag());
  }
  const HoleLoops loops = FindHoleLoops(m, census, lp);

  CoarseFillResult result;
  result.skipped_by_size = loops.skipped_by_size;
  result.skipped_by_selection = loops.skipped_by_selection;
  result.kept_as_border = loops.kept_as_border;
  result.inconsistent_edges = census.inconsistent_edges;
  result.box = ComputeUnitBox(m);
  const std::vector<HoleCollar> collars = detail::BuildCollars(m, loops.holes, result.box);

  const int count = int(loops.holes.size());
  result.holes.resize(count);
  std::vector<HolePatch> patches(count);
  // Each hole is filled on its own detached patch, so the holes are independent: fill them
  // on params.threads threads. The callback is called from this thread only (MeshLab's
  // updates its GUI).
  auto fill = [&](int h) {
    const auto start = std::chrono::steady_clock::now();
    const HoleLoop& loop = loops.holes[h];
    CoarseHoleReport& report = result.holes[h];
    report.boundary_edges = loop.EdgeCount();
    report.pinched = loop.pinched;
    report.loop = loop.vertices;
    std::vector<Eigen::Vector3d> points(loop.EdgeCount());
    for (int i = 0; i < loop.EdgeCount(); ++i)
      points[i] = result.box.ToUnit(m.vert[loop.vertices[i]].cP());
    // A cut base shows in the surface beyond the collar, so it is read from the mesh (read
    // only until every hole is done), and only where the loop alone does not decide.
    const LoopPlane plane = FitLoopPlane(points);
    const auto& sides = collars[h].side_normals;
    const bool flat_cap =
        params.fair && params.flat_planar_caps &&
        (detail::IsPlanarCap(plane, sides) || IsFlatBase(m, plane, points, sides, result.box));
    patches[h] = detail::FillOneHole(points, collars[h], flat_cap, params, report);
    report.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  // The holes another thread fills are counted while this one waits for them: a large hole
  // there can take most of the time.
  auto report = [&](int done) {
    if (!cb) return true;
    const std::string msg =
        "Coarse fill: hole " + std::to_string(done) + " of " + std::to_string(count);
    return cb(int(100.0 * done / std::max(count, 1)), msg.c_str());
  };
  ParallelFor(count, params.threads, fill, report);
  // Two loops meeting at pinch vertices could both add the same chord between them: the
  // first in loop order keeps it.
  std::set<std::pair<int, int>> chords;
  for (int h = 0; h < count; ++h) {
    const HoleLoop& loop = loops.holes[h];
    CoarseHoleReport& report = result.holes[h];
    if (!report.filled || !loop.pinched) continue;
    std::vector<std::pair<int, int>> mine;
    for (const auto& t : patches[h].triangles)
      for (int k = 0; k < 3; ++k) {
        const int a = t[k], b = t[(k + 1) % 3];
        if (a < loop.EdgeCount() && b < loop.EdgeCount() && !patches[h].IsBoundaryEdge(a, b))
          mine.push_back(std::minmax(loop.vertices[a], loop.vertices[b]));
      }
    bool clash = false;
    for (const auto& c : mine) clash = clash || chords.count(c) > 0;
    if (clash) {
      report.filled = false;
      report.problem = "its fill would share an edge with the fill of a neighbouring hole";
    } else {
      chords.insert(mine.begin(), mine.end());
    }
  }
  detail::ApplyPatches(m, loops.holes, patches, result.box, params, result.holes);
  return result;
}

} // namespace vcg_ext
