#include "hole_fill.h"

#include "hole_validation.h"
#include "inpaint/curvature_reading.h"
#include "inpaint/server_pool.h"
#include "json_text.h"
#include "montage.h"
#include "output_files.h"
#include "patch_fills.h"
#include "pipeline.h"

#include <vcg_ext/crease_flips.h>
#include <vcg_ext/parallel_for.h>

#include <QColor>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QPainter>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <thread>
#include <unordered_map>

namespace curvature_inpaint {

namespace {

using Clock = std::chrono::steady_clock;
double Since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

/// The hole's JSON from the Curvature Images stage must describe the patch rebuilt now (same
/// vertices): otherwise the hand-inpainted image belongs to another mesh or other settings.
void CheckMatchesFolder(const std::string& json_path, const HoleImage& hi) {
  QFile f(QString::fromStdString(json_path));
  if (!f.open(QIODevice::ReadOnly)) throw std::runtime_error("cannot read " + json_path);
  const QJsonObject o = QJsonDocument::fromJson(f.readAll()).object();
  const QJsonArray vertices = o.value("vertices").toArray();
  bool same = o.value("image_size").toInt() == hi.image.size &&
              vertices.size() == int(hi.patch.vertices.size());
  for (int i = 0; same && i < vertices.size(); ++i)
    same = vertices[i].toObject().value("index").toInt() == hi.patch.vertices[i];
  if (!same)
    throw std::runtime_error(json_path + " describes another patch: make the images again from "
                                         "this mesh with the same maximum hole size, context, "
                                         "filter scale and image size");
}

/// Scores every variation and takes the given pick, or the automatic one.
void ScoreAndPick(HoleVariations& hv, int pick) {
  hv.scores.clear();
  for (const QImage& v : hv.variations) hv.scores.push_back(ScoreVariation(v, hv.mask));
  hv.pick = pick > 0 ? std::min(pick, int(hv.variations.size())) : AutomaticPick(hv);
}

/// Variations without a kind (a hand-inpainted image, the oracle's) are continuations.
const std::string& KindOf(const HoleVariations& hv, size_t j) {
  static const std::string continuation = "continuation";
  return j < hv.kinds.size() ? hv.kinds[j] : continuation;
}

/// A hole's variations by number and kind, as `preview` shows them: "1-4 continuation, 5
/// tri-laplacian".
std::string ListVariations(const HoleVariations& hv) {
  std::string list;
  for (size_t j = 0; j < hv.variations.size();) {
    size_t end = j + 1;
    while (end < hv.variations.size() && KindOf(hv, end) == KindOf(hv, j)) ++end;
    list += (list.empty() ? "" : ", ") + std::to_string(j + 1) +
            (end > j + 1 ? "-" + std::to_string(end) : "") + " " + KindOf(hv, j);
    j = end;
  }
  return list.empty() ? "none" : list;
}

/// The exemplar inpainter's variations, as many as the continuations, after them.
void AddExemplars(HoleVariations& hv, const InpaintParams& params) {
  for (QImage& v : InpaintExemplarVariations(hv.image, hv.mask, params, params.variations)) {
    hv.variations.push_back(std::move(v));
    hv.kinds.push_back("exemplar");
    hv.surfaces.emplace_back();
  }
}

/// The backend's completions as a hole's continuation variations.
void SetContinuations(HoleVariations& hv, std::vector<QImage> images) {
  hv.kinds.assign(images.size(), "continuation");
  hv.surfaces.assign(images.size(), {});
  hv.variations = std::move(images);
}

/// The symmetry detection's parameters, on the run's threads.
vcg_ext::SymmetryParams SymmetryDetection(const HoleFillParams& p) {
  vcg_ext::SymmetryParams d = p.symmetry.detection;
  d.threads = p.images.coarse.threads;
  return d;
}

/// Whether FillHoles and InpaintHoles look for the object's symmetry with these parameters.
bool UsesSymmetry(const HoleFillParams& p) {
  return p.symmetry.enabled && !p.oracle && p.inpainted_dir.empty();
}

/// Stage 8 for one hole: from the backend, or from the folder a person inpainted by hand in.
HoleVariations InpaintHole(const HoleImage& hi, size_t k, const HoleFillParams& params,
                           const InpaintParams& inpaint, const ValidationContext& ctx) {
  const size_t holes = size_t(ctx.coarse->FilledCount());
  if (!params.hole_picks.empty() && params.hole_picks.size() != holes)
    throw std::invalid_argument("a pick is given for " + std::to_string(params.hole_picks.size()) +
                                " holes, and the mesh has " + std::to_string(holes) + " to fill");
  HoleVariations hv;
  hv.images_s = hi.seconds;
  hv.boundary_edges = ctx.coarse->holes[size_t(hi.hole)].boundary_edges;
  if (!hi.problem.empty()) {
    hv.problem = hi.problem;
    return hv;
  }
  const bool listed = k < params.hole_picks.size();
  const int pick = listed ? params.hole_picks[k] : params.pick;
  const std::string pick_kind = listed ? std::string() : params.pick_kind;
  if (pick < 0) {
    hv.problem = "asked to keep its coarse fill";
    return hv;
  }
  // A hole in a plane (its loop planar, the faces around it in that plane or leaving it at a
  // crease) is filled exactly by the coarse fill's flat cap; curvature painted from farther
  // context (a crease or a curved face nearby) and fake holes cut there could only bend it.
  // Asked for by kind or number, a variation is still made.
  const bool automatic =
      pick == 0 && pick_kind.empty() && !params.oracle && params.inpainted_dir.empty();
  if (automatic && ctx.coarse->holes[size_t(hi.hole)].planar_cap) {
    hv.problem = "a flat cap in its plane; it keeps its coarse fill";
    return hv;
  }
  const auto t = Clock::now();
  hv.image = ToQImage(hi.image, false);
  hv.mask = MaskImage(hi.image);
  if (params.oracle) {
    GroundTruthImage truth = params.oracle->Image(hi);
    if (!truth.problem.empty()) {
      hv.problem = "oracle: " + truth.problem + "; it keeps its coarse fill";
      return hv;
    }
    hv.truth_spread = truth.spread;
    hv.variations = {KnownPixelsKept(truth.image, hv.image, hv.mask)};
  } else if (params.inpainted_dir.empty()) {
    hv.detail_scale = FillSpacingPixels(hi);
    hv.detail = inpaint.detail;
    vcg_ext::MirroredFill mirror;
    if (ctx.symmetry) {
      mirror = MirroredPatch(*ctx.symmetry, hi, ctx.coarse->box, params);
      hv.symmetry_note = mirror.problem;
      if (mirror.problem.empty())
        hv.mirror_covered = mirror.covered, hv.mirror_ring_residual = mirror.ring_residual;
    }
    const bool symmetric = ctx.symmetry && mirror.problem.empty();
    vcg_ext::CreaseFill crease;
    if (params.creases) {
      crease = CreasedPatch(hi, params);
      hv.crease_note = crease.problem;
    }
    const std::string crease_kind =
        params.creases && crease.problem.empty() ? CreaseKind(crease) : std::string();
    PatchFill faired;
    if (params.tri_laplacian) faired = TriLaplacianPatch(hi);
    const bool continued = params.tri_laplacian && faired.problem.empty();
    if (ctx.vf && ValidatesOnFakeHoles(params)) {
      const auto v = Clock::now();
      ValidateHole(hi, params, inpaint, ctx, continued, symmetric, crease_kind, hv);
      hv.validation_s = Since(v);
    }
    InpaintParams at_scale = inpaint;
    at_scale.detail = hv.detail;
    if (at_scale.detail_scale <= 0) at_scale.detail_scale = hv.detail_scale;
    SetContinuations(hv, Inpaint(hv.image, hv.mask, at_scale));
    if (params.exemplar && params.inpaint.backend == "embedded") AddExemplars(hv, at_scale);
    if (continued) {
      hv.variations.push_back(SurfaceImage(hi, faired.points, params));
      hv.kinds.push_back("tri-laplacian");
      hv.surfaces.push_back(std::move(faired.points));
    }
    if (symmetric) {
      const QImage image = SurfaceImage(hi, mirror.points, params);
      hv.variations.push_back(image);
      hv.kinds.push_back("symmetry");
      hv.surfaces.emplace_back();
      hv.variations.push_back(image);
      hv.kinds.push_back("symmetry surface");
      hv.surfaces.push_back(std::move(mirror.points));
    }
    if (!crease_kind.empty()) {
      hv.variations.push_back(SurfaceImage(hi, crease.points, params));
      hv.kinds.push_back(crease_kind);
      hv.surfaces.push_back(std::move(crease.points));
    }
  } else {
    const std::string base = params.inpainted_dir + "/hole_" + std::to_string(k + 1);
    CheckMatchesFolder(base + ".json", hi);
    QImage done(QString::fromStdString(base + "_inpainted.png"));
    if (done.isNull()) {
      hv.problem = "no " + base + "_inpainted.png; it keeps its coarse fill";
      return hv;
    }
    hv.variations = {KnownPixelsKept(done, hv.image, hv.mask)};
  }
  hv.inpaint_s = Since(t) - hv.validation_s;
  if (pick > int(hv.variations.size()))
    throw std::invalid_argument("hole " + std::to_string(k + 1) + " has no variation " +
                                std::to_string(pick) + "; it has " + ListVariations(hv));
  ScoreAndPick(hv, pick);
  if (!pick_kind.empty()) {
    hv.pick_note = "it has no " + pick_kind + " variation";
    for (size_t j = 0; j < hv.variations.size(); ++j)
      if (KindOf(hv, j) == pick_kind) {
        hv.pick = int(j) + 1;
        hv.pick_note.clear();
        break;
      }
  }
  hv.asked = pick > 0 || (!pick_kind.empty() && hv.pick_note.empty());
  return hv;
}

/// Whether the holes are inpainted here (the embedded backend, or images given in a folder)
/// rather than by a service: they then run on every thread.
bool InpaintsLocally(const HoleFillParams& params) {
  return !params.inpainted_dir.empty() || params.inpaint.backend == "embedded";
}

/// How many holes a service is asked for at once: one at a time from a single service (which
/// would rate-limit parallel requests), as many as a pool has room for.
int RequestsAtOnce(const ServerPool* pool) {
  return pool ? pool->Capacity() : 1;
}

/// The pool of a run's servers, where several are given for a service.
std::unique_ptr<ServerPool> MakePool(const InpaintParams& p) {
  if (p.urls.empty() || p.backend == "embedded") return nullptr;
  return std::make_unique<ServerPool>(p.urls, p.per_server);
}

/// Whether the user asked to stop, for requests on any thread. MeshLab's callback updates its
/// GUI, so only the thread that made this may run it; requests on the others read what it last
/// answered.
struct CancelRequest {
  std::thread::id asker = std::this_thread::get_id();
  std::atomic<bool> requested{false};
};

/// The inpainting parameters with the callback as the network layer's cancel hook, asked on
/// the calling thread only (`progress` is read there).
InpaintParams WithCancel(const HoleFillParams& params, vcg::CallBackPos* cb, const int* progress,
                         const std::shared_ptr<CancelRequest>& cancel) {
  InpaintParams inpaint = params.inpaint;
  if (cb)
    inpaint.http.cancelled = [cb, progress, cancel] {
      if (std::this_thread::get_id() == cancel->asker &&
          !cb(*progress, "Curvature Inpaint: waiting for the inpainter"))
        cancel->requested = true;
      return cancel->requested.load();
    };
  return inpaint;
}

/// The report over holes, given the holes done (ParallelFor's after each of the calling thread's
/// holes, and while it waits for the others'): the callback, on the calling thread; a stop it
/// asks for also reaches the requests running on the other threads.
auto HolesDone(vcg::CallBackPos* cb, int* progress, int count, const char* what,
               const std::shared_ptr<CancelRequest>& cancel) {
  return [=](int done) {
    *progress = int(100.0 * done / std::max(count, 1));
    const std::string msg = std::string("Curvature Inpaint: ") + what + " hole " +
                            std::to_string(done) + " of " + std::to_string(count);
    if (cb && !cb(*progress, msg.c_str())) cancel->requested = true;
    return !cancel->requested;
  };
}

/// The threads each hole's fake holes get where the holes themselves run in parallel on
/// `threads`: those the holes leave over.
int FakeHoleThreads(const vcg_ext::CoarseFillResult& coarse, int threads) {
  return std::max(1, vcg_ext::ThreadCount(threads) / std::max(1, coarse.FilledCount()));
}

/// Writes hole k's pictures into `dir` as hole_<k+1>_coarse.png, _mask.png, _variation_<j>.png
/// and, where it has one, _final.png; returns its montage row.
MontageRow SaveHoleImages(const HoleVariations& hv, size_t k, int framed, const std::string& reason,
                          const QImage& final_image, const std::string& dir) {
  const std::string base = dir + "/hole_" + std::to_string(k + 1);
  SavePngAtomically(hv.image, base + "_coarse.png");
  SavePngAtomically(hv.mask, base + "_mask.png");
  for (size_t j = 0; j < hv.variations.size(); ++j)
    SavePngAtomically(hv.variations[j], base + "_variation_" + std::to_string(j + 1) + ".png");
  if (!final_image.isNull()) SavePngAtomically(final_image, base + "_final.png");
  return MakeMontageRow(hv, k, framed, reason, final_image);
}

/// Stages 8-9 for hole k: its variations (given, or from the backend), the pick, and the
/// deformation of its patch (`points`, empty when the hole keeps its coarse fill). Touches
/// nothing shared, so holes can run in parallel.
void DeformHole(const HoleImage& hi, size_t k, const vcg_ext::CoarseFillResult& coarse,
                const HoleFillParams& params, const InpaintParams& inpaint,
                const ValidationContext& ctx, const std::vector<HoleVariations>* chosen,
                HoleFillReport& report, HoleVariations& hv, std::vector<Eigen::Vector3d>& points,
                QImage& final_image) {
  report.hole = hi.hole;
  report.boundary_edges = coarse.holes[hi.hole].boundary_edges;
  report.new_vertices = int(coarse.holes[hi.hole].new_vertices.size());
  report.coarse_s = coarse.holes[hi.hole].seconds;
  report.images_s = hi.seconds;
  if (chosen) {
    hv = (*chosen)[k];
    if (hv.problem.empty() && (hv.image.size() != QSize(hi.image.size, hi.image.size) ||
                               ToQImage(hi.image, false) != hv.image))
      throw std::runtime_error("the previewed hole " + std::to_string(k + 1) +
                               " differs from the mesh's: preview again with the same settings");
    if (!hi.problem.empty()) hv.problem = hi.problem;
    if (hv.problem.empty() && hv.pick == 0) hv.problem = "skipped; it keeps its coarse fill";
    if (hv.problem.empty() && (hv.pick < 0 || hv.pick > int(hv.variations.size())))
      throw std::invalid_argument("hole " + std::to_string(k + 1) + " has no variation " +
                                  std::to_string(hv.pick));
  } else {
    hv = InpaintHole(hi, k, params, inpaint, ctx);
    if (hv.problem.empty() && hv.pick == 0)
      hv.problem = (hv.pick_note.empty() ? "" : hv.pick_note + ", and ") +
                   "the coarse fill validated best; it keeps it";
  }
  report.candidates = hv.candidates;
  report.validation_errors = hv.validation_errors;
  report.validation_detail = hv.validation_detail;
  report.choice = hv.choice;
  report.fake_holes = hv.fake_holes;
  report.mirror_fake_holes = hv.mirror_fake_holes;
  report.fake_hole_errors = hv.fake_hole_errors;
  report.validation_note = hv.validation_note;
  report.symmetry_note = hv.symmetry_note;
  report.crease_note = hv.crease_note;
  report.pick_note = hv.pick_note;
  report.asked = hv.asked;
  report.mirror_covered = hv.mirror_covered;
  report.mirror_ring_residual = hv.mirror_ring_residual;
  report.validation_s = hv.validation_s;
  report.inpaint_s = hv.inpaint_s;
  report.truth_spread = hv.truth_spread;
  report.scores = hv.scores;
  for (size_t j = 0; j < hv.variations.size(); ++j) report.kinds.push_back(KindOf(hv, j));
  report.pick = hv.pick;
  if (!hv.problem.empty()) {
    report.problem = hv.problem;
    return;
  }
  const QImage& target_image = hv.variations[report.pick - 1];
  report.kind = KindOf(hv, size_t(report.pick - 1));
  const std::vector<Eigen::Vector3d>* surface =
      size_t(report.pick - 1) < hv.surfaces.size() && !hv.surfaces[report.pick - 1].empty()
          ? &hv.surfaces[report.pick - 1]
          : nullptr;
  if (surface && surface->size() != hi.patch.points.size())
    throw std::runtime_error("the previewed hole " + std::to_string(k + 1) +
                             " differs from the mesh's: preview again with the same settings");

  const auto t = Clock::now();
  const std::vector<char>& free = hi.is_new;
  PatchDeformation deformed;
  if (surface) {
    // A prior's surface: the hole takes it as it is (it was backed off where it folded).
    deformed.points = *surface;
    deformed.target = TargetValues(hi, target_image);
    deformed.result.solved = true;
    for (size_t i = 0; i < free.size(); ++i)
      if (free[i])
        deformed.result.max_move =
            std::max(deformed.result.max_move, (deformed.points[i] - hi.patch.points[i]).norm());
  } else {
    deformed = DeformPatch(hi, target_image, params);
  }
  const std::vector<double>& target = deformed.target;
  std::vector<Eigen::Vector3d>& moved = deformed.points;
  const vcg_ext::DeformationResult& dr = deformed.result;
  report.backoffs = deformed.backoffs;
  report.deform_s = Since(t);
  report.iterations = dr.iterations;
  report.differing = dr.differing;
  report.max_move = dr.max_move;
  if (!dr.solved) {
    report.problem =
        "the deformation would fold the patch or make it cross itself; it keeps its coarse fill";
    return;
  }
  if (params.measure_detail) {
    std::vector<double> th, rh;
    const std::vector<double> h = PatchCurvature(moved, hi.patch.triangles, params.images.apss);
    for (size_t i = 0; i < target.size(); ++i)
      if (free[i]) th.push_back(2 * hi.scale * (target[i] - 0.5)), rh.push_back(h[i]);
    report.target_spread = Spread(th);
    report.result_spread = Spread(rh);
  }
  points = std::move(moved);
  if (!params.images_dir.empty()) final_image = FinalCurvatureImage(hi, points, params.images.apss);
}

} // namespace

void InpaintAgain(HoleVariations& hole, const InpaintParams& params) {
  if (hole.image.isNull()) throw std::runtime_error("this hole has no curvature image");
  const auto t = Clock::now();
  InpaintParams at_scale = params;
  at_scale.detail = hole.detail;
  if (at_scale.detail_scale <= 0) at_scale.detail_scale = hole.detail_scale;
  // New continuations and exemplars; the other variations (symmetry, creases, tri-Laplacian:
  // no seed changes them) stay after them.
  HoleVariations priors;
  bool exemplars = false;
  for (size_t j = 0; j < hole.variations.size(); ++j) {
    exemplars = exemplars || KindOf(hole, j) == "exemplar";
    if (KindOf(hole, j) != "continuation" && KindOf(hole, j) != "exemplar") {
      priors.variations.push_back(hole.variations[j]);
      priors.kinds.push_back(hole.kinds[j]);
      priors.surfaces.push_back(j < hole.surfaces.size() ? hole.surfaces[j]
                                                         : std::vector<Eigen::Vector3d>());
    }
  }
  SetContinuations(hole, Inpaint(hole.image, hole.mask, at_scale));
  if (exemplars) AddExemplars(hole, at_scale);
  hole.variations.insert(hole.variations.end(), priors.variations.begin(), priors.variations.end());
  hole.kinds.insert(hole.kinds.end(), priors.kinds.begin(), priors.kinds.end());
  hole.surfaces.insert(hole.surfaces.end(), priors.surfaces.begin(), priors.surfaces.end());
  hole.inpaint_s = Since(t);
  ScoreAndPick(hole, 0);
}

std::vector<HoleVariations> InpaintHoles(CMeshO& scratch, const HoleFillParams& params,
                                         vcg::CallBackPos* cb) {
  CheckHoleFillParams(params);
  CurvatureImagesParams ip = params.images;
  ip.color_vertices = false;
  const CurvatureImagesResult images = ComputeCurvatureImages(scratch, ip, cb);
  int progress = 0;
  const auto cancel = std::make_shared<CancelRequest>();
  InpaintParams inpaint = WithCancel(params, cb, &progress, cancel);
  const std::unique_ptr<ServerPool> pool = MakePool(params.inpaint);
  inpaint.pool = pool.get();
  const vcg_ext::VertexFaces vf(scratch);
  const std::unique_ptr<SymmetryPrior> symmetry =
      UsesSymmetry(params) ? DetectSymmetry(scratch, images.coarse, SymmetryDetection(params))
                           : nullptr;
  // The holes in parallel as FillHoles runs them, each hole's fake holes on the threads the
  // holes leave over. Each hole fills its own slot, so the preview does not depend on the
  // thread count.
  const int threads = params.images.coarse.threads;
  const ValidationContext ctx{&scratch, &images.coarse, &vf, symmetry.get(),
                              FakeHoleThreads(images.coarse, threads)};
  const int count = int(images.holes.size());
  if (cb && !cb(0, ("Curvature Inpaint: inpainting " + std::to_string(count) + " holes").c_str()))
    throw vcg_ext::CancelledError();
  std::vector<HoleVariations> holes(static_cast<size_t>(count));
  const int at_once = InpaintsLocally(params) ? threads : RequestsAtOnce(pool.get());
  const auto report = HolesDone(cb, &progress, count, "inpainted", cancel);
  vcg_ext::ParallelFor(
      count, at_once,
      [&](int k) {
        holes[size_t(k)] = InpaintHole(images.holes[size_t(k)], size_t(k), params, inpaint, ctx);
      },
      report);
  return holes;
}

double ScoreVariation(const QImage& variation, const QImage& mask) {
  const int n = mask.width();
  if (variation.size() != mask.size() || mask.height() != n) return -1e9;
  const CurvatureReading r = ReadCurvatureImage(variation, mask);
  const std::vector<double>& value = r.t;
  const std::vector<char>& hole = r.hole;
  std::vector<double> known;
  double palette = 0;
  int hole_pixels = 0;
  for (size_t i = 0; i < value.size(); ++i)
    if (hole[i])
      palette += r.distance[i], ++hole_pixels;
    else
      known.push_back(value[i]);
  if (hole_pixels == 0 || known.empty()) return 0;
  auto percentile = [&known](size_t k) {
    std::nth_element(known.begin(), known.begin() + k, known.end());
    return known[k];
  };
  const double lo = percentile(known.size() / 20) - 0.05,
               hi = percentile(known.size() * 19 / 20) + 0.05;
  double jump = 0, outside = 0;
  int border = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const size_t i = size_t(y) * n + x;
      if (!hole[i]) continue;
      if (value[i] < lo || value[i] > hi) ++outside;
      for (int k = 0; k < 4; ++k) {
        const int nx = x + (k == 0) - (k == 1), ny = y + (k == 2) - (k == 3);
        if (nx < 0 || ny < 0 || nx >= n || ny >= n || hole[size_t(ny) * n + nx]) continue;
        jump += std::abs(value[i] - value[size_t(ny) * n + nx]);
        ++border;
      }
    }
  const double continuity = border ? jump / border : 0;
  return -(continuity + palette / hole_pixels / 255.0 + 0.5 * outside / hole_pixels);
}

