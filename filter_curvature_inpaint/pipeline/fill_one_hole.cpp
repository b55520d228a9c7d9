#include "pipeline/fill_one_hole.h"

#include "candidates/fill_candidate.h"
#include "candidates/patch_fills.h"
#include "pipeline/pipeline.h"

#include <vcg_ext/hole_creases.h>

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <chrono>
#include <stdexcept>

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

/// Appends one variation: an image to deform the patch to, or with a `surface` (unit box) a
/// patch the hole takes as it is.
void AddVariation(HoleVariations& hv, QImage image, FillKind kind,
                  std::vector<Eigen::Vector3d> surface = {}) {
  hv.variations.push_back(std::move(image));
  hv.choice.kinds.push_back(kind);
  hv.surfaces.push_back(std::move(surface));
}

/// The embedded inpainter's parameters at the hole's amplitude and vertex spacing.
InpaintParams AtHoleScale(const InpaintParams& inpaint, const HoleVariations& hv) {
  InpaintParams at_scale = inpaint;
  at_scale.detail = hv.detail;
  if (at_scale.detail_scale <= 0) at_scale.detail_scale = hv.detail_scale;
  return at_scale;
}

/// A hole's variations by number and kind, as `preview` shows them: "1-4 continuation, 5
/// tri-laplacian".
std::string ListVariations(const HoleChoice& c) {
  std::string list;
  for (size_t j = 0; j < c.kinds.size();) {
    size_t end = j + 1;
    while (end < c.kinds.size() && c.kinds[end] == c.kinds[j]) ++end;
    list += (list.empty() ? "" : ", ") + std::to_string(j + 1) +
            (end > j + 1 ? "-" + std::to_string(end) : "") + " " + FillKindName(c.kinds[j]);
    j = end;
  }
  return list.empty() ? "none" : list;
}

/// Why the hole has no mirror image or no crease fill, and how well its mirror image fits.
PriorNotes NotesOf(const PatchWork& work) {
  PriorNotes notes;
  if (work.mirror) {
    notes.no_symmetry = work.mirror->problem;
    if (work.mirror->problem.empty())
      notes.mirror_covered = work.mirror->covered,
      notes.mirror_ring_residual = work.mirror->ring_residual;
  }
  if (work.crease) notes.no_creases = work.crease->problem;
  return notes;
}

/// Stage 8 with the embedded backend or a service: the candidates' shared work (the priors'
/// fills), the fake-hole validation where it runs (it may choose the amplitude), then each
/// candidate's variations: the continuations, the exemplars if asked for, the priors' fills.
/// With `every_variation` false (a fill that picks automatically and shows nothing) only the
/// variations the automatic pick can take are made; the others are listed, with their numbers
/// as a preview gives them, and not made.
void InpaintFromBackend(const HoleImage& hi, const HoleContext& ctx, bool every_variation,
                        HoleVariations& hv) {
  const HoleFillParams& params = *ctx.params;
  hv.detail_scale = FillSpacingPixels(hi);
  hv.detail = ctx.inpaint->detail;
  std::vector<const FillCandidate*> enabled;
  for (const FillCandidate* c : FillCandidates())
    if (c->Enabled(params)) enabled.push_back(c);
  PatchSite site;
  site.patch = &hi;
  site.params = &params;
  site.image = hv.image;
  site.mask = hv.mask;
  site.symmetry = ctx.validation.symmetry;
  site.frame = ctx.validation.coarse->box;
  const PatchWork work = MakePatchWork(site, enabled);
  hv.choice.priors = NotesOf(work);
  if (ctx.validation.vf && ValidatesOnFakeHoles(params)) {
    const auto v = Clock::now();
    hv.choice.validation = ValidateHole(hi, params, *ctx.inpaint, ctx.validation, work);
    const ValidationRecord& record = hv.choice.validation;
    if (record.HasChoice() && record.Chosen().amplitude >= 0) hv.detail = record.Chosen().amplitude;
    hv.seconds.validation = Since(v);
  }
  const InpaintParams at_scale = AtHoleScale(*ctx.inpaint, hv);
  site.inpaint = &at_scale;
  for (const FillCandidate* c : enabled) {
    if (!c->IsVariation() || !c->Applies(work)) continue;
    StopIfAsked(ctx.validation);
    const FillKind kind = c->KindAt(work);
    const int listed = c->VariationCount(site);
    if (!every_variation && listed >= 0 && !AutomaticPickCanTake(hv.choice, kind)) {
      for (int j = 0; j < listed; ++j) AddVariation(hv, QImage(), kind);
      continue;
    }
    for (CandidateVariation& v : c->Variations(site, work))
      AddVariation(hv, std::move(v.image), kind, std::move(v.surface));
  }
}

