#include "candidates/patch_fills.h"

#include <vcg_ext/curvature_colormap.h>
#include <vcg_ext/fill_extent.h>
#include <vcg_ext/hole_fairing.h>
#include <vcg_ext/self_intersections.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace curvature_inpaint {

namespace {

/// The colour-map value of the variation at (u, v), bilinear between pixel centres.
double SampleValue(const QImage& img, const Eigen::Vector2d& uv) {
  const double x = std::max(0.0, std::min(img.width() - 1.0, uv.x() * img.width() - 0.5));
  const double y = std::max(0.0, std::min(img.height() - 1.0, (1 - uv.y()) * img.height() - 0.5));
  const int x0 = int(x), y0 = int(y);
  const int x1 = std::min(x0 + 1, img.width() - 1), y1 = std::min(y0 + 1, img.height() - 1);
  const double fx = x - x0, fy = y - y0;
  auto value = [&](int px, int py) {
    const QRgb c = img.pixel(px, py);
    return vcg_ext::CurvatureColormap::Invert(Eigen::Vector3d(qRed(c), qGreen(c), qBlue(c))).t;
  };
  return (1 - fy) * ((1 - fx) * value(x0, y0) + fx * value(x1, y0)) +
         fy * ((1 - fx) * value(x0, y1) + fx * value(x1, y1));
}

/// Fill triangles whose orientation the deformation reversed; where `marked` is given (one
/// flag per patch triangle), each of them is flagged there.
int Folded(const std::vector<Eigen::Vector3d>& before, const std::vector<Eigen::Vector3d>& after,
           const vcg_ext::PatchMesh& patch, std::vector<char>* marked = nullptr) {
  int folded = 0;
  for (size_t f = 0; f < patch.triangles.size(); ++f) {
    if (!patch.is_fill[f]) continue;
    const auto& t = patch.triangles[f];
    const Eigen::Vector3d a = vcg_ext::TriangleNormal(before[t[0]], before[t[1]], before[t[2]]);
    const Eigen::Vector3d b = vcg_ext::TriangleNormal(after[t[0]], after[t[1]], after[t[2]]);
    const bool reversed = a.dot(b) <= 0;
    folded += reversed;
    if (reversed && marked) (*marked)[f] = 1;
  }
  return folded;
}

/// Whether the patch with its fill moved folds a fill triangle over or makes the fill cross
/// the patch; crossings the coarse fill already had do not count (counted once, when first
/// needed).
class FoldCheck {
public:
  explicit FoldCheck(const vcg_ext::PatchMesh& patch) : patch_(patch) {}
  bool Broken(const std::vector<Eigen::Vector3d>& moved) {
    if (Folded(patch_.points, moved, patch_) > 0) return true;
    return vcg_ext::CountSelfIntersections(moved, patch_.triangles, patch_.is_fill) >
           int(CrossingsBefore().size());
  }
  /// Marks in `bad` (one flag per patch triangle) the fill triangles that `moved` turned over
  /// and those of the crossings it made that the coarse fill did not have; false if none.
  bool BrokenTriangles(const std::vector<Eigen::Vector3d>& moved, std::vector<char>* bad) {
    bad->assign(patch_.triangles.size(), 0);
    bool broken = Folded(patch_.points, moved, patch_, bad) > 0;
    std::vector<std::pair<int, int>> pairs;
    vcg_ext::CountSelfIntersections(moved, patch_.triangles, patch_.is_fill, &pairs);
    const std::vector<std::pair<int, int>>& before = CrossingsBefore();
    for (const auto& p : pairs)
      if (!std::binary_search(before.begin(), before.end(), p))
        (*bad)[size_t(p.first)] = (*bad)[size_t(p.second)] = 1, broken = true;
    return broken;
  }

private:
  /// The coarse fill's own crossings (pairs of triangles), found once, when first asked for.
  const std::vector<std::pair<int, int>>& CrossingsBefore() {
    if (!have_crossings_before_)
      vcg_ext::CountSelfIntersections(patch_.points, patch_.triangles, patch_.is_fill,
                                      &crossings_before_);
    have_crossings_before_ = true;
    return crossings_before_;
  }

