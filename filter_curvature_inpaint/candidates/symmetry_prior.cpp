#include "candidates/symmetry_prior.h"

#include "pipeline/pipeline.h"

#include <vcg_ext/fill_extent.h>

#include <QString>

#include <algorithm>
#include <chrono>
#include <sstream>

namespace curvature_inpaint {

namespace {

/// The planes a hole may mirror across: the accepted ones, then the partial symmetries.
std::vector<vcg_ext::SymmetryPlane> UsablePlanes(const SymmetryPrior& prior) {
  std::vector<vcg_ext::SymmetryPlane> planes = prior.planes;
  planes.insert(planes.end(), prior.partial.begin(), prior.partial.end());
  return planes;
}

} // namespace

std::unique_ptr<SymmetryPrior> DetectSymmetry(const CMeshO& m,
                                              const vcg_ext::CoarseFillResult& coarse,
                                              const vcg_ext::SymmetryParams& params) {
  const auto start = std::chrono::steady_clock::now();
  auto prior = std::make_unique<SymmetryPrior>();
  prior->box = coarse.box;
  const ScanPart scan = ScanPartOf(m, coarse);
  const size_t scan_vertices = scan.vertices, scan_faces = scan.faces;
  std::vector<Eigen::Vector3d> normal(scan_vertices, Eigen::Vector3d::Zero());
  for (size_t f = 0; f < scan_faces; ++f) {
    const auto& face = m.face[f];
    if (face.IsD()) continue;
    const Eigen::Vector3d a = coarse.box.ToUnit(face.cP(0)), b = coarse.box.ToUnit(face.cP(1)),
                          c = coarse.box.ToUnit(face.cP(2));
    const Eigen::Vector3d n = (b - a).cross(c - a); // area-weighted
    for (int k = 0; k < 3; ++k) {
      const size_t v = size_t(vcg::tri::Index(m, face.cV(k)));
      if (v < scan_vertices) normal[v] += n;
    }
  }
  for (size_t v = 0; v < scan_vertices; ++v) {
    if (m.vert[v].IsD() || !(normal[v].norm() > 0)) continue;
    prior->points.push_back(coarse.box.ToUnit(m.vert[v].cP()));
    prior->normals.push_back(normal[v].normalized());
  }
  if (!prior->points.empty()) {
    prior->index = std::make_unique<vcg_ext::PointIndex>(prior->points);
    prior->planes = vcg_ext::DetectReflectiveSymmetry(*prior->index, prior->normals, params,
                                                      &prior->best, &prior->partial);
  }
  prior->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return prior;
}

std::vector<vcg_ext::SymmetryPlane> MirrorPlanesInMeshUnits(const SymmetryPrior& prior) {
  // n . u = d with u = (x - origin) scale is n . x = d / scale + n . origin.
  std::vector<vcg_ext::SymmetryPlane> planes = UsablePlanes(prior);
  for (auto& p : planes) p.offset = p.offset / prior.box.scale + p.normal.dot(prior.box.origin);
  return planes;
}

std::string DescribeSymmetry(const std::vector<vcg_ext::SymmetryPlane>& planes,
                             const vcg_ext::SymmetryPlane& best,
                             const std::vector<vcg_ext::SymmetryPlane>& partial) {
  auto plane = [](const vcg_ext::SymmetryPlane& p) {
    std::ostringstream o;
    o << "plane (" << QString::number(p.normal.x(), 'f', 3).toStdString() << ", "
      << QString::number(p.normal.y(), 'f', 3).toStdString() << ", "
      << QString::number(p.normal.z(), 'f', 3).toStdString()
      << ") . x = " << QString::number(p.offset, 'f', 4).toStdString() << " mirrors "
      << int(std::lround(100 * p.coverage)) << " % of the scan onto itself (RMS "
      << QString::number(100 * p.residual, 'f', 2).toStdString() << " % of the box)";
    return o.str();
  };
  std::ostringstream o;
  o << "symmetry: ";
  if (planes.empty() && partial.empty()) o << "none; the best " << plane(best);
  if (planes.empty() && !partial.empty()) o << "none of the whole object";
  for (size_t k = 0; k < planes.size(); ++k) o << (k ? "; " : "") << plane(planes[k]);
  if (!partial.empty()) o << "; partial, for the holes whose surroundings it mirrors: ";
  for (size_t k = 0; k < partial.size(); ++k) o << (k ? "; " : "") << plane(partial[k]);
  return o.str();
}

vcg_ext::MirroredFill MirrorHole(const SymmetryPrior& prior, const vcg_ext::PatchMesh& patch,
                                 const std::vector<char>& free, const vcg_ext::UnitBox& frame,
                                 const vcg_ext::MirroredFillParams& params,
                                 const Eigen::Vector3d& excluded_centre, double excluded_radius) {
  vcg_ext::MirroredFill best;
  best.problem = "the object has no symmetry plane";
  const std::vector<vcg_ext::SymmetryPlane> planes = UsablePlanes(prior);
  if (!prior.index || planes.empty()) return best;
  // The patch in the prior's unit box (both boxes are similarities of the mesh's units).
  auto to_prior = [&](const Eigen::Vector3d& u) {
    return Eigen::Vector3d(((u / frame.scale + frame.origin) - prior.box.origin) * prior.box.scale);
  };
  auto to_frame = [&](const Eigen::Vector3d& u) {
    return Eigen::Vector3d(((u / prior.box.scale + prior.box.origin) - frame.origin) * frame.scale);
  };
  std::vector<Eigen::Vector3d> points(patch.points.size());
  for (size_t i = 0; i < points.size(); ++i) points[i] = to_prior(patch.points[i]);
  Eigen::Vector3d centre;
  double radius = 0;
  if (!vcg_ext::FillExtent(points, free, &centre, &radius)) {
    best.problem = "the hole has no fill";
    return best;
  }
  vcg_ext::KnownSurface known;
  known.index = prior.index.get();
  known.normals = &prior.normals;
  known.excluded_centre = (excluded_centre - prior.box.origin) * prior.box.scale;
  known.excluded_radius = excluded_radius * prior.box.scale;
  // The planes best covering the object first, the partial symmetries after them: a hole's
  // ring alone (often plain surface that many planes map onto plain surface) cannot tell the
  // object's symmetry from a chance one.
  for (size_t k = 0; k < planes.size(); ++k) {
    vcg_ext::MirroredFill f =
        vcg_ext::MirrorFill(points, patch.triangles, free, planes[k], known, radius, params);
    if (k == 0 || !f.problem.empty()) best.problem = f.problem;
    if (!f.problem.empty()) continue;
    for (auto& p : f.points) p = to_frame(p);
    return f;
  }
  return best;
}

} // namespace curvature_inpaint
