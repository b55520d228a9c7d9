#include "pipeline/ground_truth_image.h"

#include <vcg_ext/curvature_colormap.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>
#include <unordered_set>

namespace curvature_inpaint {

namespace {

std::string PositionKey(const Eigen::Vector3d& p) {
  std::string key(sizeof(double) * 3, '\0');
  std::memcpy(&key[0], p.data(), key.size());
  return key;
}

} // namespace

double Spread(const std::vector<double>& x) {
  double sum = 0, sq = 0;
  int n = 0;
  for (double v : x)
    if (std::isfinite(v)) sum += v, sq += v * v, ++n;
  if (n < 2) return 0;
  const double mean = sum / n;
  return std::sqrt(std::max(0.0, sq / n - mean * mean));
}

GroundTruthOracle::GroundTruthOracle(const CMeshO& ground_truth, const CMeshO& input,
                                     const CurvatureImagesParams& params)
    : gt_(ground_truth), box_(vcg_ext::ComputeUnitBox(input)), params_(params), vf_(ground_truth) {
  by_position_.reserve(gt_.vert.size());
  for (size_t v = 0; v < gt_.vert.size(); ++v)
    if (!gt_.vert[v].IsD())
      by_position_.emplace(PositionKey(box_.ToUnit(gt_.vert[v].cP())), int(v));
  for (const auto& f : input.face) {
    if (f.IsD()) continue;
    std::array<int, 3> g;
    bool all = true;
    for (int k = 0; k < 3 && all; ++k) {
      const auto it = by_position_.find(PositionKey(box_.ToUnit(f.cP(k))));
      all = it != by_position_.end();
      if (all) g[k] = it->second;
    }
    if (!all) continue;
    std::sort(g.begin(), g.end());
    input_faces_.insert(g);
  }
}

namespace {

using Edge = std::pair<int, int>;

Edge EdgeOf(int a, int b) {
  return std::make_pair(std::min(a, b), std::max(a, b));
}

std::array<int, 3> Corners(const CMeshO& gt, int f) {
  std::array<int, 3> c;
  for (int k = 0; k < 3; ++k) c[k] = int(vcg::tri::Index(gt, gt.face[f].cV(k)));
  return c;
}

std::array<int, 3> Sorted(std::array<int, 3> c) {
  std::sort(c.begin(), c.end());
  return c;
}

/// The hole's loop in ground-truth vertices (`gt_of`, per patch vertex): the edges that a
/// context face and a fill face of the patch share; and the context's faces, corners sorted.
struct LoopInTruth {
  std::set<Edge> loop;
  std::set<std::array<int, 3>> context_faces;
};

LoopInTruth LoopOf(const vcg_ext::PatchMesh& patch, const std::vector<int>& gt_of) {
  LoopInTruth out;
  std::set<Edge> context_edges;
  for (size_t f = 0; f < patch.triangles.size(); ++f) {
    if (patch.is_fill[f]) continue;
    std::array<int, 3> g;
    for (int k = 0; k < 3; ++k) g[k] = gt_of[patch.triangles[f][k]];
    for (int k = 0; k < 3; ++k) context_edges.insert(EdgeOf(g[k], g[(k + 1) % 3]));
    out.context_faces.insert(Sorted(g));
  }
  for (size_t f = 0; f < patch.triangles.size(); ++f) {
    if (!patch.is_fill[f]) continue;
    const auto& t = patch.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const int a = gt_of[t[k]], b = gt_of[t[(k + 1) % 3]];
      if (a >= 0 && b >= 0 && context_edges.count(EdgeOf(a, b))) out.loop.insert(EdgeOf(a, b));
    }
  }
  return out;
}

/// The ground truth's patch of a hole: the context as it is, the ground truth's faces in the
/// hole (their new vertices from `first_hole_vertex` on), consistently oriented.
struct TruthPatch {
  std::vector<int> vertices; ///< ground-truth vertex of each patch vertex
  std::vector<std::array<int, 3>> tris;
  std::vector<char> is_fill;
  std::vector<int> boundary;
  size_t first_hole_vertex = 0;
};

TruthPatch MakeTruthPatch(const CMeshO& gt, const vcg_ext::PatchMesh& patch,
                          const std::vector<int>& gt_of, const std::vector<int>& hole_faces) {
  TruthPatch out;
  std::vector<int> local(patch.points.size(), -1);
  std::unordered_map<int, int> local_of_gt;
  for (size_t i = 0; i < patch.points.size(); ++i)
    if (gt_of[i] >= 0) {
      local[i] = int(out.vertices.size());
      local_of_gt[gt_of[i]] = local[i];
      out.vertices.push_back(gt_of[i]);
    }
  for (size_t f = 0; f < patch.triangles.size(); ++f)
    if (!patch.is_fill[f]) {
      const auto& t = patch.triangles[f];
      out.tris.push_back({local[t[0]], local[t[1]], local[t[2]]});
      out.is_fill.push_back(0);
    }
  out.first_hole_vertex = out.vertices.size();
  for (int f : hole_faces) {
    std::array<int, 3> t;
    const auto c = Corners(gt, f);
    for (int k = 0; k < 3; ++k) {
      const auto it = local_of_gt.find(c[k]);
      if (it != local_of_gt.end()) {
        t[k] = it->second;
      } else {
        t[k] = local_of_gt[c[k]] = int(out.vertices.size());
        out.vertices.push_back(c[k]);
      }
    }
    out.tris.push_back(t);
    out.is_fill.push_back(1);
  }
  // The context faces first keep the patch's orientation; the hole's follow them.
  vcg_ext::detail::OrientConsistently(out.tris);
  for (int v : patch.boundary) out.boundary.push_back(local[v]);
  return out;
}

/// The spread of the hole's pixels' curvature in `img`.
double ImageSpread(const HoleImage& hi, const vcg_ext::CurvatureImage& img) {
  std::vector<double> pixels;
  for (size_t p = 0; p < hi.image.hole.size(); ++p)
    if (hi.image.hole[p]) {
      const uint8_t* c = &img.rgb[3 * p];
      pixels.push_back(
          2 * hi.scale *
          (vcg_ext::CurvatureColormap::Invert(Eigen::Vector3d(c[0], c[1], c[2])).t - 0.5));
    }
  return Spread(pixels);
}

} // namespace

