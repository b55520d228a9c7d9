#include "report/hole_words.h"

#include <algorithm>
#include <cmath>

namespace curvature_inpaint {

namespace {

/// The index of the smooth fill among the candidates, or -1.
int SmoothIndex(const std::vector<TriedFill>& candidates) {
  for (size_t c = 0; c < candidates.size(); ++c)
    if (candidates[c].kind == FillKind::kCoarse) return int(c);
  return -1;
}

/// A problem without its trailing "; it keeps its coarse fill" (the sentence says so already).
std::string Reason(std::string problem) {
  for (const char* tail : {"; it keeps its coarse fill", "; it keeps it",
                           "; with nothing to go on it keeps the smooth fill"}) {
    const std::string t = tail;
    if (problem.size() > t.size() && problem.compare(problem.size() - t.size(), t.size(), t) == 0)
      problem.erase(problem.size() - t.size());
  }
  return problem;
}

} // namespace

std::string KindInWords(FillKind kind) {
  switch (kind) {
  case FillKind::kCoarse:
    return "the smooth fill";
  case FillKind::kContinuation:
    return "the inpainted curvature";
  case FillKind::kExemplar:
    return "patches of the scan's own curvature";
  case FillKind::kLearned:
    return "the curvature as the learned inpainter completes it";
  case FillKind::kTriLaplacian:
    return "the surrounding curvature continued";
  case FillKind::kSymmetry:
    return "the curvature of the mirror image";
  case FillKind::kSymmetrySurface:
    return "the mirror image of the other side";
  case FillKind::kCreases:
    return "the creases extended across it";
  case FillKind::kFace:
    return "the face around it extended";
  }
  return FillKindName(kind);
}

std::string TriedFillInWords(const TriedFill& fill) {
  if (fill.amplitude < 0) return KindInWords(fill.kind);
  if (fill.amplitude == 0) return KindInWords(fill.kind) + ", smooth";
  // "detail 0.5" as the report names it: the same digits.
  return KindInWords(fill.kind) + " with " + TriedFillName(fill);
}

std::string TestCutsInWords(const ValidationRecord& v, size_t c) {
  const int smooth = SmoothIndex(v.candidates);
  if (smooth < 0 || c >= v.candidates.size() || v.per_fake_hole.empty()) return "";
  int wins = 0, cuts = 0;
  for (const std::vector<double>& errors : v.per_fake_hole) {
    if (c >= errors.size() || !std::isfinite(errors[c])) continue;
    ++cuts;
    if (int(c) == smooth) {
      bool best = true;
      for (double e : errors) best = best && !(std::isfinite(e) && e < errors[c]);
      wins += best;
    } else {
      wins += errors[c] < errors[size_t(smooth)];
    }
  }
  if (cuts == 0) return "";
  const std::string of = std::to_string(wins) + " of " + std::to_string(cuts) +
                         (cuts == 1 ? " test cut" : " test cuts");
  if (int(c) == smooth) return "best on " + of;
  std::string by;
  if (c < v.errors.size() && size_t(smooth) < v.errors.size() && v.errors[size_t(smooth)] > 0) {
    const double gain = 100 * (1 - v.errors[c] / v.errors[size_t(smooth)]);
    by = gain >= 0 ? ", " + std::to_string(int(std::lround(gain))) + " % closer"
                   : ", " + std::to_string(int(std::lround(-gain))) + " % farther on average";
  }
  return "better than the smooth fill on " + of + by;
}

std::string ChoiceInWords(const HoleChoice& f) {
  const ValidationRecord& v = f.validation;
  const bool validated = v.HasChoice();
  if (!f.problem.empty() || f.pick <= 0) {
    const std::string note = f.pick_note.empty() ? "" : " (" + f.pick_note + ")";
    if (validated && v.not_clear >= 0 && size_t(v.not_clear) < v.candidates.size() && f.pick <= 0)
      return "kept the smooth fill: no clear winner (" +
             TriedFillInWords(v.candidates[size_t(v.not_clear)]) + " did best, " +
             TestCutsInWords(v, size_t(v.not_clear)) + ")" + note;
    if (validated && v.Chosen().kind == FillKind::kCoarse && f.pick <= 0)
      return "kept the smooth fill, " + TestCutsInWords(v, size_t(v.chosen)) + note;
    return "kept the smooth fill" + (f.problem.empty() ? note : ": " + Reason(f.problem));
  }
  std::string what = KindInWords(f.PickedKind());
  if (f.asked) return what + " (variation " + std::to_string(f.pick) + "), as asked";
  std::string why;
  if (validated) {
    // The continuations are validated as detail amplitudes; the picked one is the chosen one.
    why = TestCutsInWords(v, size_t(v.chosen));
    if (f.PickedKind() == FillKind::kContinuation) what = TriedFillInWords(v.Chosen());
  } else {
    why = "the best-scored of its variations";
  }
  if (!f.pick_note.empty()) why += " (" + f.pick_note + ")";
  return why.empty() ? what : what + ", " + why;
}

} // namespace curvature_inpaint