bool ValidatesOnFakeHoles(const HoleFillParams& p) {
  return p.validation.fake_holes > 0 && p.inpaint.backend == "embedded" && !p.oracle &&
         p.inpainted_dir.empty();
}

bool CoarseValidatedBest(const HoleVariations& hole) {
  return hole.choice >= 0 && size_t(hole.choice) < hole.candidates.size() &&
         hole.candidates[size_t(hole.choice)] == "coarse";
}

int AutomaticPick(const HoleVariations& hole) {
  if (CoarseValidatedBest(hole)) return 0;
  if (hole.choice >= 0 && size_t(hole.choice) < hole.candidates.size())
    for (size_t j = 0; j < hole.variations.size(); ++j)
      if (KindOf(hole, j) == hole.candidates[size_t(hole.choice)]) return int(j) + 1;
  // A prior's variation is chosen only where it validated best: nothing is forced on a hole.
  int best = 0;
  for (size_t j = 0; j < hole.variations.size() && j < hole.scores.size(); ++j)
    if (KindOf(hole, j) == "continuation" &&
        (best == 0 || hole.scores[j] > hole.scores[size_t(best - 1)]))
      best = int(j) + 1;
  return best > 0 || hole.variations.empty() ? best : 1;
}

void CheckHoleFillParams(const HoleFillParams& p) {
  using vcg_ext::RequireRange;
  if (p.mode != "direct" && p.mode != "paper")
    throw vcg_ext::InvalidParameterError("unknown mode \"" + p.mode + "\" (direct or paper)");
  CheckCurvatureImagesParams(p.images);
  CheckInpaintParams(p.inpaint);
  RequireRange(p.pick, -1, 1000, "the variation to use");
  for (int pick : p.hole_picks) RequireRange(pick, -1, 1000, "a hole's variation to use");
  RequireRange(p.direct.iterations, 1, 100, "the deformation solves");
  RequireRange(p.direct.apss_passes, 0, 20, "the curvature passes");
  RequireRange(p.direct.apss_gain, 1e-3, 1, "the curvature passes' gain");
  RequireRange(p.paper.similitude, 0, 255, "the similitude");
  RequireRange(p.paper.transformation_constant, 0, 1, "the transformation constant");
  RequireRange(p.paper.max_iterations, 1, 100000, "the deformation steps");
  RequireRange(p.validation.fake_holes, 0, 16, "the fake holes per hole");
  RequireRange(p.validation.image_size, 16, 8192, "the fake holes' image size");
  RequireRange(p.validation.max_flatter, 0, 1e6,
               "how much flatter a hole may be than its fake holes");
  RequireRange(p.validation.tie, 0, 1, "the validation's tie band");
  for (double a : p.validation.details) RequireRange(a, 0, 10, "a validated detail amplitude");
  RequireRange(p.symmetry.detection.tolerance, 1e-6, 1, "the symmetry tolerance");
  RequireRange(p.symmetry.detection.min_coverage, 0, 1, "the symmetry's minimum coverage");
  RequireRange(p.symmetry.detection.min_partial_coverage, 0, 1,
               "a partial symmetry's minimum coverage");
  RequireRange(p.crease_fill.crease_angle, 1, 179, "the crease angle");
  RequireRange(p.crease_fill.smooth_angle, 0, 179, "the smooth angle");
}

