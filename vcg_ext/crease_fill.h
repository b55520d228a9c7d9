// A hole's fill that carries the creases running into it across: the known context around
// the hole is split at its sharp edges into smooth regions (a machined part's faces), each
// region is fitted with a quadric height field, and every fill vertex is moved onto the
// solid those surfaces bound (across a convex crease the intersection of the two faces'
// solids, across a concave one their union; where both senses meet, one formula of all of
// them, a top over a concave corner being the top intersected with the walls' union), the
// fill vertex nearest a corner where three of them meet onto it, and the fill vertices
// nearest a crease onto its line, so that fill edges run along it. Where two regions' surfaces
// meet, the crease comes back straight and sharp as the extension of both, even where the hole took
// all of it (a plate's corner edge); where three meet, a corner. Where one face surrounds the hole
// and a crease passes beside it (or, when asked, no crease at all), the fill is that face extended.
// A smooth cap (Liepa, CGAL, MeshLab) rounds them away.
#pragma once

#include "fill_extent.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace vcg_ext {

struct CreaseFillParams {
  double crease_angle = 30; ///< degrees between face normals across an edge that is a crease
  double smooth_angle = 15; ///< degrees under which neighbouring faces are one smooth region
  int min_region_faces = 8; ///< smaller regions (slivers along a crease) are ignored
  /// A region's fit may leave this RMS, in hole radii: what is not that smooth is no face of a
  /// machined part, and its extension would not predict the hole.
  double max_fit_residual = 0.02;
  /// Two faces with no crease edge between them beside the hole are paired from how their
  /// vertices within this many hole radii of its centre lie: farther out, past another crease,
  /// a face may run on beyond the other's surface (a top beside a wall that ends). Chosen on
  /// the development holes (docs/experiments.md, "The figures behind the defaults").
  double pairing_reach = 1.5;
  /// Rounds of umbrella smoothing of the fill's vertices over the solid's boundary (each to
  /// its neighbours' mean, then back onto the solid): they spread the vertices that the
  /// projection piles up on a crease's line. 0: none.
  int relax_rounds = 0;
  /// Where no crease runs into the hole, the one smooth face all around it, if it is one,
  /// extended across it (a hole inside a machined part's curved face). False: such a hole has
  /// no fill.
  bool face_without_crease = false;
};

struct CreaseFill {
  std::vector<Eigen::Vector3d> points; ///< the whole patch, fill vertices moved
  int regions = 0;                     ///< smooth regions meeting at the hole
  int crease_edges = 0; ///< sharp edges of the context; 0 where the fill is one face extended
  /// Of faces that meet at a crease: paired by its edges beside the hole, by how they lie
  /// near it, or by the solid's formula.
  int convex_pairs = 0, concave_pairs = 0;
  std::string problem; ///< why there is no fill; empty if there is one
};

