// A minimal VCG mesh type and the meshes the unit tests build, so the tests need no files.
#pragma once

#include <vcg/complex/algorithms/create/platonic.h>
#include <vcg/complex/complex.h>
#include <vcg_ext/edge_census.h>
#include <vcg_ext/hole_loops.h>
#include <vcg_ext/punch_hole.h>

namespace test {

class Vertex;
class Face;
struct Types : public vcg::UsedTypes<vcg::Use<Vertex>::AsVertexType, vcg::Use<Face>::AsFaceType> {};
class Vertex
    : public vcg::Vertex<Types, vcg::vertex::Coord3f, vcg::vertex::Normal3f, vcg::vertex::Color4b,
                         vcg::vertex::Qualityf, vcg::vertex::BitFlags> {};
class Face
    : public vcg::Face<Types, vcg::face::VertexRef, vcg::face::Normal3f, vcg::face::BitFlags> {};
class Mesh : public vcg::tri::TriMesh<std::vector<Vertex>, std::vector<Face>> {};

/// Icosphere of radius `r` (4 subdivisions: 2562 vertices).
inline void MakeSphere(Mesh& m, float r, int subdiv = 4) {
  m.Clear();
  vcg::tri::Sphere(m, subdiv);
  for (auto& v : m.vert) v.P() *= r;
}

/// Square grid of (n+1)^2 vertices in the plane z = 0, side `side`.
inline void MakePlane(Mesh& m, int n, float side) {
  vcg::tri::Grid(m, n + 1, n + 1, side, side);
}

/// Removes the faces with a vertex within `angle_deg`/2 (angular radius) of direction `dir` on
/// a sphere of radius `r` centred at the origin: a hole spanning `angle_deg`.
inline int PunchSphere(Mesh& m, vcg::Point3f dir, float r, float angle_deg) {
  const float half = float(0.5 * angle_deg * M_PI / 180.0);
  return vcg_ext::PunchHole(m, dir.Normalize() * r, 2 * r * std::sin(half / 2));
}

struct Topology {
  size_t boundary_edges = 0;
  size_t non_manifold_edges = 0;
  size_t loops = 0;
};

inline Topology Inspect(const Mesh& m) {
  const auto census = vcg_ext::CensusEdges(m);
  Topology t;
  t.boundary_edges = census.boundary.size();
  t.non_manifold_edges = census.non_manifold_edges + census.inconsistent_edges;
  if (t.non_manifold_edges == 0) t.loops = vcg_ext::FindHoleLoops(m, census).holes.size();
  return t;
}

} // namespace test

namespace test {

/// Quad grid wrapped in u (and in v when `closed_v`), point(u, v) in [0,1)^2, outward faces.
template <class F>
void MakeParametric(Mesh& m, int nu, int nv, bool closed_v, F point) {
  m.Clear();
  const int rows = closed_v ? nv : nv + 1;
  vcg::tri::Allocator<Mesh>::AddVertices(m, nu * rows);
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < nu; ++i) m.vert[j * nu + i].P() = point(double(i) / nu, double(j) / nv);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const int a = j * nu + i, b = j * nu + (i + 1) % nu;
      const int c = ((j + 1) % rows) * nu + (i + 1) % nu, d = ((j + 1) % rows) * nu + i;
      vcg::tri::Allocator<Mesh>::AddFace(m, &m.vert[a], &m.vert[b], &m.vert[c]);
      vcg::tri::Allocator<Mesh>::AddFace(m, &m.vert[a], &m.vert[c], &m.vert[d]);
    }
}

inline void MakeTorus(Mesh& m, float R, float r, int nu = 96, int nv = 48) {
  MakeParametric(m, nu, nv, true, [&](double u, double v) {
    const double a = 2 * M_PI * u, b = 2 * M_PI * v;
    return vcg::Point3f(float((R + r * std::cos(b)) * std::cos(a)),
                        float((R + r * std::cos(b)) * std::sin(a)), float(r * std::sin(b)));
  });
}

/// Open cylinder of radius r around z, from z = 0 to z = h.
inline void MakeCylinder(Mesh& m, float r, float h, int nu = 96, int nv = 48) {
  MakeParametric(m, nu, nv, false, [&](double u, double v) {
    const double a = 2 * M_PI * u;
    return vcg::Point3f(float(r * std::cos(a)), float(r * std::sin(a)), float(h * v));
  });
}

} // namespace test
