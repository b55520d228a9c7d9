// Stage 4: signed mean curvature by APSS sphere fitting (paper, section 3.3; Guennebaud &
// Gross 2007), with MeshLab's own implementation from filter_mls (apss.h, balltree.cpp).
//
// It runs on a point set built for the purpose (a patch and the rings around it), never on
// the whole mesh, in whatever units the points are given (the pipeline uses the unit box).
// Sign: convex < 0 < concave, the paper's colours (blue convex, red concave).
#pragma once

#include <apss.h>
#include <apss.tpp>

#include <Eigen/Core>
#include <vcg/complex/complex.h>

#include <vector>

namespace vcg_ext {

struct ApssParams {
  /// MeshLab's "MLS - filter scale": the fitting support in local point spacings. Larger
  /// smooths more.
  float filter_scale = 4.0f;
  int max_projection_iterations = 15;
  float projection_accuracy = 1e-4f;
};

namespace detail {

// The point set APSS fits: MlsSurface wants an optional per-vertex radius it can enable and
// fill itself (a radius that is enabled but zero makes every fit fail), as MeshLab's own mesh
// type has.
class ApssVertex;
class ApssFace;
struct ApssTypes
    : public vcg::UsedTypes<vcg::Use<ApssVertex>::AsVertexType, vcg::Use<ApssFace>::AsFaceType> {};
class ApssVertex
    : public vcg::Vertex<ApssTypes, vcg::vertex::InfoOcf, vcg::vertex::Coord3f,
                         vcg::vertex::Normal3f, vcg::vertex::BitFlags, vcg::vertex::RadiusfOcf> {};
class ApssFace : public vcg::Face<ApssTypes, vcg::face::VertexRef> {};
class ApssMesh
    : public vcg::tri::TriMesh<vcg::vertex::vector_ocf<ApssVertex>, std::vector<ApssFace>> {};

/// MeshLab's APSS builds a ball tree on its first query and never frees it (MlsSurface's
/// destructor is empty and BallTree has none): this one frees the tree and its nodes.
template <class MeshType>
class Apss : public GaelMls::APSS<MeshType> {
public:
  explicit Apss(const MeshType& m) : GaelMls::APSS<MeshType>(m) {}
  ~Apss() override {
    Tree*& tree = static_cast<Surface&>(*this).*TreeOf::Member();
    if (!tree) return;
    delete ((*tree).*RootOf::Member()); // a node deletes its children
    delete tree;
    tree = nullptr;
  }
  Apss(const Apss&) = delete;
  Apss& operator=(const Apss&) = delete;

private:
  using Surface = GaelMls::MlsSurface<MeshType>;
  using Tree = GaelMls::BallTree<typename MeshType::ScalarType>;
  // Both pointers are protected (APSS even hides the tree as private): reached through
  // pointers to members named in classes derived from their owners.
  struct TreeOf : Surface {
    static Tree* Surface::*Member() { return &TreeOf::mBallTree; }
  };
  struct RootOf : Tree {
    static typename Tree::Node* Tree::*Member() { return &RootOf::mRootNode; }
  };
};

} // namespace detail

/// Mean curvature at points[query[i]] of the APSS surface through `points` with `normals`
/// (unit, outward). Returns NaN where the fit fails (too few neighbours).
inline std::vector<double> ApssMeanCurvature(const std::vector<Eigen::Vector3d>& points,
                                             const std::vector<Eigen::Vector3d>& normals,
                                             const std::vector<int>& query,
                                             const ApssParams& params = {}) {
  std::vector<double> h(query.size(), std::numeric_limits<double>::quiet_NaN());
  if (points.size() < 2) return h; // MlsSurface reads the stride off the first two points
  detail::ApssMesh m;
  vcg::tri::Allocator<detail::ApssMesh>::AddVertices(m, points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    m.vert[i].P() = vcg::Point3f(float(points[i].x()), float(points[i].y()), float(points[i].z()));
    m.vert[i].N() =
        vcg::Point3f(float(normals[i].x()), float(normals[i].y()), float(normals[i].z()));
  }
  vcg::tri::UpdateBounding<detail::ApssMesh>::Box(m);
#if CURVATURE_INPAINT_MLS_RADIUS_ATTRIBUTE
  // MeshLab 2021.05 and later: the radii are an attribute the surface expects to find.
  GaelMls::computeVertexRadius(m);
#endif
  detail::Apss<detail::ApssMesh> apss(m);
  apss.setFilterScale(params.filter_scale);
  apss.setMaxProjectionIters(params.max_projection_iterations);
  apss.setProjectionAccuracy(params.projection_accuracy);
  for (size_t i = 0; i < query.size(); ++i) {
    int error = GaelMls::MLS_OK;
    const float c = apss.approxMeanCurvature(m.vert[query[i]].cP(), &error);
    // APSS is positive on a sphere seen from outside (convex); the paper's colours want the
    // opposite sign.
    if (error == GaelMls::MLS_OK && std::isfinite(c)) h[i] = -double(c);
  }
  return h;
}

} // namespace vcg_ext