namespace detail {

/// z = a x^2 + b xy + c y^2 + d x + e y + f over a frame (origin, u, v, n).
struct HeightField {
  Eigen::Vector3d origin, u, v, n;
  Eigen::Matrix<double, 6, 1> c = Eigen::Matrix<double, 6, 1>::Zero();
  double Height(const Eigen::Vector3d& p, double* z) const {
    const Eigen::Vector3d d = p - origin;
    const double x = d.dot(u), y = d.dot(v);
    *z = d.dot(n);
    return c[0] * x * x + c[1] * x * y + c[2] * y * y + c[3] * x + c[4] * y + c[5];
  }
  /// Signed distance along n from the surface (positive: on the side n points to).
  double Offset(const Eigen::Vector3d& p) const {
    double z = 0;
    const double h = Height(p, &z);
    return z - h;
  }
};

/// One face of a read-once formula of the faces' half-spaces: the solid is
/// `face op (the terms after it)`, the last term's face alone.
struct SolidTerm {
  size_t face;
  bool intersect; ///< convex creases with the rest (intersection); false: concave (union)
};

/// The faces that meet others (`sense`, nr x nr: > 0 convex, < 0 concave, 0 apart) as one
/// read-once formula, where the senses are mixed and the faces can be peeled off one by one,
/// each meeting the faces left at creases of one sense (fewest meetings first: a face that
/// meets only one other is peeled before the face it meets). Empty where the senses are all
/// alike (the pairs say it all) or no such order exists.
inline std::vector<SolidTerm> ReadOnceSolid(const std::vector<double>& sense, size_t nr) {
  std::vector<char> left(nr, 0);
  bool convex = false, concave = false;
  for (size_t a = 0; a < nr; ++a)
    for (size_t b = 0; b < nr; ++b) {
      if (a == b || sense[a * nr + b] == 0) continue;
      left[a] = 1;
      (sense[a * nr + b] > 0 ? convex : concave) = true;
    }
  if (!convex || !concave) return {};
  std::vector<SolidTerm> terms;
  size_t remaining = size_t(std::count(left.begin(), left.end(), 1));
  while (remaining > 1) {
    size_t pick = nr, pick_meetings = 0;
    bool pick_convex = false;
    for (size_t a = 0; a < nr; ++a) {
      if (!left[a]) continue;
      size_t meetings = 0, convex_meetings = 0;
      for (size_t b = 0; b < nr; ++b)
        if (b != a && left[b] && sense[a * nr + b] != 0)
          ++meetings, convex_meetings += sense[a * nr + b] > 0;
      if (meetings == 0 || (convex_meetings != 0 && convex_meetings != meetings)) continue;
      if (pick == nr || meetings < pick_meetings)
        pick = a, pick_meetings = meetings, pick_convex = convex_meetings > 0;
    }
    if (pick == nr) return {};
    terms.push_back({pick, pick_convex});
    left[pick] = 0;
    --remaining;
  }
  for (size_t a = 0; a < nr; ++a)
    if (left[a]) terms.push_back({a, true});
  return terms;
}

/// The formula's value at p (negative inside the solid: the faces' offsets combined by max
/// for an intersection, min for a union) and the face whose offset it is.
inline double SolidValue(const std::vector<SolidTerm>& terms,
                         const std::vector<HeightField>& fields, const Eigen::Vector3d& p,
                         size_t* deciding) {
  size_t k = terms.size() - 1;
  double value = fields[terms[k].face].Offset(p);
  *deciding = terms[k].face;
  while (k-- > 0) {
    const double own = fields[terms[k].face].Offset(p);
    if (terms[k].intersect ? own > value : own < value) value = own, *deciding = terms[k].face;
  }
  return value;
}

/// The cosine under which two faces' normals meet at a crease.
inline double CreaseCosine(const CreaseFillParams& params) {
  return std::cos(params.crease_angle * M_PI / 180);
}

/// A hole's patch as the crease fill reads it: the arrays it was given, each triangle's normal
/// in the coarse fill, the border's vertices and the fill's extent.
struct CreasePatch {
  const std::vector<Eigen::Vector3d>& points;
  const std::vector<std::array<int, 3>>& triangles;
  const std::vector<char>& is_fill; ///< per triangle
  const std::vector<char>& free;    ///< per vertex: the fill's
  std::vector<Eigen::Vector3d> normal;
  std::vector<char> on_border; ///< per vertex: of a fill triangle and not free
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 0;
};

/// The patch's normals and border. \pre the arrays are as FillAcrossCreases takes them.
inline CreasePatch MakeCreasePatch(const std::vector<Eigen::Vector3d>& points,
                                   const std::vector<std::array<int, 3>>& triangles,
                                   const std::vector<char>& is_fill,
                                   const std::vector<char>& free) {
  CreasePatch p{points, triangles, is_fill, free, {}, {}};
  p.normal.resize(triangles.size());
  for (size_t t = 0; t < triangles.size(); ++t) {
    const auto& f = triangles[t];
    const Eigen::Vector3d n = (points[size_t(f[1])] - points[size_t(f[0])])
                                  .cross(points[size_t(f[2])] - points[size_t(f[0])]);
    p.normal[t] = n.norm() > 0 ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d::Zero();
  }
  p.on_border.assign(points.size(), 0);
  for (size_t t = 0; t < triangles.size(); ++t)
    if (is_fill[t])
      for (int v : triangles[t]) p.on_border[size_t(v)] = !free[size_t(v)];
  return p;
}

/// A sharp edge between two known triangles.
struct Crease {
  int t1, t2;
  double convex_length; ///< the edge's length, negative where it is concave
};

/// The edges between known triangles: smooth joins and creases (with their sense).
struct KnownEdges {
  std::vector<std::vector<int>> smooth_neighbours; ///< per triangle
  std::vector<Crease> creases;
};

inline KnownEdges ClassifyKnownEdges(const CreasePatch& p, const CreaseFillParams& params) {
  const size_t nt = p.triangles.size();
  std::map<std::pair<int, int>, std::vector<int>> by_edge;
  for (size_t t = 0; t < nt; ++t)
    if (!p.is_fill[t])
      for (int k = 0; k < 3; ++k) {
        const int a = p.triangles[t][size_t(k)], b = p.triangles[t][size_t((k + 1) % 3)];
        by_edge[{std::min(a, b), std::max(a, b)}].push_back(int(t));
      }
  const double cos_crease = CreaseCosine(params);
  const double cos_smooth = std::cos(params.smooth_angle * M_PI / 180);
  KnownEdges edges;
  edges.smooth_neighbours.resize(nt);
  for (const auto& e : by_edge) {
    if (e.second.size() != 2) continue;
    const int t1 = e.second[0], t2 = e.second[1];
    const double c = p.normal[size_t(t1)].dot(p.normal[size_t(t2)]);
    if (c >= cos_smooth) {
      edges.smooth_neighbours[size_t(t1)].push_back(t2);
      edges.smooth_neighbours[size_t(t2)].push_back(t1);
    } else if (c <= cos_crease) {
      // Convex when t2's far corner lies below t1's plane.
      int far = p.triangles[size_t(t2)][0];
      for (int v : p.triangles[size_t(t2)])
        if (v != e.first.first && v != e.first.second) far = v;
      const double side =
          (p.points[size_t(far)] - p.points[size_t(e.first.first)]).dot(p.normal[size_t(t1)]);
      const double length =
          (p.points[size_t(e.first.first)] - p.points[size_t(e.first.second)]).norm();
      edges.creases.push_back({t1, t2, side < 0 ? length : -length});
    }
  }
  return edges;
}

/// The smooth regions of known triangles that reach the hole's border, each with its quadric
/// height field.
struct SmoothRegions {
  std::vector<int> region;                ///< per triangle: its region, or < 0
  std::vector<HeightField> fields;        ///< per region
  std::vector<std::vector<int>> vertices; ///< per region
  bool rough = false; ///< a region is not smooth enough to extend (the others then unfitted)
};

/// A region's frame and its quadric height field (a plane where it has few vertices), and the
/// fit's RMS residual.
inline HeightField FitHeightField(const CreasePatch& p, const std::vector<int>& faces,
                                  const std::vector<int>& verts, double* residual) {
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for (int f : faces) n += p.normal[size_t(f)];
  HeightField hf;
  hf.n = n.normalized();
  hf.origin = Eigen::Vector3d::Zero();
  for (int v : verts) hf.origin += p.points[size_t(v)];
  hf.origin /= double(verts.size());
  hf.u = hf.n.unitOrthogonal();
  hf.v = hf.n.cross(hf.u);
  const bool quadric = verts.size() >= 12;
  Eigen::MatrixXd a(verts.size(), quadric ? 6 : 3);
  Eigen::VectorXd z(verts.size());
  for (size_t i = 0; i < verts.size(); ++i) {
    const Eigen::Vector3d d = p.points[size_t(verts[i])] - hf.origin;
    const double x = d.dot(hf.u), y = d.dot(hf.v);
    if (quadric)
      a.row(Eigen::Index(i)) << x * x, x * y, y * y, x, y, 1;
    else
      a.row(Eigen::Index(i)) << x, y, 1;
    z[Eigen::Index(i)] = d.dot(hf.n);
  }
  const Eigen::VectorXd c = a.colPivHouseholderQr().solve(z);
  if (quadric)
    hf.c = c;
  else
    hf.c << 0, 0, 0, c[0], c[1], c[2];
  *residual = std::sqrt((a * c - z).squaredNorm() / double(verts.size()));
  return hf;
}

inline SmoothRegions FitSmoothRegions(const CreasePatch& p, const KnownEdges& edges,
                                      const CreaseFillParams& params) {
  const size_t nt = p.triangles.size();
  SmoothRegions r;
  r.region.assign(nt, -1);
  for (size_t seed = 0; seed < nt; ++seed) {
    if (p.is_fill[seed] || r.region[seed] >= 0) continue;
    std::vector<int> faces{int(seed)};
    r.region[seed] = -2;
    for (size_t k = 0; k < faces.size(); ++k)
      for (int g : edges.smooth_neighbours[size_t(faces[k])])
        if (r.region[size_t(g)] == -1) r.region[size_t(g)] = -2, faces.push_back(g);
    bool touches = false;
    for (int f : faces)
      for (int v : p.triangles[size_t(f)]) touches = touches || p.on_border[size_t(v)];
    if (int(faces.size()) < params.min_region_faces || !touches) {
      for (int f : faces) r.region[size_t(f)] = -3;
      continue;
    }
    for (int f : faces) r.region[size_t(f)] = int(r.fields.size());
    std::vector<int> verts;
    for (int f : faces)
      for (int v : p.triangles[size_t(f)]) verts.push_back(v);
    std::sort(verts.begin(), verts.end());
    verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
    double residual = 0;
    const HeightField hf = FitHeightField(p, faces, verts, &residual);
    if (!(residual <= params.max_fit_residual * p.radius)) {
      r.rough = true;
      return r;
    }
    r.fields.push_back(hf);
    r.vertices.push_back(std::move(verts));
  }
  return r;
}

/// Whether one smooth region surrounds the hole: every known triangle at its border is in it.
inline bool OneFaceAround(const CreasePatch& p, const SmoothRegions& r) {
  bool one = r.fields.size() == 1;
  for (size_t t = 0; t < p.triangles.size() && one; ++t)
    if (!p.is_fill[t])
      for (int v : p.triangles[t]) one = one && (!p.on_border[size_t(v)] || r.region[t] == 0);
  return one;
}

/// How each pair of faces meets (nr x nr): > 0 convex, < 0 concave, 0 apart. By the sense of
/// the crease edges between them (the longer), else by how they lie near the hole.
inline std::vector<double> FaceMeetings(const CreasePatch& p, const KnownEdges& edges,
                                        const SmoothRegions& r, const CreaseFillParams& params,
                                        double eps) {
  const size_t nr = r.fields.size();
  std::vector<double> sense(nr * nr, 0.0);
  for (const Crease& c : edges.creases) {
    const int a = r.region[size_t(c.t1)], b = r.region[size_t(c.t2)];
    if (a < 0 || b < 0 || a == b) continue;
    sense[size_t(a) * nr + size_t(b)] += c.convex_length;
    sense[size_t(b) * nr + size_t(a)] += c.convex_length;
  }
  // Two faces whose crease lies wholly inside the hole (a thin plate's corner edge, where the
  // hole took the edge from the top face to the bottom one) have no crease edge in the context;
  // left unpaired, each face's extension runs on through the other. How they meet shows in
  // their vertices near the hole: of a convex edge, each face lies below the other's surface;
  // of a concave one, above. Faces with vertices on both sides of each other do not meet here.
  const double cos_crease = CreaseCosine(params);
  const double tolerance = params.max_fit_residual * p.radius;
  for (size_t a = 0; a < nr; ++a)
    for (size_t b = a + 1; b < nr; ++b) {
      if (sense[a * nr + b] != 0 || std::abs(r.fields[a].n.dot(r.fields[b].n)) > cos_crease)
        continue;
      double lowest = 0, highest = 0;
      for (const auto& pair : {std::make_pair(a, b), std::make_pair(b, a)})
        for (int v : r.vertices[pair.first]) {
          if ((p.points[size_t(v)] - p.centre).norm() > params.pairing_reach * p.radius) continue;
          const double offset = r.fields[pair.second].Offset(p.points[size_t(v)]);
          lowest = std::min(lowest, offset), highest = std::max(highest, offset);
        }
      if (highest <= tolerance && lowest < -tolerance) sense[a * nr + b] = sense[b * nr + a] = eps;
      if (lowest >= -tolerance && highest > tolerance) sense[a * nr + b] = sense[b * nr + a] = -eps;
    }
  return sense;
}

/// Where creases of both senses meet, the pairs alone may not say what the solid is: a top
/// over a concave corner covers both walls' sides of it, not only the side both walls share.
/// The faces' read-once formula then stands for the solid where it holds more of the known
/// surface on its boundary than the pairs do. Empty: the pairs stand for it.
inline std::vector<SolidTerm> SolidFormula(const CreasePatch& p, const SmoothRegions& r,
                                           const std::vector<double>& sense,
                                           const CreaseFillParams& params) {
  const size_t nr = r.fields.size();
  std::vector<SolidTerm> solid = ReadOnceSolid(sense, nr);
  if (solid.empty()) return solid;
  const double tolerance = params.max_fit_residual * p.radius;
  size_t off_formula = 0, off_pairs = 0;
  for (size_t a = 0; a < nr; ++a)
    for (int v : r.vertices[a]) {
      const Eigen::Vector3d& q = p.points[size_t(v)];
      size_t deciding = nr;
      off_formula += std::abs(SolidValue(solid, r.fields, q, &deciding)) > tolerance;
      bool inside_pairs = true;
      for (size_t b = 0; b < nr; ++b) {
        const double meet = sense[a * nr + b], offset = r.fields[b].Offset(q);
        if (b != a && meet != 0 && (meet > 0 ? offset > tolerance : offset < -tolerance))
          inside_pairs = false;
      }
      off_pairs += !inside_pairs;
    }
  if (off_formula >= off_pairs) solid.clear();
  return solid;
}

/// The solid the faces bound (by their pairs, or by the formula where it has one), and points
/// put onto its boundary.
struct CreaseSolid {
  const std::vector<HeightField>& fields;
  std::vector<double> sense; ///< FaceMeetings
  std::vector<SolidTerm> formula;
  double eps = 0;
  double radius = 0; ///< the hole's: a point that moves twice as far ran off