HoleFillResult FillHoles(CMeshO& m, const HoleFillParams& params, vcg::CallBackPos* cb,
                         const std::vector<HoleVariations>* chosen) {
  CheckHoleFillParams(params);
  if (!params.images_dir.empty() && !QDir().mkpath(QString::fromStdString(params.images_dir)))
    throw std::runtime_error("cannot create " + params.images_dir);
  MeshCheckpoint checkpoint(m);
  HoleFillResult result;
  CurvatureImagesParams ip = params.images;
  ip.color_vertices = false;
  // Stages 8-9 per hole, on the hole's own patch. With the embedded backend (or given images)
  // each hole is inpainted and deformed on the thread that built its image, as soon as it is
  // built, and its pictures are written if asked for and dropped: with hundreds of holes they
  // would outweigh the mesh. A service, which would rate-limit parallel calls, is
  // asked one hole at a time once every image is built. The mesh is only written afterwards,
  // on this thread.
  const bool local = chosen || InpaintsLocally(params);
  int progress = 0;
  const auto cancel = std::make_shared<CancelRequest>();
  InpaintParams inpaint = WithCancel(params, local ? nullptr : cb, &progress, cancel);
  const std::unique_ptr<ServerPool> pool = MakePool(params.inpaint);
  inpaint.pool = pool.get();
  struct HoleWork {
    HoleFillReport report;
    std::vector<Eigen::Vector3d> points; ///< the deformed patch; empty: keep the coarse fill
    MontageRow montage_row;              ///< when the images are written
  };
  std::map<int, HoleWork> work; // by hole; nodes stay put while other threads insert
  std::mutex work_mutex;
  const bool validates = !chosen && ValidatesOnFakeHoles(params);
  const bool symmetric = !chosen && UsesSymmetry(params);
  std::once_flag context_once;
  std::unique_ptr<vcg_ext::VertexFaces> vf;
  std::unique_ptr<SymmetryPrior> symmetry;
  int fake_hole_threads = 1;
  auto fill_hole = [&](const vcg_ext::CoarseFillResult& coarse, int k, HoleImage& hi) {
    if (chosen && size_t(k) >= chosen->size())
      throw std::runtime_error("the previewed variations are for " +
                               std::to_string(chosen->size()) +
                               " holes, the mesh has more: preview again with the same settings");
    HoleWork* w;
    {
      std::lock_guard<std::mutex> lock(work_mutex);
      w = &work[k];
    }
    // The validation reads the filled mesh around each hole, the symmetry prior its scan part:
    // the vertex-face adjacency, the symmetry planes and the fake holes' threads are found once, by
    // the first hole that needs them (every coarse fill is in place by then).
    ValidationContext ctx;
    ctx.coarse = &coarse;
    if (validates || symmetric) {
      std::call_once(context_once, [&] {
        if (validates) vf = std::make_unique<vcg_ext::VertexFaces>(m);
        if (symmetric) symmetry = DetectSymmetry(m, coarse, SymmetryDetection(params));
        fake_hole_threads = FakeHoleThreads(coarse, params.images.coarse.threads);
      });
      ctx = ValidationContext{&m, &coarse, vf.get(), symmetry.get(), fake_hole_threads};
    }
    HoleVariations hv;
    QImage final_image;
    DeformHole(hi, size_t(k), coarse, params, inpaint, ctx, chosen, w->report, hv, w->points,
               final_image);
    // The pictures of every hole that has variations, also one that keeps its coarse fill
    // (its final image is then the coarse one, and no variation is framed).
    if (!params.images_dir.empty() && !hv.variations.empty()) {
      if (final_image.isNull()) final_image = hv.image;
      const int framed = w->report.problem.empty() ? w->report.pick : 0;
      w->montage_row = SaveHoleImages(hv, size_t(k), framed, ChoiceInWords(FactsOf(w->report)),
                                      final_image, params.images_dir);
    }
    std::vector<uint8_t>().swap(hi.image.rgb);
    std::vector<uint8_t>().swap(hi.image.hole);
  };
  CurvatureImagesResult images =
      ComputeCurvatureImages(m, ip, cb, local ? HoleImageSink(fill_hole) : HoleImageSink());
  result.coarse = images.coarse;
  try {
    if (chosen && chosen->size() != images.holes.size())
      throw std::runtime_error("the previewed variations are for " +
                               std::to_string(chosen->size()) + " holes, the mesh has " +
                               std::to_string(images.holes.size()) +
                               ": preview again with the same settings");
    if (!local) {
      const int count = int(images.holes.size());
      const auto report = HolesDone(cb, &progress, count, "inpainted and deformed", cancel);
      vcg_ext::ParallelFor(
          count, RequestsAtOnce(pool.get()),
          [&](int k) { fill_hole(result.coarse, k, images.holes[k]); }, report);
    }
    if (symmetry) {
      result.symmetry_detected = true;
      result.symmetry = symmetry->planes;
      result.symmetry_partial = symmetry->partial;
      result.symmetry_best = symmetry->best;
      result.symmetry_s = symmetry->seconds;
    }
    std::vector<MontageRow> montage_rows;
    std::vector<int> moved_fills;            // faces of the fills that moved
    std::unordered_map<int, size_t> hole_of; // fill face -> its hole's report
    for (size_t k = 0; k < images.holes.size(); ++k) {
      const HoleImage& hi = images.holes[k];
      HoleWork& w = work.at(int(k));
      result.holes.push_back(w.report);
      if (!w.montage_row.image.isNull()) montage_rows.push_back(std::move(w.montage_row));
      if (w.points.empty()) continue;
      const std::vector<char>& free = hi.is_new;
      for (size_t i = 0; i < w.points.size(); ++i)
        if (free[i])
          m.vert[hi.patch.vertices[i]].P() = result.coarse.box.FromUnit<Scalarm>(w.points[i]);
      for (int f : result.coarse.holes[size_t(hi.hole)].new_faces)
        moved_fills.push_back(f), hole_of[f] = k;
    }
    // The fills' triangles laid along the sharp edges they have (a crease fill's, a mirrored
    // ridge's), here, where the mesh, not the patch, holds them: the patch's triangles are the
    // coarse fill's, which every candidate shares. One pass for every hole.
    std::vector<int> flipped;
    vcg_ext::FlipFillEdgesOntoCreases(m, moved_fills, {}, &flipped);
    for (size_t i = 0; i < flipped.size(); i += 2) ++result.holes[hole_of[flipped[i]]].crease_flips;
    SaveMontage(montage_rows, params.images_dir + "/montage.png");
  } catch (...) {
    checkpoint.Restore();
    throw;
  }
  // Normals of the moved fill.
  for (const auto& h : result.coarse.holes)
    for (int f : h.new_faces) m.face[f].N() = vcg::TriangleNormal(m.face[f]).Normalize();
  for (const auto& h : result.coarse.holes)
    for (int v : h.new_vertices) m.vert[v].N().SetZero();
  for (const auto& h : result.coarse.holes)
    for (int f : h.new_faces)
      for (int k = 0; k < 3; ++k) m.face[f].V(k)->N() += vcg::TriangleNormal(m.face[f]);
  for (const auto& h : result.coarse.holes)
    for (int v : h.new_vertices) m.vert[v].N().Normalize();
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
  return result;
}