  const vcg_ext::PatchMesh& patch_;
  bool have_crossings_before_ = false;
  std::vector<std::pair<int, int>> crossings_before_;
};

/// Backs `moved` (the patch with its fill moved) off towards the coarse fill, halving the way,
/// while `check` finds it broken. Returns the halvings, or -1 when four did not undo it.
int BackOff(const vcg_ext::PatchMesh& patch, std::vector<Eigen::Vector3d>& moved,
            FoldCheck& check) {
  int halvings = 0;
  for (; check.Broken(moved); ++halvings) {
    if (halvings == 4) return -1;
    for (size_t i = 0; i < moved.size(); ++i)
      moved[i] = patch.points[i] + 0.5 * (moved[i] - patch.points[i]);
  }
  return halvings;
}

/// Backs `moved` off towards the coarse fill only where it broke: the free vertices of the
/// triangles that turned over or cross anew have their way halved, round after round, so a
/// fold in one corner does not round the whole fill. Returns the vertex halvings made, or -1
/// when `rounds` did not undo it.
int BackOffLocally(const vcg_ext::PatchMesh& patch, const std::vector<char>& free,
                   std::vector<Eigen::Vector3d>& moved, FoldCheck& check, int rounds) {
  int halvings = 0;
  std::vector<char> bad;
  for (int round = 0; check.BrokenTriangles(moved, &bad); ++round) {
    if (round == rounds) return -1;
    std::vector<char> halve(moved.size(), 0);
    for (size_t f = 0; f < bad.size(); ++f)
      if (bad[f])
        for (int v : patch.triangles[f]) halve[size_t(v)] = free[size_t(v)];
    for (size_t i = 0; i < moved.size(); ++i)
      if (halve[i]) moved[i] = patch.points[i] + 0.5 * (moved[i] - patch.points[i]), ++halvings;
  }
  return halvings;
}

int BackOff(const vcg_ext::PatchMesh& patch, std::vector<Eigen::Vector3d>& moved) {
  FoldCheck check(patch);
  return BackOff(patch, moved, check);
}

// Rounds of spreading of the crease fill's vertices, and of backing it off where it folds:
// chosen on the fandisk's development holes (docs/experiments.md, "The figures behind the
// defaults").
constexpr int kCreaseRelaxRounds = 10;
constexpr int kCreaseBackOffRounds = 12;

} // namespace

