#include "report/hole_words.h"

#include <algorithm>
#include <cmath>

namespace curvature_inpaint {

namespace {

/// The index of the smooth fill among the candidates, or -1.
int SmoothIndex(const std::vector<std::string>& candidates) {
  const auto it = std::find(candidates.begin(), candidates.end(), "coarse");
  return it == candidates.end() ? -1 : int(it - candidates.begin());
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

std::string KindInWords(const std::string& kind) {
  if (kind == "coarse") return "the smooth fill";
  if (kind == "continuation") return "the inpainted curvature";
  if (kind == "detail 0") return "the inpainted curvature, smooth";
  if (kind.compare(0, 7, "detail ") == 0)
    return "the inpainted curvature with detail " + kind.substr(7);
  if (kind == "exemplar") return "patches of the scan's own curvature";
  if (kind == "tri-laplacian") return "the surrounding curvature continued";
  if (kind == "symmetry") return "the curvature of the mirror image";
  if (kind == "symmetry surface") return "the mirror image of the other side";
  if (kind == "creases") return "the creases extended across it";
  if (kind == "face") return "the face around it extended";
  return kind;
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
  const bool validated = v.chosen >= 0 && size_t(v.chosen) < v.candidates.size();
  if (!f.problem.empty() || f.pick <= 0) {
    const std::string note = f.pick_note.empty() ? "" : " (" + f.pick_note + ")";
    if (validated && v.not_clear >= 0 && size_t(v.not_clear) < v.candidates.size() && f.pick <= 0)
      return "kept the smooth fill: no clear winner (" +
             KindInWords(v.candidates[size_t(v.not_clear)]) + " did best, " +
             TestCutsInWords(v, size_t(v.not_clear)) + ")" + note;
    if (validated && v.candidates[size_t(v.chosen)] == "coarse" && f.pick <= 0)
      return "kept the smooth fill, " + TestCutsInWords(v, size_t(v.chosen)) + note;
    return "kept the smooth fill" + (f.problem.empty() ? note : ": " + Reason(f.problem));
  }
  std::string what = KindInWords(f.PickedKind());
  if (f.asked) return what + " (variation " + std::to_string(f.pick) + "), as asked";
  std::string why;
  if (validated) {
    // The continuations are validated as detail amplitudes; the picked one is the chosen one.
    why = TestCutsInWords(v, size_t(v.chosen));
    if (f.PickedKind() == "continuation") what = KindInWords(v.candidates[size_t(v.chosen)]);
  } else {
    why = "the best-scored of its variations";
  }
  if (!f.pick_note.empty()) why += " (" + f.pick_note + ")";
  return why.empty() ? what : what + ", " + why;
}

} // namespace curvature_inpaint