/// Stage 8 from the image a person inpainted by hand in params.inpainted_dir; false (with the
/// problem set) where there is none.
bool InpaintFromFolder(const HoleImage& hi, size_t k, const HoleFillParams& params,
                       HoleVariations& hv) {
  const std::string base = params.inpainted_dir + "/hole_" + std::to_string(k + 1);
  CheckMatchesFolder(base + ".json", hi);
  QImage done(QString::fromStdString(base + "_inpainted.png"));
  if (done.isNull()) {
    hv.choice.problem = "no " + base + "_inpainted.png; it keeps its coarse fill";
    return false;
  }
  AddVariation(hv, KnownPixelsKept(done, hv.image, hv.mask), FillKind::kContinuation);
  return true;
}

/// Stage 8 from the ground truth's own curvature image (the benchmark's oracle); false (with
/// the problem set) where it has none.
bool InpaintFromOracle(const HoleImage& hi, const GroundTruthOracle& oracle, HoleVariations& hv) {
  GroundTruthImage truth = oracle.Image(hi);
  if (!truth.problem.empty()) {
    hv.choice.problem = "oracle: " + truth.problem + "; it keeps its coarse fill";
    return false;
  }
  hv.truth_spread = truth.spread;
  AddVariation(hv, KnownPixelsKept(truth.image, hv.image, hv.mask), FillKind::kContinuation);
  return true;
}

/// The preview's variations of hole `k`, checked against the mesh's hole, with the reason it
/// keeps its coarse fill where it does.
HoleVariations PreviewedHole(const HoleImage& hi, size_t k,
                             const std::vector<HoleVariations>& chosen) {
  if (k >= chosen.size())
    throw std::runtime_error("the previewed variations are for " + std::to_string(chosen.size()) +
                             " holes, the mesh has more: preview again with the same settings");
  HoleVariations hv = chosen[k];
  HoleChoice& c = hv.choice;
  if (c.problem.empty() && (hv.image.size() != QSize(hi.image.size, hi.image.size) ||
                            ToQImage(hi.image, false) != hv.image))
    throw std::runtime_error("the previewed hole " + std::to_string(k + 1) +
                             " differs from the mesh's: preview again with the same settings");
  if (!hi.problem.empty()) c.problem = hi.problem;
  if (c.problem.empty() && c.pick == 0) c.problem = "skipped; it keeps its coarse fill";
  if (c.problem.empty() && (c.pick < 0 || c.pick > int(hv.variations.size())))
    throw std::invalid_argument("hole " + std::to_string(k + 1) + " has no variation " +
                                std::to_string(c.pick));
  return hv;
}

/// Stage 9 for a picked variation: the patch deformed to its curvature, or a prior's surface
/// taken as it is (it was backed off where it folded).
PatchDeformation ApplyPick(const HoleImage& hi, const HoleVariations& hv, size_t k,
                           const HoleFillParams& params) {
  const size_t j = size_t(hv.choice.pick - 1);
  const QImage& target_image = hv.variations[j];
  const std::vector<Eigen::Vector3d>* surface =
      j < hv.surfaces.size() && !hv.surfaces[j].empty() ? &hv.surfaces[j] : nullptr;
  if (!surface) return DeformPatch(hi, target_image, params);
  if (surface->size() != hi.patch.points.size())
    throw std::runtime_error("the previewed hole " + std::to_string(k + 1) +
                             " differs from the mesh's: preview again with the same settings");
  PatchDeformation placed;
  placed.points = *surface;
  placed.target = TargetValues(hi, target_image);
  placed.result.solved = true;
  for (size_t i = 0; i < hi.is_new.size(); ++i)
    if (hi.is_new[i])
      placed.result.max_move =
          std::max(placed.result.max_move, (placed.points[i] - hi.patch.points[i]).norm());
  return placed;
}