std::string DescribeValidation(const std::vector<std::string>& candidates,
                               const std::vector<double>& errors, int choice, int fake_holes,
                               int mirror_fake_holes, const std::string& note) {
  if (candidates.empty()) return note.empty() ? "not validated" : note;
  std::ostringstream o;
  o << "on " << fake_holes << " fake hole" << (fake_holes == 1 ? "" : "s");
  if (mirror_fake_holes > 0) o << " (" << mirror_fake_holes << " at its mirror place)";
  o << ", RMS in % of the hole's radius:";
  for (size_t c = 0; c < candidates.size() && c < errors.size(); ++c)
    o << (c ? ", " : " ") << candidates[c] << " "
      << QString::number(100 * errors[c], 'f', 2).toStdString();
  if (choice >= 0 && size_t(choice) < candidates.size()) o << "; chose " << candidates[choice];
  if (!note.empty()) o << " (" << note << ")";
  return o.str();
}

void SaveVariationImages(const std::vector<HoleVariations>& holes, const std::string& dir,
                         int threads) {
  if (!QDir().mkpath(QString::fromStdString(dir))) throw std::runtime_error("cannot create " + dir);
  // PNG encoding is most of the time here: the holes' pictures are written in parallel.
  std::vector<MontageRow> rows(holes.size());
  vcg_ext::ParallelFor(int(holes.size()), threads, [&](int k) {
    const HoleVariations& hv = holes[size_t(k)];
    if (!hv.variations.empty())
      rows[size_t(k)] =
          SaveHoleImages(hv, size_t(k), hv.pick, ChoiceInWords(FactsOf(hv)), QImage(), dir);
  });
  rows.erase(std::remove_if(rows.begin(), rows.end(),
                            [](const MontageRow& r) { return r.image.isNull(); }),
             rows.end());
  SaveMontage(rows, dir + "/montage.png");
}

