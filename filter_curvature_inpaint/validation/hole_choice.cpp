// Stage 8b, the pick (hole_choice.h).
#include "validation/hole_choice.h"

#include "inpaint/curvature_reading.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace curvature_inpaint {

FillKind HoleChoice::PickedKind() const {
  return pick > 0 && size_t(pick) <= kinds.size() ? kinds[size_t(pick - 1)] : FillKind::kCoarse;
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

bool ClearlyBetter(const std::vector<std::vector<double>>& per_fake_hole, size_t c, size_t smooth,
                   const ValidationParams& vp) {
  // A fake hole that both fill within 0.1 % of its radius (a flat face every fill closes
  // exactly) shows nothing between them.
  const double exact = 1e-3;
  double won = 0, total = 0;
  for (const std::vector<double>& e : per_fake_hole) {
    if (std::max(e[c], e[smooth]) <= exact) continue;
    total += e[smooth];
    if (e[c] < e[smooth]) won += e[smooth];
  }
  return total > 0 && won >= vp.min_win_share * total;
}

bool CoarseValidatedBest(const HoleChoice& choice) {
  const ValidationRecord& v = choice.validation;
  return v.HasChoice() && v.Chosen().kind == FillKind::kCoarse;
}

namespace {

/// The kind of variation the pick takes: the prior the validation chose where it chose one
/// (the tri-Laplacian fill, the mirror image, ...), else (an amplitude of the inpainter, the
/// coarse fill, or nothing validated) the continuation.
FillKind ValidatedKind(const ValidationRecord& v) {
  const bool prior = v.HasChoice() && v.Chosen().kind != FillKind::kCoarse &&
                     v.Chosen().kind != FillKind::kContinuation;
  return prior ? v.Chosen().kind : FillKind::kContinuation;
}

} // namespace

int AutomaticPick(const HoleChoice& choice) {
  if (CoarseValidatedBest(choice) || choice.validation.no_evidence) return 0;
  const FillKind validated = ValidatedKind(choice.validation);
  for (size_t j = 0; j < choice.kinds.size() && validated != FillKind::kContinuation; ++j)
    if (choice.kinds[j] == validated) return int(j) + 1;
  // A prior's variation is chosen only where it validated best: nothing is forced on a hole.
  int best = 0;
  for (size_t j = 0; j < choice.kinds.size() && j < choice.scores.size(); ++j)
    if (choice.kinds[j] == FillKind::kContinuation &&
        (best == 0 || choice.scores[j] > choice.scores[size_t(best - 1)]))
      best = int(j) + 1;
  return best > 0 || choice.kinds.empty() ? best : 1;
}

bool AutomaticPickCanTake(const HoleChoice& choice, FillKind kind) {
  if (CoarseValidatedBest(choice) || choice.validation.no_evidence) return false;
  // The validated prior's variation; where an amplitude of the embedded inpainter validated
  // best, or nothing was validated, the best-scored continuation.
  return kind == ValidatedKind(choice.validation);
}

void PickVariation(HoleVariations& hole, int pick, FillKind pick_kind) {
  HoleChoice& c = hole.choice;
  c.scores.clear();
  const std::vector<QImage>& v = hole.variations;
  for (size_t j = 0; j < v.size(); ++j)
    if (v[j].isNull())
      c.scores.push_back(std::numeric_limits<double>::quiet_NaN());
    else if (j > 0 && !v[j - 1].isNull() && v[j].cacheKey() == v[j - 1].cacheKey())
      c.scores.push_back(c.scores.back()); // one picture shared: the same score
    else
      c.scores.push_back(ScoreVariation(v[j], hole.mask));
  c.pick = pick > 0 ? std::min(pick, int(hole.variations.size())) : AutomaticPick(c);
  if (pick_kind != FillKind::kCoarse) {
    c.pick_note = std::string("it has no ") + FillKindName(pick_kind) + " variation";
    for (size_t j = 0; j < c.kinds.size(); ++j)
      if (c.kinds[j] == pick_kind) {
        c.pick = int(j) + 1;
        c.pick_note.clear();
        break;
      }
  }
  c.asked = pick > 0 || (pick_kind != FillKind::kCoarse && c.pick_note.empty());
}

} // namespace curvature_inpaint