  size_t Faces() const { return fields.size(); }
  double Meet(size_t a, size_t b) const { return sense[a * Faces() + b]; }

  size_t NearestFace(const Eigen::Vector3d& p) const {
    size_t on = 0;
    for (size_t k = 1; k < Faces(); ++k)
      if (std::abs(fields[k].Offset(p)) < std::abs(fields[on].Offset(p))) on = k;
    return on;
  }

  /// `from` onto the solid's boundary: onto the nearest face, then, while it lies outside a
  /// face that meets this one at a convex crease (inside one at a concave crease), onto that
  /// one, which alternates onto the crease's line, or a corner where three meet. With the
  /// formula, onto the face that decides its value until that value is zero. `on`: the face
  /// it ends on. False where it runs off (two curved faces that do not meet near the hole).
  bool Onto(const Eigen::Vector3d& from, Eigen::Vector3d* p, size_t* on) const {
    const size_t nr = Faces();
    *p = from;
    *on = NearestFace(*p);
    *p -= fields[*on].Offset(*p) * fields[*on].n;
    if (!formula.empty()) {
      for (int it = 0; it < 64; ++it) {
        size_t deciding = nr;
        const double value = SolidValue(formula, fields, *p, &deciding);
        if (std::abs(value) <= eps) break;
        *p -= fields[deciding].Offset(*p) * fields[deciding].n;
        *on = deciding;
      }
      return p->allFinite() && (*p - from).norm() <= 2 * radius;
    }
    for (int it = 0; it < 64; ++it) {
      size_t worst = nr;
      double violation = eps;
      for (size_t k = 0; k < nr; ++k) {
        const double meet = Meet(*on, k);
        if (k == *on || meet == 0) continue;
        const double s = fields[k].Offset(*p), v = meet > 0 ? s : -s;
        if (v > violation) violation = v, worst = k;
      }
      if (worst == nr) break;
      *p -= fields[worst].Offset(*p) * fields[worst].n;
      *on = worst;
    }
    return p->allFinite() && (*p - from).norm() <= 2 * radius;
  }

