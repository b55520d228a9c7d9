// The meshes and helpers the tests of the whole method share: builders of MeshLab meshes with
// holes whose truth is known, the fills compared with it, and the settings that keep them small.
#pragma once

#include "inpaint/curvature_reading.h"
#include "io/mesh_io.h"
#include "pipeline/fill_one_hole.h"
#include "pipeline/hole_fill.h"
#include "pipeline/pipeline.h"
#include "report/hole_report.h"
#include "validation/fake_holes.h"

#include <vcg/complex/algorithms/create/platonic.h>
#include <vcg/simplex/face/distance.h>
#include <vcg_ext/curvature_colormap.h>
#include <vcg_ext/mesh_errors.h>
#include <vcg_ext/punch_hole.h>

#include <gtest/gtest.h>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <ostream>
#include <string>

namespace curvature_inpaint {

// gtest prints the kinds by their names.
inline void PrintTo(FillKind kind, std::ostream* os) {
  *os << FillKindName(kind);
}
inline void PrintTo(const TriedFill& fill, std::ostream* os) {
  *os << TriedFillName(fill);
}

} // namespace curvature_inpaint

namespace fixtures {

using curvature_inpaint::FillHoles;
using curvature_inpaint::HoleFillParams;

/// A hole's validation as the log gives it: what a failed expectation on its choice shows.
inline std::string Validation(const curvature_inpaint::HoleFillReport& r) {
  return curvature_inpaint::DescribeValidation(r.choice.validation);
}

// Bumps whose tip curvature (1 + 2 h / w^2) the colour map's range can hold.
const double kBumpHeight = 0.025, kBumpWidth = 0.2;

/// Directions of the bumps: three close together (the hole's), the rest spread.
inline std::vector<Eigen::Vector3d> BumpDirections() {
  std::vector<Eigen::Vector3d> d{{1, 0.2, 0}, {1, -0.1, 0.18}, {1, -0.1, -0.18},
                                 {0, 1, 0},   {0, -1, 0},      {0, 0, 1},
                                 {0, 0, -1},  {-1, 0, 0},      {-0.5, 0.7, 0.5}};
  for (auto& x : d) x.normalize();
  return d;
}

/// Unit sphere carrying Gaussian bumps of height kBumpHeight (radially).
inline void MakeBumpySphere(CMeshO& m, int subdiv = 5) {
  vcg::tri::Sphere(m, subdiv);
  for (auto& v : m.vert) {
    const Eigen::Vector3d p = Eigen::Vector3d(v.P()[0], v.P()[1], v.P()[2]).normalized();
    double r = 1;
    for (const auto& d : BumpDirections())
      r += kBumpHeight * std::exp(-(p - d).squaredNorm() / (kBumpWidth * kBumpWidth));
    v.P() = Point3m(Scalarm(r * p.x()), Scalarm(r * p.y()), Scalarm(r * p.z()));
  }
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
  vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
}

inline HoleFillParams SmallImages() {
  HoleFillParams p;
  p.images.image_size = 256;
  p.inpaint.variations = 2;
  p.measure_detail = true;
  return p;
}

/// Distance from p to triangle abc, as a brute force would measure it: to its plane where the
/// foot lies inside it, else to the nearest of its edges.
inline double DistanceToTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                 const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d n = (b - a).cross(c - a).normalized();
  const Eigen::Vector3d foot = p - (p - a).dot(n) * n;
  const bool inside = (b - a).cross(foot - a).dot(n) >= 0 && (c - b).cross(foot - b).dot(n) >= 0 &&
                      (a - c).cross(foot - c).dot(n) >= 0;
  if (inside) return (p - foot).norm();
  auto to_edge = [&p](const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
    const double s = std::max(0.0, std::min(1.0, (p - u).dot(v - u) / (v - u).squaredNorm()));
    return (p - (u + s * (v - u))).norm();
  };
  return std::min({to_edge(a, b), to_edge(b, c), to_edge(c, a)});
}

/// A closed surface of revolution about the z axis, radius `profile(z)` for z in [0, length]
/// (poles at both ends), `rings` rings of `around` vertices, faces facing out.
template <class Profile>
inline void MakeRevolved(CMeshO& m, double length, int rings, int around, Profile profile) {
  vcg::tri::Allocator<CMeshO>::AddVertices(m, size_t(rings * around + 2));
  for (int k = 0; k < rings; ++k)
    for (int j = 0; j < around; ++j) {
      const double z = length * (k + 1) / (rings + 1), a = 2 * M_PI * j / around;
      m.vert[size_t(k * around + j)].P() =
          Point3m(Scalarm(profile(z) * std::cos(a)), Scalarm(profile(z) * std::sin(a)), Scalarm(z));
    }
  const size_t bottom = size_t(rings * around), top = bottom + 1;
  m.vert[bottom].P() = Point3m(0, 0, 0);
  m.vert[top].P() = Point3m(0, 0, Scalarm(length));
  auto at = [&](int k, int j) { return &m.vert[size_t(k * around + (j % around))]; };
  auto add = [&](CVertexO* a, CVertexO* b, CVertexO* c) {
    auto f = vcg::tri::Allocator<CMeshO>::AddFaces(m, 1);
    f->V(0) = a, f->V(1) = b, f->V(2) = c;
  };
  for (int j = 0; j < around; ++j) {
    add(&m.vert[bottom], at(0, j + 1), at(0, j));
    add(&m.vert[top], at(rings - 1, j), at(rings - 1, j + 1));
    for (int k = 0; k + 1 < rings; ++k) {
      add(at(k, j), at(k, j + 1), at(k + 1, j + 1));
      add(at(k, j), at(k + 1, j + 1), at(k + 1, j));
    }
  }
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
}