std::vector<std::string> DescribeVariations(const std::vector<HoleVariations>& holes) {
  std::vector<std::string> lines;
  for (size_t k = 0; k < holes.size(); ++k) {
    const HoleVariations& hv = holes[k];
    const std::string hole = "hole " + std::to_string(k + 1) + ": ";
    if (!hv.candidates.empty() || !hv.validation_note.empty())
      lines.push_back(hole + "validation " +
                      DescribeValidation(hv.candidates, hv.validation_errors, hv.choice,
                                         hv.fake_holes, hv.mirror_fake_holes, hv.validation_note));
    if (hv.variations.empty()) {
      lines.push_back(hole + "no variations: " + hv.problem);
      continue;
    }
    std::string line = hole + "variations";
    for (size_t j = 0; j < hv.variations.size(); ++j)
      line += (j ? ", " : " ") + std::to_string(j + 1) + " " + KindOf(hv, j) + " (score " +
              QString::number(j < hv.scores.size() ? hv.scores[j] : 0, 'g', 4).toStdString() + ")";
    line += hv.pick > 0 ? "; fill picks " + std::to_string(hv.pick)
                        : std::string("; fill keeps the coarse fill");
    lines.push_back(line);
  }
  return lines;
}

std::vector<std::string> DescribeHoleFill(const HoleFillResult& result) {
  std::vector<std::string> lines = DescribeCoarseFill(result.coarse);
  if (result.symmetry_detected)
    lines.push_back(
        DescribeSymmetry(result.symmetry, result.symmetry_best, result.symmetry_partial));
  char buf[512];
  for (size_t k = 0; k < result.holes.size(); ++k) {
    const auto& r = result.holes[k];
    if (!r.candidates.empty() || !r.validation_note.empty())
      lines.push_back("validation " + std::to_string(k + 1) + ": " +
                      DescribeValidation(r.candidates, r.validation_errors, r.choice, r.fake_holes,
                                         r.mirror_fake_holes, r.validation_note));
    if (!r.problem.empty()) {
      std::snprintf(buf, sizeof buf, "inpaint %zu: none: %s", k + 1, r.problem.c_str());
    } else {
      std::string scores;
      for (double s : r.scores)
        scores += (scores.empty() ? "" : " ") + QString::number(s, 'g', 4).toStdString();
      const std::string kind = r.kind == "continuation" ? "" : " " + r.kind;
      std::snprintf(
          buf, sizeof buf,
          "inpaint %zu: %d edges, variation %d%s of %zu (scores %s), %d deformation steps, "
          "images %.0f ms, validation %.0f ms, inpaint %.0f ms, deform %.0f ms",
          k + 1, r.boundary_edges, r.pick, kind.c_str(), r.scores.size(), scores.c_str(),
          r.iterations, 1000 * r.images_s, 1000 * r.validation_s, 1000 * r.inpaint_s,
          1000 * r.deform_s);
    }
    lines.emplace_back(buf);
    if (!r.pick_note.empty() && r.problem.empty())
      lines.back() += ", " + r.pick_note + " (the automatic choice instead)";
    if (r.crease_flips > 0)
      lines.back() += ", " + std::to_string(r.crease_flips) + " fill edges flipped onto creases";
    if (r.mirror_covered >= 0)
      lines.back() += ", mirror image on " + std::to_string(std::lround(100 * r.mirror_covered)) +
                      " % of the fill, its ring within " +
                      QString::number(100 * r.mirror_ring_residual, 'f', 1).toStdString() +
                      " % of the hole's radius";
  }
  return lines;
}