/// The curvature spread of the deformation's target and of the deformed fill, for the report.
void MeasureDetail(const HoleImage& hi, const PatchDeformation& deformed,
                   const HoleFillParams& params, HoleFillReport& report) {
  std::vector<double> th, rh;
  const std::vector<double> h =
      PatchCurvature(deformed.points, hi.patch.triangles, params.images.apss);
  for (size_t i = 0; i < deformed.target.size(); ++i)
    if (hi.is_new[i]) th.push_back(2 * hi.scale * (deformed.target[i] - 0.5)), rh.push_back(h[i]);
  report.target_spread = Spread(th);
  report.result_spread = Spread(rh);
}

} // namespace

HoleVariations InpaintHole(const HoleImage& hi, size_t k, const HoleContext& ctx) {
  const HoleFillParams& params = *ctx.params;
  const vcg_ext::CoarseFillResult& coarse = *ctx.validation.coarse;
  const size_t holes = size_t(coarse.FilledCount());
  if (!params.hole_picks.empty() && params.hole_picks.size() != holes)
    throw std::invalid_argument("a pick is given for " + std::to_string(params.hole_picks.size()) +
                                " holes, and the mesh has " + std::to_string(holes) + " to fill");
  HoleVariations hv;
  hv.seconds.images = hi.seconds;
  hv.boundary_edges = coarse.holes[size_t(hi.hole)].boundary_edges;
  if (!hi.problem.empty()) {
    hv.choice.problem = hi.problem;
    return hv;
  }
  const bool listed = k < params.hole_picks.size();
  const int pick = listed ? params.hole_picks[k] : params.pick;
  const FillKind pick_kind = listed ? FillKind::kCoarse : params.pick_kind;
  if (pick < 0) {
    hv.choice.problem = "asked to keep its coarse fill";
    return hv;
  }
  // A hole in a plane (its loop planar, the faces around it in that plane or leaving it at a
  // crease) is filled exactly by the coarse fill's flat cap; curvature painted from farther
  // context (a crease or a curved face nearby) and fake holes cut there could only bend it.
  // Asked for by kind or number, a variation is still made.
  const bool automatic =
      pick == 0 && pick_kind == FillKind::kCoarse && !params.oracle && params.inpainted_dir.empty();
  if (automatic && coarse.holes[size_t(hi.hole)].planar_cap) {
    hv.choice.problem = "a flat cap in its plane; it keeps its coarse fill";
    return hv;
  }
  const auto t = Clock::now();
  hv.image = ToQImage(hi.image, false);
  hv.mask = MaskImage(hi.image);
  if (params.oracle) {
    if (!InpaintFromOracle(hi, *params.oracle, hv)) return hv;
  } else if (!params.inpainted_dir.empty()) {
    if (!InpaintFromFolder(hi, k, params, hv)) return hv;
  } else {
    InpaintFromBackend(hi, ctx, ctx.every_variation || !automatic, hv);
  }
  hv.seconds.inpaint = Since(t) - hv.seconds.validation;
  hv.choice.priors.has_creases = vcg_ext::CreaseLinesIntoHole(hi.patch) >= 2;
  if (pick > int(hv.variations.size()))
    throw std::invalid_argument("hole " + std::to_string(k + 1) + " has no variation " +
                                std::to_string(pick) + "; it has " + ListVariations(hv.choice));
  PickVariation(hv, pick, pick_kind);
  return hv;
}

/// Why the automatic pick kept the coarse fill, in a log's words.
std::string WhyItKeepsTheCoarseFill(const HoleChoice& c) {
  if (c.validation.no_evidence) return c.validation.note;
  if (c.validation.not_clear >= 0)
    return "no fill did clearly better than the coarse fill on the fake holes; it keeps it";
  return "the coarse fill validated best; it keeps it";
}