  /// The point of the line where faces fa and fb meet nearest `from` (Newton steps on the two
  /// offsets); false where they are parallel.
  bool LinePoint(const Eigen::Vector3d& from, size_t fa, size_t fb, Eigen::Vector3d* p) const {
    *p = from;
    for (int it = 0; it < 8; ++it) {
      Eigen::Matrix<double, 2, 3> n;
      n.row(0) = fields[fa].n.transpose(), n.row(1) = fields[fb].n.transpose();
      const Eigen::Vector2d r(fields[fa].Offset(*p), fields[fb].Offset(*p));
      const Eigen::Matrix2d gram = n * n.transpose();
      if (std::abs(gram.determinant()) < 1e-12) return false;
      *p -= n.transpose() * gram.inverse() * r;
      if (r.norm() < eps) break;
    }
    return p->allFinite();
  }
};

/// The formula also says how two faces that no crease edge pairs meet: as the earlier of them
/// in its order meets every face after it. Where they are not parallel, their crease's line
/// then runs along fill edges too, as a paired crease's does. Counts the pairs it adds.
inline void PairByFormula(double cos_crease, CreaseSolid& solid, CreaseFill& out) {
  const size_t nr = solid.Faces();
  const std::vector<SolidTerm>& terms = solid.formula;
  for (size_t i = 0; i < terms.size(); ++i)
    for (size_t j = i + 1; j < terms.size(); ++j) {
      const size_t a = terms[i].face, b = terms[j].face;
      if (solid.sense[a * nr + b] != 0 ||
          !(std::abs(solid.fields[a].n.dot(solid.fields[b].n)) <= cos_crease))
        continue;
      solid.sense[a * nr + b] = solid.sense[b * nr + a] =
          terms[i].intersect ? solid.eps : -solid.eps;
      ++(terms[i].intersect ? out.convex_pairs : out.concave_pairs);
    }
}

/// The fill's vertices on the solid, as the steps after the projection move them.
struct FillOnSolid {
  std::vector<Eigen::Vector3d> points; ///< the whole patch
  std::vector<size_t> face_of;         ///< per fill vertex: the face it lies on
  std::vector<char> on_line;           ///< put on a crease's line or a corner: stays there
  std::vector<std::vector<int>> fill_triangles_of; ///< per vertex