std::vector<int> GroundTruthOracle::FacesInHole(const HoleImage& hi, const std::vector<int>& gt_of,
                                                std::string* problem) const {
  const LoopInTruth loop = LoopOf(hi.patch, gt_of);
  auto faces_on = [&](int a, int b, std::vector<int>& faces) {
    faces.clear();
    vf_.ForEach(a, [&](int f) {
      for (int k = 0; k < 3; ++k)
        if (int(vcg::tri::Index(gt_, gt_.face[f].cV(k))) == b) faces.push_back(f);
    });
  };
  std::vector<int> hole_faces, stack, on_edge;
  std::unordered_set<int> seen;
  for (const auto& e : loop.loop) {
    faces_on(e.first, e.second, on_edge);
    for (int f : on_edge) {
      const auto c = Sorted(Corners(gt_, f));
      if (!loop.context_faces.count(c) && !input_faces_.count(c) && seen.insert(f).second)
        stack.push_back(f);
    }
  }
  const size_t limit = 50 * hi.patch.triangles.size() + 1000;
  while (!stack.empty()) {
    const int f = stack.back();
    stack.pop_back();
    hole_faces.push_back(f);
    if (hole_faces.size() > limit) {
      *problem = "the ground truth does not close the hole";
      return {};
    }
    const auto c = Corners(gt_, f);
    for (int k = 0; k < 3; ++k) {
      if (loop.loop.count(EdgeOf(c[k], c[(k + 1) % 3]))) continue;
      faces_on(c[k], c[(k + 1) % 3], on_edge);
      for (int g : on_edge) {
        if (g == f) continue;
        if (input_faces_.count(Sorted(Corners(gt_, g)))) {
          // The missing surface reaches a face the input has beyond this hole's loop: it is
          // also another hole's (the two parts of a pinched loop).
          *problem = "the ground truth's surface there also fills another hole";
          return {};
        }
        if (seen.insert(g).second) stack.push_back(g);
      }
    }
  }
  if (hole_faces.empty()) *problem = "the ground truth has no surface in the hole";
  return hole_faces;
}

GroundTruthImage GroundTruthOracle::Image(const HoleImage& hi) const {
  GroundTruthImage out;
  if (!hi.problem.empty() || hi.image.size == 0) {
    out.problem = "the hole has no image";
    return out;
  }
  const auto& patch = hi.patch;
  // The patch's scan vertices in the ground truth.
  std::vector<int> gt_of(patch.points.size(), -1);
  for (size_t i = 0; i < patch.points.size(); ++i) {
    if (hi.is_new[i]) continue;
    const auto it = by_position_.find(PositionKey(patch.points[i]));
    if (it == by_position_.end()) {
      out.problem = "a context vertex of the hole is not in the ground truth";
      return out;
    }
    gt_of[i] = it->second;
  }
  const std::vector<int> hole_faces = FacesInHole(hi, gt_of, &out.problem);
  if (hole_faces.empty()) return out;

  const TruthPatch truth = MakeTruthPatch(gt_, patch, gt_of, hole_faces);
  std::vector<Eigen::Vector3d> points;
  for (int v : truth.vertices) points.push_back(box_.ToUnit(gt_.vert[v].cP()));
  const vcg_ext::MvcParameterization uv =
      vcg_ext::ParameterizeMvc(points, truth.tris, truth.boundary);
  if (!uv.solved || uv.flipped > 0) {
    out.problem = "the ground truth's patch does not parameterize (" + std::to_string(uv.flipped) +
                  " flipped triangles)";
    return out;
  }
  const ApssSupport support = ApssNeighbourhood(gt_, vf_, box_, truth.vertices, params_.apss_rings);
  std::vector<int> query(truth.vertices.size());
  for (size_t i = 0; i < query.size(); ++i) query[i] = int(i);
  const std::vector<double> h =
      vcg_ext::ApssMeanCurvature(support.points, support.normals, query, params_.apss);
  std::vector<double> value(h.size(), 0.5);
  for (size_t i = 0; i < h.size(); ++i)
    if (std::isfinite(h[i])) value[i] = vcg_ext::CurvatureColormap::Value(h[i], hi.scale);
  const auto img =
      vcg_ext::RasterizeCurvature(uv.uv, value, truth.tris, truth.is_fill, hi.image.size);
  out.image = ToQImage(img, false);
  out.spread.truth =
      Spread(std::vector<double>(h.begin() + long(truth.first_hole_vertex), h.end()));
  out.spread.image = ImageSpread(hi, img);
  return out;
}

} // namespace curvature_inpaint