std::vector<VariationRun> VariationRuns(const HoleVariations& hv) {
  std::vector<VariationRun> runs;
  for (size_t j = 0; j < hv.variations.size(); ++j) {
    const std::string& kind = KindOf(hv, j);
    if (!runs.empty() && runs.back().kind == kind &&
        hv.variations[size_t(runs.back().first)] == hv.variations[j]) {
      runs.back().last = int(j);
      continue;
    }
    runs.push_back({int(j), int(j), kind});
  }
  return runs;
}

ChoiceFacts FactsOf(const HoleFillReport& r) {
  return {r.candidates, r.fake_hole_errors, r.choice, r.pick, r.kind,
          r.asked,      r.pick_note,        r.problem};
}

ChoiceFacts FactsOf(const HoleVariations& hv) {
  static const std::string none;
  const std::string& kind = hv.pick > 0 ? KindOf(hv, size_t(hv.pick - 1)) : none;
  return {hv.candidates, hv.fake_hole_errors, hv.choice, hv.pick, kind,
          hv.asked,      hv.pick_note,        hv.problem};
}

std::vector<std::string> DescribeHolesInWords(const HoleFillResult& result) {
  std::vector<std::string> lines;
  for (size_t k = 0; k < result.holes.size(); ++k) {
    const HoleFillReport& r = result.holes[k];
    lines.push_back("hole " + std::to_string(k + 1) + " (" + std::to_string(r.boundary_edges) +
                    " edges): " + ChoiceInWords(FactsOf(r)));
  }
  return lines;
}

