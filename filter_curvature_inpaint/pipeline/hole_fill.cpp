// The scheduler of the whole method: stages 0-7 for every hole, then each hole's path
// (fill_one_hole.h) on the threads, and the mesh changed only once every hole is done.
#include "pipeline/hole_fill.h"

#include "pipeline/fill_settings.h"

#include "inpaint/server_pool.h"
#include "io/output_files.h"
#include "pipeline/fill_one_hole.h"
#include "pipeline/fill_settings.h"
#include "pipeline/pipeline.h"
#include "report/montage.h"

#include <vcg_ext/crease_flips.h>
#include <vcg_ext/parallel_for.h>

#include <QDir>

#include <algorithm>
#include <atomic>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <thread>
#include <unordered_map>

namespace curvature_inpaint {

namespace {

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

/// Whether the holes are inpainted here (the embedded backend, or images given in a folder)
/// rather than by a service: they then run on every thread.
bool InpaintsLocally(const HoleFillParams& params) {
  return !params.inpainted_dir.empty() || params.inpaint.backend == Backend::kEmbedded;
}

/// How many holes a service is asked for at once: one at a time from a single service (which
/// would rate-limit parallel requests), as many as a pool has room for.
int RequestsAtOnce(const ServerPool* pool) {
  return pool ? pool->Capacity() : 1;
}

/// The pool of a run's servers, where several are given for a service.
std::unique_ptr<ServerPool> MakePool(const InpaintParams& p) {
  if (p.urls.empty() || p.backend == Backend::kEmbedded) return nullptr;
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

/// The hook a hole's path asks between two candidates' fills whether to stop: on the calling
/// thread the callback, with the progress the run last showed ("Curvature Inpaint: <what>hole
/// <done> of <count>", so the bar stays put and the GUI stays live while a big hole is
/// validated), on the others what it last answered. Null without a callback.
std::function<bool()> StopHook(vcg::CallBackPos* cb, const char* what, const std::atomic<int>* done,
                               const std::atomic<int>* count,
                               const std::shared_ptr<CancelRequest>& cancel) {
  if (!cb) return nullptr;
  return [=] {
    if (std::this_thread::get_id() == cancel->asker) {
      const int d = done->load(), n = std::max(1, count->load());
      const std::string msg = std::string("Curvature Inpaint: ") + what + "hole " +
                              std::to_string(d) + " of " + std::to_string(n);
      if (!cb(int(100.0 * d / n), msg.c_str())) cancel->requested = true;
    }
    return cancel->requested.load();
  };
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

/// What the scheduler keeps of one hole once its path is done: its record and its deformed
/// patch; its images are written and dropped.
struct HoleDone {
  HoleFillReport report;
  std::vector<Eigen::Vector3d> points; ///< the deformed patch; empty: keep the coarse fill
  MontageRow montage_row;              ///< when the images are written
};

/// Writes the pictures of a hole that has variations into `images_dir` (when set), also of one
/// that keeps its coarse fill (its final image is then the coarse one, and no variation is
/// framed), and keeps what the mesh needs.
HoleDone Finish(HoleOutcome outcome, size_t k, const std::string& images_dir) {
  HoleDone d{std::move(outcome.report), std::move(outcome.points), {}};
  const HoleVariations& hv = outcome.variations;
  if (!images_dir.empty() && !hv.variations.empty()) {
    const QImage final_image = outcome.final_image.isNull() ? hv.image : outcome.final_image;
    const int framed = d.report.choice.problem.empty() ? d.report.choice.pick : 0;
    d.montage_row =
        SaveHoleImages(hv, k, framed, ChoiceInWords(d.report.choice), final_image, images_dir);
  }
  return d;
}

/// Moves each deformed patch into the mesh, lays the fills' triangles along their sharp edges,
/// and writes the montage into `images_dir` (where set); `result` gets every hole's report in
/// order.
void ApplyToMesh(const std::vector<HoleImage>& holes, std::map<int, HoleDone>& done,
                 const std::string& images_dir, CMeshO& m, HoleFillResult& result) {
  std::vector<MontageRow> montage_rows;
  std::vector<int> moved_fills;            // faces of the fills that moved
  std::unordered_map<int, size_t> hole_of; // fill face -> its hole's report
  for (size_t k = 0; k < holes.size(); ++k) {
    const HoleImage& hi = holes[k];
    HoleDone& d = done.at(int(k));
    result.holes.push_back(d.report);
    if (!d.montage_row.image.isNull()) montage_rows.push_back(std::move(d.montage_row));
    if (d.points.empty()) continue;
    for (size_t i = 0; i < d.points.size(); ++i)
      if (hi.is_new[i])
        m.vert[hi.patch.vertices[i]].P() = result.coarse.box.FromUnit<Scalarm>(d.points[i]);
    if (!d.report.choice.priors.has_creases) continue;
    for (int f : result.coarse.holes[size_t(hi.hole)].new_faces)
      moved_fills.push_back(f), hole_of[f] = k;
  }
  // The fills' triangles laid along the sharp edges they have (a crease fill's, a mirrored
  // ridge's), here, where the mesh, not the patch, holds them: the patch's triangles are the
  // coarse fill's, which every candidate shares. One pass for every hole. Only where creases
  // of the known surface run into the hole: on an organic surface (a face, a neck) a fill's
  // bends are no creases, and flipping onto them carves ridges into it.
  std::vector<int> flipped;
  vcg_ext::FlipFillEdgesOntoCreases(m, moved_fills, {}, &flipped);
  for (size_t i = 0; i < flipped.size(); i += 2) ++result.holes[hole_of[flipped[i]]].crease_flips;
  SaveMontage(montage_rows, images_dir + "/montage.png");
}

/// The normals of the fills, which moved.
void UpdateFillNormals(const vcg_ext::CoarseFillResult& coarse, CMeshO& m) {
  for (const auto& h : coarse.holes)
    for (int f : h.new_faces) m.face[f].N() = vcg::TriangleNormal(m.face[f]).Normalize();
  for (const auto& h : coarse.holes)
    for (int v : h.new_vertices) m.vert[v].N().SetZero();
  for (const auto& h : coarse.holes)
    for (int f : h.new_faces)
      for (int k = 0; k < 3; ++k) m.face[f].V(k)->N() += vcg::TriangleNormal(m.face[f]);
  for (const auto& h : coarse.holes)
    for (int v : h.new_vertices) m.vert[v].N().Normalize();
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
}

} // namespace

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
  HoleContext ctx;
  ctx.params = &params;
  ctx.inpaint = &inpaint;
  const int count = int(images.holes.size());
  std::atomic<int> inpainted{0}, holes{count};
  ctx.validation = ValidationContext{&scratch,
                                     &images.coarse,
                                     &vf,
                                     symmetry.get(),
                                     FakeHoleThreads(images.coarse, threads),
                                     StopHook(cb, "inpainted ", &inpainted, &holes, cancel)};
  if (cb && !cb(0, ("Curvature Inpaint: inpainting " + std::to_string(count) + " holes").c_str()))
    throw vcg_ext::CancelledError();
  std::vector<HoleVariations> variations(static_cast<size_t>(count));
  const int at_once = InpaintsLocally(params) ? threads : RequestsAtOnce(pool.get());
  const auto report = HolesDone(cb, &progress, count, "inpainted", cancel);
  vcg_ext::ParallelFor(
      count, at_once,
      [&](int k) {
        variations[size_t(k)] = InpaintHole(images.holes[size_t(k)], size_t(k), ctx);
        ++inpainted;
      },
      report);
  return variations;
}

const char* DeformationModeName(DeformationMode mode) {
  return mode == DeformationMode::kPaper ? "paper" : "direct";
}

bool DeformationModeFromName(const std::string& name, DeformationMode* mode) {
  for (DeformationMode m : {DeformationMode::kDirect, DeformationMode::kPaper})
    if (name == DeformationModeName(m)) {
      *mode = m;
      return true;
    }
  return false;
}

void CheckHoleFillParams(const HoleFillParams& p) {
  using vcg_ext::RequireRange;
  // The settings a person gives, each in its declared range; then what the stages check.
  for (const SettingSpec& s : Settings())
    if (s.type != SettingType::kText) RequireSetting(s.id, SettingValue(s.id, p));
  CheckCurvatureImagesParams(p.images);
  CheckInpaintParams(p.inpaint);
  RequireRange(p.pick, -1, 1000, "the variation to use");
  for (int pick : p.hole_picks) RequireRange(pick, -1, 1000, "a hole's variation to use");
  RequireRange(p.direct.iterations, 1, 100, "the deformation solves");
  RequireRange(p.direct.apss_passes, 0, 20, "the curvature passes");
  RequireRange(p.direct.apss_gain, 1e-3, 1, "the curvature passes' gain");
  RequireRange(p.paper.max_iterations, 1, 100000, "the deformation steps");
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
  std::map<int, HoleDone> done; // by hole; nodes stay put while other threads insert
  std::mutex done_mutex;
  const bool validates = !chosen && ValidatesOnFakeHoles(params);
  const bool symmetric = !chosen && UsesSymmetry(params);
  std::once_flag context_once;
  std::unique_ptr<vcg_ext::VertexFaces> vf;
  std::unique_ptr<SymmetryPrior> symmetry;
  int fake_hole_threads = 1;
  // Where the holes are filled as their images are built, the callback is asked after each
  // hole this thread fills and, within a hole, between two candidates' fills.
  std::atomic<int> holes_finished{0}, holes_to_fill{1};
  const std::function<bool()> stop_asked =
      StopHook(local ? cb : nullptr, "", &holes_finished, &holes_to_fill, cancel);
  auto fill_hole = [&](const vcg_ext::CoarseFillResult& coarse, int k, HoleImage& hi) {
    holes_to_fill = coarse.FilledCount();
    HoleDone* slot;
    {
      std::lock_guard<std::mutex> lock(done_mutex);
      slot = &done[k];
    }
    // The validation reads the filled mesh around each hole, the symmetry prior its scan part:
    // the vertex-face adjacency, the symmetry planes and the fake holes' threads are found once,
    // by the first hole that needs them (every coarse fill is in place by then).
    HoleContext ctx;
    ctx.params = &params;
    ctx.inpaint = &inpaint;
    ctx.chosen = chosen;
    // What a hole's automatic pick cannot take is not made where no picture shows it.
    ctx.every_variation = !params.images_dir.empty();
    ctx.validation.coarse = &coarse;
    if (validates || symmetric) {
      std::call_once(context_once, [&] {
        if (validates) vf = std::make_unique<vcg_ext::VertexFaces>(m);
        if (symmetric) symmetry = DetectSymmetry(m, coarse, SymmetryDetection(params));
        fake_hole_threads = FakeHoleThreads(coarse, params.images.coarse.threads);
      });
      ctx.validation = ValidationContext{&m, &coarse, vf.get(), symmetry.get(), fake_hole_threads};
    }
    ctx.validation.stop_asked = stop_asked;
    *slot = Finish(FillOneHole(hi, size_t(k), ctx), size_t(k), params.images_dir);
    ++holes_finished;
    std::vector<uint8_t>().swap(hi.image.rgb);
    std::vector<uint8_t>().swap(hi.image.hole);
  };
  CurvatureImagesResult images =
      ComputeCurvatureImages(m, ip, cb, local ? HoleImageSink(fill_hole) : HoleImageSink());
  HoleFillResult result;
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
          [&](int k) { fill_hole(result.coarse, k, images.holes[size_t(k)]); }, report);
    }
    if (symmetry) {
      result.symmetry_detected = true;
      result.symmetry = symmetry->planes;
      result.symmetry_partial = symmetry->partial;
      result.symmetry_best = symmetry->best;
      result.symmetry_s = symmetry->seconds;
    }
    ApplyToMesh(images.holes, done, params.images_dir, m, result);
  } catch (...) {
    checkpoint.Restore();
    throw;
  }
  UpdateFillNormals(result.coarse, m);
  return result;
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
          SaveHoleImages(hv, size_t(k), hv.choice.pick, ChoiceInWords(hv.choice), QImage(), dir);
  });
  rows.erase(std::remove_if(rows.begin(), rows.end(),
                            [](const MontageRow& r) { return r.image.isNull(); }),
             rows.end());
  SaveMontage(rows, dir + "/montage.png");
}

std::vector<VariationRun> VariationRuns(const HoleVariations& hv) {
  std::vector<VariationRun> runs;
  for (size_t j = 0; j < hv.variations.size(); ++j) {
    const FillKind kind = hv.choice.kinds[j];
    if (!runs.empty() && runs.back().kind == kind &&
        hv.variations[size_t(runs.back().first)] == hv.variations[j]) {
      runs.back().last = int(j);
      continue;
    }
    runs.push_back({int(j), int(j), kind});
  }
  return runs;
}

} // namespace curvature_inpaint