HoleOutcome FillOneHole(const HoleImage& hi, size_t k, const HoleContext& ctx) {
  const HoleFillParams& params = *ctx.params;
  const vcg_ext::CoarseHoleReport& coarse = ctx.validation.coarse->holes[size_t(hi.hole)];
  HoleOutcome out;
  HoleVariations& hv = out.variations;
  if (ctx.chosen) {
    hv = PreviewedHole(hi, k, *ctx.chosen);
  } else {
    hv = InpaintHole(hi, k, ctx);
    HoleChoice& c = hv.choice;
    if (c.problem.empty() && c.pick == 0)
      c.problem = (c.pick_note.empty() ? "" : c.pick_note + ", and ") + WhyItKeepsTheCoarseFill(c);
  }
  HoleFillReport& report = out.report;
  report.hole = hi.hole;
  report.boundary_edges = coarse.boundary_edges;
  report.new_vertices = int(coarse.new_vertices.size());
  report.choice = hv.choice;
  report.truth_spread = hv.truth_spread;
  report.seconds = hv.seconds;
  report.seconds.coarse = coarse.seconds;
  report.seconds.images = hi.seconds;
  if (!report.choice.problem.empty()) return out;

  report.kind = report.choice.PickedKind();
  const auto t = Clock::now();
  PatchDeformation deformed = ApplyPick(hi, hv, k, params);
  const vcg_ext::DeformationResult& dr = deformed.result;
  report.deformation = {dr.iterations, deformed.backoffs, dr.differing, dr.max_move};
  report.seconds.deform = Since(t);
  if (!dr.solved) {
    report.choice.problem =
        "the deformation would fold the patch or make it cross itself; it keeps its coarse fill";
    return out;
  }
  if (params.measure_detail) MeasureDetail(hi, deformed, params, report);
  out.points = std::move(deformed.points);
  if (!params.images_dir.empty())
    out.final_image = FinalCurvatureImage(hi, out.points, params.images.apss);
  return out;
}

void InpaintAgain(HoleVariations& hole, const InpaintParams& params) {
  if (hole.image.isNull()) throw std::runtime_error("this hole has no curvature image");
  const auto t = Clock::now();
  const InpaintParams at_scale = AtHoleScale(params, hole);
  PatchSite site;
  site.inpaint = &at_scale;
  site.image = hole.image;
  site.mask = hole.mask;
  // New variations from the seeded candidates (the continuations, and the exemplars where the
  // hole had them); the priors' variations, which no seed changes, stay after them.
  const PatchWork none;
  auto seeded = [&none](FillKind kind) {
    for (const FillCandidate* c : FillCandidates())
      if (c->Seeded() && kind == c->KindAt(none)) return true;
    return false;
  };
  HoleVariations kept;
  const std::vector<FillKind> had = hole.choice.kinds;
  for (size_t j = 0; j < hole.variations.size(); ++j)
    if (!seeded(had[j]))
      AddVariation(kept, std::move(hole.variations[j]), had[j],
                   j < hole.surfaces.size() ? std::move(hole.surfaces[j])
                                            : std::vector<Eigen::Vector3d>());
  hole.variations.clear();
  hole.choice.kinds.clear();
  hole.surfaces.clear();
  for (const FillCandidate* c : FillCandidates()) {
    const FillKind kind = c->KindAt(none);
    if (c->Seeded() &&
        (kind == FillKind::kContinuation || std::find(had.begin(), had.end(), kind) != had.end()))
      for (CandidateVariation& v : c->Variations(site, none))
        AddVariation(hole, std::move(v.image), kind, std::move(v.surface));
  }
  for (size_t j = 0; j < kept.variations.size(); ++j)
    AddVariation(hole, std::move(kept.variations[j]), kept.choice.kinds[j],
                 std::move(kept.surfaces[j]));
  hole.seconds.inpaint = Since(t);
  PickVariation(hole, 0, FillKind::kCoarse);
}

} // namespace curvature_inpaint