std::string HoleFillReportJson(const HoleFillResult& result, const HoleFillParams& params) {
  std::ostringstream o;
  o.precision(6);
  o << "{\n  \"backend\": " << JsonQuoted(params.inpaint.backend)
    << ",\n  \"mode\": " << JsonQuoted(params.mode) << ",\n";
  if (result.symmetry_detected) {
    auto planes = [&o](const std::vector<vcg_ext::SymmetryPlane>& list) {
      o << "[";
      for (size_t k = 0; k < list.size(); ++k) {
        const auto& p = list[k];
        o << (k ? ", " : "") << "{\"normal\": [" << JsonNumber{p.normal.x()} << ", "
          << JsonNumber{p.normal.y()} << ", " << JsonNumber{p.normal.z()}
          << "], \"offset\": " << JsonNumber{p.offset}
          << ", \"coverage\": " << JsonNumber{p.coverage}
          << ", \"residual\": " << JsonNumber{p.residual} << "}";
      }
      o << "]";
    };
    o << "  \"symmetry\": {\"seconds\": " << JsonNumber{result.symmetry_s} << ", \"planes\": ";
    planes(result.symmetry);
    o << ", \"partial_planes\": ";
    planes(result.symmetry_partial);
    o << ", \"best_coverage\": " << JsonNumber{result.symmetry_best.coverage} << "},\n";
  }
  o << "  \"holes\": [";
  for (size_t k = 0; k < result.holes.size(); ++k) {
    const auto& r = result.holes[k];
    o << (k ? ",\n" : "\n") << "    {\"hole\": " << k + 1
      << ", \"boundary_edges\": " << r.boundary_edges << ", \"new_vertices\": " << r.new_vertices
      << ", \"scores\": [";
    for (size_t j = 0; j < r.scores.size(); ++j) o << (j ? ", " : "") << JsonNumber{r.scores[j]};
    o << "], \"kinds\": [";
    for (size_t j = 0; j < r.kinds.size(); ++j) o << (j ? ", " : "") << JsonQuoted(r.kinds[j]);
    o << "]";
    if (!r.candidates.empty()) {
      o << ", \"validation\": {\"fake_holes\": " << r.fake_holes
        << ", \"at_mirror_place\": " << r.mirror_fake_holes
        << ", \"tie\": " << JsonNumber{params.validation.tie} << ", \"candidates\": [";
      for (size_t c = 0; c < r.candidates.size(); ++c)
        o << (c ? ", " : "") << "{\"name\": " << JsonQuoted(r.candidates[c])
          << ", \"error\": " << JsonNumber{r.validation_errors[c]}
          << ", \"detail_ratio\": " << JsonNumber{r.validation_detail[c]} << "}";
      o << "], \"per_fake_hole\": [";
      for (size_t f = 0; f < r.fake_hole_errors.size(); ++f) {
        o << (f ? ", [" : "[");
        for (size_t c = 0; c < r.fake_hole_errors[f].size(); ++c)
          o << (c ? ", " : "") << JsonNumber{r.fake_hole_errors[f][c]};
        o << "]";
      }
      o << "], \"choice\": " << JsonQuoted(r.candidates[size_t(r.choice)]);
      if (!r.validation_note.empty()) o << ", \"note\": " << JsonQuoted(r.validation_note);
      o << "}";
    } else if (!r.validation_note.empty()) {
      o << ", \"validation\": {\"note\": " << JsonQuoted(r.validation_note) << "}";
    }
    o << ", \"pick\": " << r.pick;
    if (!r.kind.empty()) o << ", \"kind\": " << JsonQuoted(r.kind);
    o << ", \"crease_flips\": " << r.crease_flips;
    o << ", \"iterations\": " << r.iterations << ", \"backoffs\": " << r.backoffs
      << ", \"max_move\": " << JsonNumber{r.max_move}
      << ", \"seconds\": {\"coarse\": " << JsonNumber{r.coarse_s}
      << ", \"images\": " << JsonNumber{r.images_s}
      << ", \"validation\": " << JsonNumber{r.validation_s}
      << ", \"inpaint\": " << JsonNumber{r.inpaint_s} << ", \"deform\": " << JsonNumber{r.deform_s}
      << "}";
    if (params.measure_detail)
      o << ", \"curvature_spread\": {\"truth\": " << JsonNumber{r.truth_spread.truth}
        << ", \"truth_image\": " << JsonNumber{r.truth_spread.image}
        << ", \"target\": " << JsonNumber{r.target_spread}
        << ", \"result\": " << JsonNumber{r.result_spread} << "}";
    if (r.mirror_covered >= 0)
      o << ", \"mirror_image\": {\"covered\": " << JsonNumber{r.mirror_covered}
        << ", \"ring_residual\": " << JsonNumber{r.mirror_ring_residual} << "}";
    if (!r.symmetry_note.empty()) o << ", \"no_symmetry\": " << JsonQuoted(r.symmetry_note);
    if (!r.crease_note.empty()) o << ", \"no_creases\": " << JsonQuoted(r.crease_note);
    if (!r.problem.empty()) o << ", \"problem\": " << JsonQuoted(r.problem);
    o << "}";
  }
  o << "\n  ]\n}\n";
  return o.str();
}

} // namespace curvature_inpaint
