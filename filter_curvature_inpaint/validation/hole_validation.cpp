// Stage 8b, the fake-hole validation (hole_choice.h).
#include "validation/hole_choice.h"

#include "candidates/patch_fills.h"
#include "pipeline/pipeline.h"
#include "validation/fake_holes.h"

#include <vcg_ext/fill_extent.h>
#include <vcg_ext/parallel_for.h>

#include <QString>

#include <algorithm>
#include <sstream>
#include <vector>

namespace curvature_inpaint {

namespace {

/// How curved the known surface around a patch's fill is for its size: the spread of the known
/// vertices' mean curvature times the fill's radius (both in the patch's units).
double RingCurvature(const HoleImage& h) {
  Eigen::Vector3d centre;
  double radius = 0;
  if (!vcg_ext::FillExtent(h.patch.points, h.is_new, &centre, &radius)) return 0;
  std::vector<double> known;
  for (size_t i = 0; i < h.curvature.size(); ++i)
    if (!h.is_new[i]) known.push_back(h.curvature[i]);
  return Spread(known) * radius;
}

/// One candidate of the validation: a way to fill, at one of its amplitudes where it has them.
struct ValidationCandidate {
  const FillCandidate* fill = nullptr;
  TriedFill tried;      ///< its kind and amplitude, as the record keeps them
  size_t amplitude = 0; ///< index into its ValidatedAmplitudes
};

/// The candidates of a hole, in the order of the report: each way to fill that these
/// parameters turn on and the hole itself has (`hole`: its shared work), the continuation once
/// per detail amplitude.
std::vector<ValidationCandidate> ValidationCandidates(const HoleFillParams& params,
                                                      const PatchWork& hole) {
  std::vector<ValidationCandidate> c;
  for (const FillCandidate* fill : FillCandidates()) {
    if (!fill->Enabled(params) || !fill->Applies(hole)) continue;
    const std::vector<double> amplitudes = fill->ValidatedAmplitudes(params);
    const FillKind kind = fill->KindAt(hole);
    if (amplitudes.empty()) c.push_back({fill, {kind, -1}, 0});
    for (size_t i = 0; i < amplitudes.size(); ++i) c.push_back({fill, {kind, amplitudes[i]}, i});
  }
  return c;
}

/// One fake hole of a hole's validation: its image and every candidate's fill of it.
struct FakeHoleTrial {
  const FakeHole* fake = nullptr;
  CurvatureImagesResult images;
  int hole = -1;                                   ///< its hole in `images`
  std::vector<std::vector<Eigen::Vector3d>> fills; ///< per candidate, the whole patch
  std::vector<double> errors;                      ///< per candidate: RMS / the fake's radius
  std::vector<char> applies; ///< per candidate: it has a fill of its own (a surface prior may not)
  const HoleImage& Hole() const { return images.holes[size_t(hole)]; }
};

/// Fills fake hole `fake` with every candidate and scores each against the surface cut out.
/// False where the fake hole could not be filled (it then does not count).
bool TryFakeHole(const FakeHole& fake, const std::vector<ValidationCandidate>& candidates,
                 const HoleFillParams& params, const InpaintParams& inpaint,
                 const ValidationContext& ctx, FakeHoleTrial& t) {
  const ValidationParams& vp = params.validation;
  t.fake = &fake;
  StopIfAsked(ctx);
  CMeshO local;
  CopyMesh(fake.holed, local);
  CurvatureImagesParams ip = params.images;
  ip.coarse.keep_longest_open = true; // the piece's own border
  ip.coarse.max_hole_edges = 0;
  ip.coarse.max_hole_diameter = 0;
  ip.coarse.selected_only = false;
  ip.coarse.threads = 1; // the holes and their fake holes already run in parallel
  ip.color_vertices = false;
  ip.image_size = std::min(ip.image_size, vp.image_size);
  try {
    t.images = ComputeCurvatureImages(local, ip);
  } catch (const std::exception&) {
    return false;
  }
  for (size_t h = 0; h < t.images.holes.size(); ++h)
    if (t.images.holes[h].problem.empty()) t.hole = int(h);
  if (t.hole < 0) return false;
  const HoleImage& f = t.Hole();
  const auto fill = FillTriangles(f.patch);
  // The fake holes are deformed in direct mode whatever the hole's: paper mode's hundreds of
  // steps, twenty times over, would take a minute a hole.
  HoleFillParams direct = params;
  direct.mode = DeformationMode::kDirect;
  InpaintParams one = inpaint;
  one.detail_scale = FillSpacingPixels(f);
  // Embedded only, and perhaps on another thread than the caller's: never MeshLab's callback.
  one.http.cancelled = nullptr;
  PatchSite site;
  site.patch = &f;
  site.params = &direct;
  site.inpaint = &one;
  site.image = ToQImage(f.image, false);
  site.mask = MaskImage(f.image);
  // The fake hole's mirror image, on the known surface without the fake hole's own (which the
  // whole mesh still has).
  site.symmetry = ctx.symmetry;
  site.frame = t.images.coarse.box;
  site.excluded_centre = fake.centre;
  site.excluded_radius = 1.25 * fake.radius / t.images.coarse.box.scale;
  std::vector<const FillCandidate*> used;
  for (const ValidationCandidate& c : candidates) used.push_back(c.fill);
  StopIfAsked(ctx);
  PatchWork work = MakePatchWork(site, used);
  StopIfAsked(ctx);
  work.completions = InpaintEmbeddedAmplitudes(site.image, site.mask, one, vp.details);
  FakeHoleScorer scorer(fake);
  for (const ValidationCandidate& c : candidates) {
    StopIfAsked(ctx);
    FakeHoleFill filled = c.fill->FillFakeHole(site, work, c.amplitude);
    t.applies.push_back(filled.applies);
    t.fills.push_back(filled.applies ? std::move(filled.points) : f.patch.points);
    t.errors.push_back(filled.applies ? scorer.Error(t.fills.back(), fill) / fake.radius : 0.0);
  }
  return true;
}

/// Where a surface prior has no fill for a fake hole it stands for what the hole would get
/// without the surface priors, the candidate with the lowest error over all fake holes among
/// the others, so that it wins only where it applies and does better.
void StandInForSurfacePriors(const std::vector<ValidationCandidate>& candidates,
                             std::vector<FakeHoleTrial>& trials) {
  const size_t n = candidates.size();
  std::vector<double> sum(n, 0.0);
  for (const FakeHoleTrial& t : trials)
    for (size_t c = 0; c < n; ++c) sum[c] += t.errors[c];
  size_t fallback = n;
  for (size_t c = 0; c < n; ++c)
    if (!candidates[c].fill->IsSurfacePrior() && (fallback == n || sum[c] < sum[fallback]))
      fallback = c;
  if (fallback == n) return;
  for (FakeHoleTrial& t : trials)
    for (size_t c = 0; c < n; ++c)
      if (candidates[c].fill->IsSurfacePrior() && !t.applies[c])
        t.errors[c] = t.errors[fallback], t.fills[c] = t.fills[fallback];
}

/// The candidate with the lowest mean error; among those within `tie` of it (a fraction), one
/// whose detail ratio on the fake holes lies in 0.7-1.3 (as much detail as the cut surface
/// had), the closest of those: four fake holes cannot tell a few per cent apart, the detail
/// ratio says which fill looks like the surface around it. The ratios cost curvature fits, so
/// they are measured only where they break a tie (-1 elsewhere).
struct CandidateChoice {
  size_t chosen = 0;
  std::vector<double> detail; ///< per candidate: its detail ratio, or -1
};

CandidateChoice ChooseCandidate(const std::vector<double>& error,
                                const std::vector<FakeHoleTrial>& trials,
                                const HoleFillParams& params) {
  const size_t n = error.size();
  CandidateChoice out;
  std::vector<double>& detail = out.detail;
  detail.assign(n, -1.0);
  const size_t best = size_t(std::min_element(error.begin(), error.end()) - error.begin());
  out.chosen = best;
  std::vector<size_t> tied;
  for (size_t c = 0; c < n; ++c)
    if (error[c] <= (1 + params.validation.tie) * error[best]) tied.push_back(c);
  if (tied.size() < 2) return out;
  const double used = double(trials.size());
  for (size_t c : tied) detail[c] = 0;
  for (const FakeHoleTrial& t : trials) {
    const FakeHole& fake = *t.fake;
    const ApssSupport support =
        ApssNeighbourhood(fake.truth, vcg_ext::VertexFaces(fake.truth), t.images.coarse.box,
                          fake.cut_vertices, params.images.apss_rings);
    std::vector<int> query(fake.cut_vertices.size());
    for (size_t i = 0; i < query.size(); ++i) query[i] = int(i);
    const double truth = Spread(
        vcg_ext::ApssMeanCurvature(support.points, support.normals, query, params.images.apss));
    for (size_t c : tied) {
      const std::vector<double> h =
          PatchCurvature(t.fills[c], t.Hole().patch.triangles, params.images.apss);
      std::vector<double> free_h;
      for (size_t i = 0; i < h.size(); ++i)
        if (t.Hole().is_new[i]) free_h.push_back(h[i]);
      detail[c] += truth > 0 ? Spread(free_h) / truth / used : 0.0;
    }
  }
  auto natural = [&](size_t c) { return detail[c] >= 0.7 && detail[c] <= 1.3; };
  for (size_t c : tied)
    if (natural(c) && (!natural(out.chosen) || error[c] < error[out.chosen])) out.chosen = c;
  return out;
}

/// The index of the smooth (coarse) fill among the candidates; candidates.size() where it is
/// not one.
size_t SmoothFillIndex(const std::vector<ValidationCandidate>& candidates) {
  for (size_t c = 0; c < candidates.size(); ++c)
    if (candidates[c].tried.kind == FillKind::kCoarse) return c;
  return candidates.size();
}

/// Fake holes cut where the surface curves far more than around the hole (a near-flat spot
/// among a machined part's fillets) reward a prior for bending the fill as they bend; the
/// hole's own flat surroundings ask for the smooth cap. Whether the hole's ring is more than
/// `max_flatter` times flatter than its fake holes' (median): the note that says so, empty where
/// it is not.
std::string FlatterThanFakeHoles(const HoleImage& hi, const std::vector<FakeHoleTrial>& trials,
                                 double max_flatter) {
  std::vector<double> fake_ring;
  for (const FakeHoleTrial& t : trials) fake_ring.push_back(RingCurvature(t.Hole()));
  std::nth_element(fake_ring.begin(), fake_ring.begin() + std::ptrdiff_t(fake_ring.size() / 2),
                   fake_ring.end());
  const double own_ring = RingCurvature(hi), fakes_ring = fake_ring[fake_ring.size() / 2];
  if (!(max_flatter > 0 && fakes_ring > max_flatter * own_ring)) return "";
  std::ostringstream out;
  out.precision(3);
  if (own_ring > 0)
    out << "the surface around it is " << fakes_ring / own_ring
        << " times flatter than around its fake holes";
  else
    out << "the surface around it is flat, unlike around its fake holes";
  out << ": they do not show how it fills, so it keeps the smooth coarse fill";
  return out.str();
}

} // namespace

void StopIfAsked(const ValidationContext& ctx) {
  if (ctx.stop_asked && ctx.stop_asked()) throw vcg_ext::CancelledError();
}

bool ValidatesOnFakeHoles(const HoleFillParams& p) {
  return p.validation.fake_holes > 0 && p.inpaint.backend == Backend::kEmbedded && !p.oracle &&
         p.inpainted_dir.empty();
}

ValidationRecord ValidateHole(const HoleImage& hi, const HoleFillParams& params,
                              const InpaintParams& inpaint, const ValidationContext& ctx,
                              const PatchWork& hole) {
  const ValidationParams& vp = params.validation;
  const std::vector<ValidationCandidate> candidates = ValidationCandidates(params, hole);
  ValidationRecord record;
  for (const ValidationCandidate& c : candidates) record.candidates.push_back(c.tried);
  FakeHoleParams fp;
  fp.count = vp.fake_holes;
  fp.seed = params.inpaint.seed;
  fp.piece = 1 + params.images.segmentation.context;
  if (ctx.symmetry) fp.mirror_planes = MirrorPlanesInMeshUnits(*ctx.symmetry);
  std::string why;
  const auto fakes = CutFakeHoles(*ctx.mesh, *ctx.vf, *ctx.coarse, hi.hole, fp, &why);
  // The fake holes are independent: on the threads the other holes leave over, each into its
  // own slot, so the choice does not depend on how many there are.
  std::vector<FakeHoleTrial> tried(fakes.size());
  std::vector<char> filled(fakes.size(), 0);
  vcg_ext::ParallelFor(int(fakes.size()), ctx.threads, [&](int i) {
    filled[size_t(i)] =
        TryFakeHole(*fakes[size_t(i)], candidates, params, inpaint, ctx, tried[size_t(i)]);
  });
  std::vector<FakeHoleTrial> trials;
  for (size_t i = 0; i < tried.size(); ++i)
    if (filled[i]) trials.push_back(std::move(tried[i]));
  StandInForSurfacePriors(candidates, trials);
  record.fake_holes = int(trials.size());
  for (const FakeHoleTrial& t : trials) {
    record.mirror_fake_holes += t.fake->at_mirror_place;
    record.per_fake_hole.push_back(t.errors);
  }
  if (trials.empty()) {
    record.candidates.clear();
    record.no_evidence = true;
    record.note = (why.empty() ? std::string("no fake hole near it could be filled") : why) +
                  "; with nothing to go on it keeps the smooth fill";
    return record;
  }
  std::vector<double> error(candidates.size(), 0.0);
  for (const FakeHoleTrial& t : trials)
    for (size_t c = 0; c < candidates.size(); ++c) error[c] += t.errors[c];
  for (double& e : error) e /= double(trials.size());
  const CandidateChoice chosen = ChooseCandidate(error, trials, params);
  size_t choice = chosen.chosen;
  const size_t smooth = SmoothFillIndex(candidates);
  const std::string flatter =
      smooth < candidates.size() ? FlatterThanFakeHoles(hi, trials, vp.max_flatter) : "";
  if (!flatter.empty()) {
    choice = smooth;
    why = why.empty() ? flatter : why + "; " + flatter;
  }
  if (smooth < candidates.size() && choice != smooth &&
      !ClearlyBetter(record.per_fake_hole, choice, smooth, vp)) {
    record.not_clear = int(choice);
    choice = smooth;
  }
  record.errors = error;
  record.detail = chosen.detail;
  record.chosen = int(choice);
  if (!why.empty()) record.note = why;
  return record;
}

} // namespace curvature_inpaint