  /// Whether vertex v at q keeps every fill triangle around it facing as in the coarse fill,
  /// with some area (three vertices on one line would make none).
  bool KeepsTrianglesFacing(const CreasePatch& p, size_t v, const Eigen::Vector3d& q) const {
    for (int t : fill_triangles_of[v]) {
      std::array<Eigen::Vector3d, 3> c;
      for (int k = 0; k < 3; ++k) {
        const size_t w = size_t(p.triangles[size_t(t)][size_t(k)]);
        c[size_t(k)] = w == v ? q : points[w];
      }
      const Eigen::Vector3d after = (c[1] - c[0]).cross(c[2] - c[0]);
      if (!(after.norm() > 1e-3 * (c[1] - c[0]).squaredNorm()) ||
          !(after.dot(p.normal[size_t(t)]) > 0))
        return false;
    }
    return true;
  }

  /// Vertex v to q on a crease's line, where that keeps its triangles facing.
  void PlaceOnLine(const CreasePatch& p, size_t v, const Eigen::Vector3d& q) {
    if (!KeepsTrianglesFacing(p, v, q)) return;
    points[v] = q;
    on_line[v] = 1;
  }
};

/// Every fill vertex onto the solid's boundary (CreaseSolid::Onto); false where one runs off.
inline bool ProjectFill(const CreasePatch& p, const CreaseSolid& solid, FillOnSolid& fill) {
  fill.points = p.points;
  fill.face_of.assign(p.points.size(), solid.Faces());
  for (size_t i = 0; i < p.points.size(); ++i)
    if (p.free[i] && !solid.Onto(p.points[i], &fill.points[i], &fill.face_of[i])) return false;
  return true;
}

/// Projected one by one, the fill vertices near a crease pile up on its line and the
/// triangles between them fold or cross (on the fandisk, into dozens of crossings: the
/// caller then backed the whole fill off half its way, 20-36 degrees off the crease's
/// angle). Rounds of umbrella smoothing, each point put back onto the solid, spread them out.
inline void RelaxOnSolid(const CreasePatch& p, const CreaseSolid& solid, int rounds,
                         FillOnSolid& fill) {
  std::vector<std::vector<int>> neighbours(p.points.size());
  for (size_t t = 0; t < p.triangles.size(); ++t)
    if (p.is_fill[t])
      for (int k = 0; k < 3; ++k) {
        const int a = p.triangles[t][size_t(k)], b = p.triangles[t][size_t((k + 1) % 3)];
        neighbours[size_t(a)].push_back(b), neighbours[size_t(b)].push_back(a);
      }
  for (int round = 0; round < rounds; ++round) {
    std::vector<Eigen::Vector3d> next = fill.points;
    std::vector<size_t> next_face = fill.face_of;
    for (size_t i = 0; i < p.points.size(); ++i) {
      if (!p.free[i] || neighbours[i].empty()) continue;
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      for (int j : neighbours[i]) mean += fill.points[size_t(j)];
      mean /= double(neighbours[i].size());
      Eigen::Vector3d q;
      size_t on = solid.Faces();
      if (solid.Onto(mean, &q, &on)) next[i] = q, next_face[i] = on;
    }
    fill.points.swap(next);
    fill.face_of.swap(next_face);
  }
}

/// Where three faces meet pairwise inside the hole, the fill vertex nearest their common
/// point goes there: the lines between them then end on a vertex, not on a triangle cut
/// across the corner.
inline void CornersOntoVertices(const CreasePatch& p, const CreaseSolid& solid, FillOnSolid& fill) {
  const size_t nr = solid.Faces();
  const std::vector<HeightField>& fields = solid.fields;
  for (size_t a = 0; a < nr; ++a)
    for (size_t b = a + 1; b < nr; ++b)
      for (size_t c = b + 1; c < nr; ++c) {
        if (solid.Meet(a, b) == 0 || solid.Meet(a, c) == 0 || solid.Meet(b, c) == 0) continue;
        Eigen::Matrix3d n;
        n.row(0) = fields[a].n.transpose(), n.row(1) = fields[b].n.transpose(),
        n.row(2) = fields[c].n.transpose();
        if (std::abs(n.determinant()) < 0.1) continue; // no single point
        const Eigen::Matrix3d inverse = n.inverse();
        Eigen::Vector3d q = p.centre;
        for (int it = 0; it < 8; ++it) {
          const Eigen::Vector3d r(fields[a].Offset(q), fields[b].Offset(q), fields[c].Offset(q));
          q -= inverse * r;
          if (r.norm() < solid.eps) break;
        }
        if (!q.allFinite()) continue;
        // The point is the hole's where a fill vertex is nearer to it than the hole's border.
        size_t nearest = p.points.size();
        double border = std::numeric_limits<double>::infinity();
        for (size_t i = 0; i < p.points.size(); ++i) {
          if (p.on_border[i]) border = std::min(border, (p.points[i] - q).norm());
          if (p.free[i] && !fill.on_line[i] &&
              (nearest == p.points.size() ||
               (fill.points[i] - q).norm() < (fill.points[nearest] - q).norm()))
            nearest = i;
        }
        if (nearest == p.points.size() || !((fill.points[nearest] - q).norm() < border) ||
            !fill.KeepsTrianglesFacing(p, nearest, q))
          continue;
        fill.points[nearest] = q;
        fill.on_line[nearest] = 1;
      }
}

/// The fill's triangles do not follow the crease: an edge whose ends lie on two faces that
/// meet there cuts the crease off as a chamfer one edge wide, which reads as a rounded edge
/// at the scan's scale. Of each such edge, the end nearer the other face goes onto the
/// crease's line, so the line runs along fill edges and the chamfers close. A vertex moves
/// once, and not where a triangle around it would turn over or lose its area (the caller
/// would back the whole fill off for one fold).
inline void CreaseLinesAlongEdges(const CreasePatch& p, const CreaseSolid& solid,
                                  FillOnSolid& fill) {
  const size_t nr = solid.Faces();
  const std::vector<HeightField>& fields = solid.fields;
  auto onto_line = [&](size_t v, size_t fa, size_t fb) {
    Eigen::Vector3d q;
    if (solid.LinePoint(fill.points[v], fa, fb, &q)) fill.PlaceOnLine(p, v, q);
  };
  // A border vertex is on the face it lies nearest to.
  auto face_of_vertex = [&](size_t v) {
    return p.free[v] ? fill.face_of[v] : solid.NearestFace(p.points[v]);
  };
  for (size_t t = 0; t < p.triangles.size(); ++t) {
    if (!p.is_fill[t]) continue;
    for (int k = 0; k < 3; ++k) {
      const size_t a = size_t(p.triangles[t][size_t(k)]),
                   b = size_t(p.triangles[t][size_t((k + 1) % 3)]);
      if (fill.on_line[a] || fill.on_line[b]) continue;
      if (!p.free[a] && !p.free[b]) continue;
      const size_t fa = face_of_vertex(a), fb = face_of_vertex(b);
      if (fa == fb) continue;
      if (solid.Meet(fa, fb) != 0) {
        const bool a_nearer =
            p.free[a] && (!p.free[b] || std::abs(fields[fb].Offset(fill.points[a])) <=
                                            std::abs(fields[fa].Offset(fill.points[b])));
        a_nearer ? onto_line(a, fa, fb) : onto_line(b, fa, fb);
        continue;
      }
      // Two faces that do not meet, both meeting a third: a side face narrower than the
      // fill's edges between a thin part's top and bottom, on which few fill vertices land.
      // The edge across it cuts it off as a groove; each end goes onto its face's crease with
      // the side face (of several, the one whose creases lie nearest the ends), so the edge
      // runs over it.
      double nearest = std::numeric_limits<double>::infinity();
      Eigen::Vector3d to_a, to_b;
      for (size_t c = 0; c < nr; ++c) {
        if (c == fa || c == fb || solid.Meet(fa, c) == 0 || solid.Meet(fb, c) == 0) continue;
        Eigen::Vector3d pa, pb;
        if (!solid.LinePoint(fill.points[a], fa, c, &pa) ||
            !solid.LinePoint(fill.points[b], fb, c, &pb))
          continue;
        const double d = (p.free[a] ? (pa - fill.points[a]).norm() : 0.0) +
                         (p.free[b] ? (pb - fill.points[b]).norm() : 0.0);
        if (d < nearest) nearest = d, to_a = pa, to_b = pb;
      }
      if (!std::isfinite(nearest)) continue;
      if (p.free[a]) fill.PlaceOnLine(p, a, to_a);
      if (p.free[b]) fill.PlaceOnLine(p, b, to_b);
    }
  }
}

/// A sliver of the coarse fill (two border vertices and a free one that stood a hair off the
/// line through them, out of the face) ends turned over when the free vertex is put in the
/// face a hair across that line. It goes to the right side of the line, in its face, at least
/// a twentieth of the edge off it: the caller would otherwise back the whole fill off, and the
/// crease would come back rounded.
inline void TurnSliversBack(const CreasePatch& p, const CreaseSolid& solid, FillOnSolid& fill) {
  for (size_t t = 0; t < p.triangles.size(); ++t) {
    if (!p.is_fill[t]) continue;
    const auto& f = p.triangles[t];
    const Eigen::Vector3d& p0 = fill.points[size_t(f[0])];
    if ((fill.points[size_t(f[1])] - p0).cross(fill.points[size_t(f[2])] - p0).dot(p.normal[t]) > 0)
      continue;
    for (int k = 0; k < 3; ++k) {
      const size_t v = size_t(f[size_t(k)]);
      if (!p.free[v] || fill.on_line[v]) continue;
      const Eigen::Vector3d a = fill.points[size_t(f[size_t((k + 1) % 3)])],
                            b = fill.points[size_t(f[size_t((k + 2) % 3)])];
      if (!((b - a).norm() > 0)) continue;
      const Eigen::Vector3d e = (b - a).normalized();
      const Eigen::Vector3d foot = a + (fill.points[v] - a).dot(e) * e;
      const Eigen::Vector3d across = solid.fields[fill.face_of[v]].n.cross(e).normalized();
      const double off = std::max((fill.points[v] - foot).norm(), 0.05 * (b - a).norm());
      // The check covers t itself, one of the triangles around v.
      for (double side : {1.0, -1.0}) {
        const Eigen::Vector3d q = foot + side * off * across;
        if (fill.KeepsTrianglesFacing(p, v, q)) {
          fill.points[v] = q;
          break;
        }
      }
      break;
    }
  }
}

} // namespace detail

