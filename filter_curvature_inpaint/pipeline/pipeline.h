// The pipeline both front ends call: the MeshLab plugin and the curvature-inpaint tool.
// Stages live in vcg_ext/; this layer binds them to MeshLab's mesh type and turns their
// results into the log lines users read.
#pragma once

#include "pipeline/meshlab_mesh.h"
#include <vcg_ext/coarse_fill.h>

#include <string>
#include <vector>

namespace curvature_inpaint {

/// Stages 0-2 on a MeshLab mesh: fills its holes and updates its bounding box.
/// Throws vcg_ext::InvalidMeshError or vcg_ext::CancelledError with `m` untouched.
vcg_ext::CoarseFillResult CoarseFill(CMeshO& m, const vcg_ext::CoarseFillParams& params,
                                     vcg::CallBackPos* cb = nullptr);

/// Remembers what the coarse fill is about to append (it only appends vertices and faces and
/// replaces the face selection), so a later stage's failure can take it back out exactly.
class MeshCheckpoint {
public:
  explicit MeshCheckpoint(CMeshO& m);
  void Restore();

private:
  CMeshO& m_;
  size_t vn_, fn_;
  std::vector<char> selected_;
};

/// Copies what the fill reads (live vertices and faces, positions, face selection) into
/// `to`, compacted and in the same order: the fill of the copy equals the fill of `from`.
void CopyMesh(const CMeshO& from, CMeshO& to);

/// How much of `m` is the scan's after its coarse fill `coarse`: the fill only appends, so
/// the vertices and faces before these counts are the scan's own.
struct ScanPart {
  size_t vertices = 0, faces = 0;
};
ScanPart ScanPartOf(const CMeshO& m, const vcg_ext::CoarseFillResult& coarse);

/// One line per hole, then a summary line.
std::vector<std::string> DescribeCoarseFill(const vcg_ext::CoarseFillResult& result);

/// Boundary loops of a mesh, by size: for reports and for tests of watertightness.
struct HoleCensus {
  int vertices = 0;
  int faces = 0;
  std::vector<int> loop_edges;   ///< boundary edges of each loop, largest first
  size_t non_manifold_edges = 0; ///< edges with three or more faces
  size_t inconsistent_edges = 0; ///< edges whose two faces disagree on orientation
};
HoleCensus CountHoles(const CMeshO& m);

/// One boundary loop as `info` shows it.
struct HoleSummary {
  int number = 0;      ///< as the fill numbers it (1-based); 0: the selection leaves it open
  int edges = 0;       ///< boundary edges
  double diameter = 0; ///< diagonal of the loop's bounding box, in the mesh's units
  vcg::Point3d centre{0, 0, 0}; ///< mean of the loop's vertices
};

/// Every boundary loop of `m`, in the order the coarse fill (and so every later stage) numbers
/// the holes it fills with `selection`'s hole options. Empty if `m` has non-manifold edges.
std::vector<HoleSummary> ListHoles(const CMeshO& m, const vcg_ext::CoarseFillParams& selection);

} // namespace curvature_inpaint
