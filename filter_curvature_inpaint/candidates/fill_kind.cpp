#include "candidates/fill_kind.h"

#include <QString>

namespace curvature_inpaint {

namespace {

/// By FillKind.
constexpr const char* kNames[] = {"coarse",           "continuation",  "exemplar",
                                  "learned",          "tri-laplacian", "symmetry",
                                  "symmetry surface", "creases",       "face"};
constexpr size_t kKinds = sizeof kNames / sizeof *kNames;

} // namespace

const char* FillKindName(FillKind kind) {
  return kNames[static_cast<size_t>(kind)];
}

std::vector<FillKind> VariationKinds() {
  std::vector<FillKind> kinds;
  for (size_t k = 0; k < kKinds; ++k)
    if (static_cast<FillKind>(k) != FillKind::kCoarse) kinds.push_back(static_cast<FillKind>(k));
  return kinds;
}

bool VariationKindNamed(const std::string& name, FillKind* kind) {
  for (FillKind k : VariationKinds())
    if (name == FillKindName(k)) {
      *kind = k;
      return true;
    }
  return false;
}

std::string TriedFillName(const TriedFill& fill) {
  if (fill.amplitude < 0) return FillKindName(fill.kind);
  return "detail " + QString::number(fill.amplitude, 'g', 3).toStdString();
}

} // namespace curvature_inpaint