/// The cells of the cube [-1, 1]^3 split into n^3 that `solid` (of i, j, k in 0..n-1) keeps, as
/// a mesh: each square between a kept cell and one that is not split into two triangles,
/// outward.
template <class Solid>
inline void MakeBlock(CMeshO& m, int n, Solid solid) {
  auto kept = [&](int i, int j, int k) {
    return i >= 0 && j >= 0 && k >= 0 && i < n && j < n && k < n && solid(i, j, k);
  };
  std::map<std::array<int, 3>, int> index; // grid coordinates (0..n) -> vertex
  std::vector<Point3m> points;
  std::vector<std::array<int, 3>> faces;
  auto vertex = [&](const std::array<int, 3>& g) {
    const auto it = index.find(g);
    if (it != index.end()) return it->second;
    points.emplace_back(Scalarm(2.0 * g[0] / n - 1), Scalarm(2.0 * g[1] / n - 1),
                        Scalarm(2.0 * g[2] / n - 1));
    return index[g] = int(points.size()) - 1;
  };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        if (!kept(i, j, k)) continue;
        for (size_t axis = 0; axis < 3; ++axis)
          for (int side : {0, 1}) {
            std::array<int, 3> cell{i, j, k};
            cell[axis] += side ? 1 : -1;
            if (kept(cell[0], cell[1], cell[2])) continue;
            // The square between the cell and its empty neighbour; (u, w) follow the axis
            // cyclically, so a, b, c turn about +axis.
            const size_t u = (axis + 1) % 3, w = (axis + 2) % 3;
            std::array<int, 3> a{i, j, k};
            a[axis] += side;
            std::array<int, 3> b = a, c = a, d = a;
            ++b[u], ++c[u], ++c[w], ++d[w];
            const int va = vertex(a), vb = vertex(b), vc = vertex(c), vd = vertex(d);
            if (side)
              faces.push_back({va, vb, vc}), faces.push_back({va, vc, vd});
            else
              faces.push_back({va, vc, vb}), faces.push_back({va, vd, vc});
          }
      }
  vcg::tri::BuildMeshFromCoordVectorIndexVector(m, points, faces);
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
  vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
}

/// The cube [-1, 1]^3, each face an n x n grid of squares split into two triangles, outward.
inline void MakeCube(CMeshO& m, int n) {
  MakeBlock(m, n, [](int, int, int) { return true; });
}

/// Fills the holes punched in `m` with the small images and without the mirror prior (the
/// boxes and the cylinder below are symmetric: their mirror image would restore what the prior
/// under test should), taking the variation of `pick_kind` where one is given (not kCoarse).
inline curvature_inpaint::HoleFillResult
FillWithoutSymmetry(CMeshO& m,
                    curvature_inpaint::FillKind pick_kind = curvature_inpaint::FillKind::kCoarse) {
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
  HoleFillParams p = SmallImages();
  p.symmetry.enabled = false;
  p.pick_kind = pick_kind;
  return FillHoles(m, p);
}

/// How many of the ways the validation tried are of `kind`.
inline long TriedOfKind(const curvature_inpaint::ValidationRecord& v,
                        curvature_inpaint::FillKind kind) {
  return std::count_if(v.candidates.begin(), v.candidates.end(),
                       [kind](const curvature_inpaint::TriedFill& c) { return c.kind == kind; });
}

/// The distance of each of `points` to the surface of `truth`, over `unit`.
inline std::vector<double> DistancesTo(const CMeshO& truth,
                                       const std::vector<Eigen::Vector3d>& points, double unit) {
  std::vector<double> distances;
  for (const Eigen::Vector3d& q : points) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& f : truth.face) {
      Eigen::Vector3d c[3];
      for (int k = 0; k < 3; ++k) c[k] = Eigen::Vector3d(f.cP(k)[0], f.cP(k)[1], f.cP(k)[2]);
      nearest = std::min(nearest, DistanceToTriangle(q, c[0], c[1], c[2]));
    }
    distances.push_back(nearest / unit);
  }
  return distances;
}

inline Eigen::Vector3d ToEigen(const Point3m& p) {
  return Eigen::Vector3d(double(p[0]), double(p[1]), double(p[2]));
}

/// The distance of each vertex of `m` from `first` on (a fill's) to the surface of `truth`,
/// over `unit`.
inline std::vector<double> FillErrors(const CMeshO& truth, const CMeshO& m, size_t first,
                                      double unit) {
  std::vector<Eigen::Vector3d> points;
  for (size_t v = first; v < m.vert.size(); ++v) points.push_back(ToEigen(m.vert[v].cP()));
  return DistancesTo(truth, points, unit);
}

} // namespace fixtures