/// The crease-carrying fill of a hole's patch (`points`, `triangles`, `is_fill` per triangle,
/// `free` per vertex: the fill's vertices), oriented consistently; where one smooth region
/// surrounds the hole, that region extended. A `problem` where the context has no crease
/// (unless `params.face_without_crease` and one smooth region surrounds the hole), no
/// smooth region or only part of the hole's border in one, a region is not smooth enough to
/// extend, no two of them meet at a crease (one beside the hole, or one inside it that shows
/// in how the two faces lie), or their extensions do not meet within the hole's reach.
inline CreaseFill FillAcrossCreases(const std::vector<Eigen::Vector3d>& points,
                                    const std::vector<std::array<int, 3>>& triangles,
                                    const std::vector<char>& is_fill, const std::vector<char>& free,
                                    const CreaseFillParams& params) {
  CreaseFill out;
  detail::CreasePatch patch = detail::MakeCreasePatch(points, triangles, is_fill, free);
  if (!FillExtent(points, free, &patch.centre, &patch.radius)) {
    out.problem = "the hole has no fill";
    return out;
  }
  const detail::KnownEdges edges = detail::ClassifyKnownEdges(patch, params);
  out.crease_edges = int(edges.creases.size());
  if (out.crease_edges == 0 && !params.face_without_crease) {
    out.problem = "no crease runs into it";
    return out;
  }
  // Without a crease only one face extended can fill it, so every other problem is that.
  auto fail = [&](const char* problem) {
    out.problem = out.crease_edges > 0 ? std::string(problem)
                                       : "no crease runs into it, and the surface around it is "
                                         "not one smooth face to extend";
    return out;
  };

  const detail::SmoothRegions regions = detail::FitSmoothRegions(patch, edges, params);
  if (regions.rough) return fail("a face beside it is not smooth enough to extend");
  out.regions = int(regions.fields.size());
  // One face all around the hole and a crease beyond it (a hole in a machined part's face,
  // near its edge): the missing surface is that face, extended. A smooth fill reads the
  // crease's curvature in the rings around the hole and bends towards it.
  if (detail::OneFaceAround(patch, regions)) {
    const detail::HeightField& face = regions.fields[0];
    out.points = points;
    for (size_t i = 0; i < points.size(); ++i)
      if (free[i]) out.points[i] -= face.Offset(points[i]) * face.n;
    return out;
  }
  if (regions.fields.size() < 2 || out.crease_edges == 0)
    return fail("fewer than two smooth faces meet at it");

  detail::CreaseSolid solid{
      regions.fields, {}, {}, 1e-9 * std::max(1.0, patch.radius), patch.radius};
  solid.sense = detail::FaceMeetings(patch, edges, regions, params, solid.eps);
  const size_t nr = solid.Faces();
  for (size_t a = 0; a < nr; ++a)
    for (size_t b = a + 1; b < nr; ++b)
      if (solid.Meet(a, b) != 0) ++(solid.Meet(a, b) > 0 ? out.convex_pairs : out.concave_pairs);
  if (out.convex_pairs + out.concave_pairs == 0) {
    out.problem = "no two faces beside it meet at a crease";
    return out;
  }
  solid.formula = detail::SolidFormula(patch, regions, solid.sense, params);
  detail::PairByFormula(detail::CreaseCosine(params), solid, out);

  detail::FillOnSolid fill;
  if (!detail::ProjectFill(patch, solid, fill)) {
    out.problem = "the faces beside it do not meet near it";
    return out;
  }
  detail::RelaxOnSolid(patch, solid, params.relax_rounds, fill);
  fill.on_line.assign(points.size(), 0);
  fill.fill_triangles_of.resize(points.size());
  for (size_t t = 0; t < triangles.size(); ++t)
    if (is_fill[t])
      for (int v : triangles[t]) fill.fill_triangles_of[size_t(v)].push_back(int(t));
  detail::CornersOntoVertices(patch, solid, fill);
  detail::CreaseLinesAlongEdges(patch, solid, fill);
  detail::TurnSliversBack(patch, solid, fill);
  out.points = std::move(fill.points);
  return out;
}

} // namespace vcg_ext