QImage KnownPixelsKept(const QImage& edited, const QImage& image, const QImage& mask) {
  QImage v = edited.convertToFormat(QImage::Format_RGB32)
                 .scaled(image.size(), Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
  for (int y = 0; y < v.height(); ++y)
    for (int x = 0; x < v.width(); ++x)
      if (qGray(mask.pixel(x, y)) <= 127) v.setPixel(x, y, image.pixel(x, y));
  return v;
}

std::vector<double> PatchCurvature(const std::vector<Eigen::Vector3d>& points,
                                   const std::vector<std::array<int, 3>>& triangles,
                                   const vcg_ext::ApssParams& apss) {
  const std::vector<Eigen::Vector3d> normals = vcg_ext::detail::VertexNormals(points, triangles);
  std::vector<int> query(points.size());
  for (size_t i = 0; i < query.size(); ++i) query[i] = int(i);
  return vcg_ext::ApssMeanCurvature(points, normals, query, apss);
}

QImage FinalCurvatureImage(const HoleImage& hi, const std::vector<Eigen::Vector3d>& points,
                           const vcg_ext::ApssParams& apss) {
  const auto h = PatchCurvature(points, hi.patch.triangles, apss);
  std::vector<double> value(h.size(), 0.5);
  for (size_t i = 0; i < h.size(); ++i)
    if (std::isfinite(h[i])) value[i] = vcg_ext::CurvatureColormap::Value(h[i], hi.scale);
  return ToQImage(vcg_ext::RasterizeCurvature(hi.uv.uv, value, hi.patch.triangles, hi.patch.is_fill,
                                              hi.image.size),
                  false);
}

std::vector<double> TargetValues(const HoleImage& hi, const QImage& image) {
  std::vector<double> target(hi.patch.points.size(), 0.5);
  for (size_t i = 0; i < target.size(); ++i)
    if (hi.is_new[i]) target[i] = SampleValue(image, hi.uv.uv[i]);
  return target;
}

PatchDeformation DeformPatch(const HoleImage& hi, const QImage& target_image,
                             const HoleFillParams& params) {
  PatchDeformation out;
  const std::vector<char>& free = hi.is_new;
  out.target = TargetValues(hi, target_image);
  const std::vector<double>& target = out.target;
  std::vector<Eigen::Vector3d>& moved = out.points;
  moved = hi.patch.points;
  vcg_ext::DeformationResult& dr = out.result;
  FoldCheck check(hi.patch); // the rounds' and the back-off's: the coarse crossings counted once
  if (params.mode == DeformationMode::kDirect) {
    // A round that folds a triangle or makes the fill cross the patch is not taken: the
    // back-off below would have to undo the rounds before it too.
    dr = vcg_ext::DeformToCurvatureImage(
        moved, hi.patch.triangles, free, target, hi.value, hi.scale, params.images.apss,
        params.direct, [&](const std::vector<Eigen::Vector3d>& p) { return !check.Broken(p); });
  } else {
    dr = vcg_ext::DeformToCurvaturePaper(moved, hi.patch.triangles, free, target, hi.scale,
                                         params.paper);
  }
  if (dr.solved) {
    out.backoffs = BackOff(hi.patch, moved, check);
    if (out.backoffs < 0) dr.solved = false, out.backoffs = 4;
  }
  return out;
}

double FillSpacingPixels(const HoleImage& hi) {
  double sum = 0;
  int n = 0;
  for (size_t f = 0; f < hi.patch.triangles.size(); ++f) {
    if (!hi.patch.is_fill[f]) continue;
    const auto& t = hi.patch.triangles[f];
    for (int k = 0; k < 3; ++k) sum += (hi.uv.uv[t[k]] - hi.uv.uv[t[(k + 1) % 3]]).norm(), ++n;
  }
  return n ? hi.image.size * sum / n : 0.0;
}

vcg_ext::MirroredFill MirroredPatch(const SymmetryPrior& prior, const HoleImage& hi,
                                    const vcg_ext::UnitBox& frame, const HoleFillParams& params,
                                    const Eigen::Vector3d& excluded_centre,
                                    double excluded_radius) {
  vcg_ext::MirroredFill f = MirrorHole(prior, hi.patch, hi.is_new, frame, params.symmetry.fill,
                                       excluded_centre, excluded_radius);
  if (f.problem.empty() && BackOff(hi.patch, f.points) < 0) {
    f.points.clear();
    f.problem = "its mirror image would fold the patch or make it cross itself";
  }
  return f;
}

QImage SurfaceImage(const HoleImage& hi, const std::vector<Eigen::Vector3d>& points,
                    const HoleFillParams& params) {
  return KnownPixelsKept(FinalCurvatureImage(hi, points, params.images.apss),
                         ToQImage(hi.image, false), MaskImage(hi.image));
}

vcg_ext::CreaseFill CreasedPatch(const HoleImage& hi, const HoleFillParams& params) {
  FoldCheck check(hi.patch);
  size_t fill_vertices = 0;
  for (char is_new : hi.is_new) fill_vertices += is_new != 0;
  // The fill and how much of it was backed off (vertex halvings; -1: it could not be mended).
  auto attempt = [&](int relax_rounds, long* halvings) {
    vcg_ext::CreaseFillParams cp = params.crease_fill;
    cp.relax_rounds = relax_rounds;
    vcg_ext::CreaseFill f = vcg_ext::FillAcrossCreases(hi.patch.points, hi.patch.triangles,
                                                       hi.patch.is_fill, hi.is_new, cp);
    *halvings = 0;
    if (!f.problem.empty()) return f;
    std::vector<Eigen::Vector3d> local = f.points;
    const int local_halvings =
        BackOffLocally(hi.patch, hi.is_new, local, check, kCreaseBackOffRounds);
    if (local_halvings >= 0) {
      f.points.swap(local);
      *halvings = local_halvings;
    } else {
      const int whole = BackOff(hi.patch, f.points, check);
      *halvings = whole < 0 ? -1 : long(whole) * long(fill_vertices);
    }
    return f;
  };
  long halvings = 0;
  vcg_ext::CreaseFill f = attempt(0, &halvings);
  if (f.problem.empty()) {
    long relaxed_halvings = 0;
    vcg_ext::CreaseFill relaxed = attempt(kCreaseRelaxRounds, &relaxed_halvings);
    if (relaxed.problem.empty() && relaxed_halvings >= 0 &&
        (halvings < 0 || relaxed_halvings < halvings || relaxed_halvings == 0))
      f = std::move(relaxed), halvings = relaxed_halvings;
  }
  if (f.problem.empty() && halvings < 0) {
    f.points.clear();
    f.problem = "its creases would fold the patch or make it cross itself";
  }
  return f;
}

PatchFill TriLaplacianPatch(const HoleImage& hi) {
  PatchFill f;
  f.points = hi.patch.points;
  vcg_ext::HoleFairingParams fp;
  fp.order = 3;
  // It starts from the thin plate, whose weights are already those of a curved fill: two
  // plain solves settle them.
  fp.iterations = 2;
  fp.over_relaxation = 1;
  if (!vcg_ext::FairFreeVertices(f.points, hi.patch.triangles, hi.is_new, fp))
    f.problem = "its tri-Laplacian system cannot be solved";
  else if (BackOff(hi.patch, f.points) < 0)
    f.problem = "its tri-Laplacian fill would fold the patch or make it cross itself";
  if (!f.problem.empty()) f.points.clear();
  return f;
}

std::vector<std::array<int, 3>> FillTriangles(const vcg_ext::PatchMesh& patch) {
  std::vector<std::array<int, 3>> tris;
  for (size_t f = 0; f < patch.triangles.size(); ++f)
    if (patch.is_fill[f]) tris.push_back(patch.triangles[f]);
  return tris;
}

} // namespace curvature_inpaint
