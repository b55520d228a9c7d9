// The kinds of fill, and the ways the validation tries them, as values inside the pipeline.
// Their names ("symmetry surface", "detail 0.5") appear only at the edges: the report, the
// log, the dialog and `--pick`.
#pragma once

#include <string>
#include <vector>

namespace curvature_inpaint {

/// The kinds of fill, in the order of a hole's variations and of the validation's report.
enum class FillKind {
  kCoarse,          ///< "coarse": the coarse fill as it is
  kContinuation,    ///< "continuation": the backend's completion of the curvature image
  kExemplar,        ///< "exemplar": patches of the known curvature copied in
  kLearned,         ///< "learned": the continuation corrected by the network trained here
  kTriLaplacian,    ///< "tri-laplacian": the fill faired to continue the curvature around it
  kSymmetry,        ///< "symmetry": the curvature of the mirror image
  kSymmetrySurface, ///< "symmetry surface": the mirror image itself
  kCreases,         ///< "creases": the faces around it extended until they meet
  kFace,            ///< "face": the one smooth face around it extended
};

/// The kind's name at the edges (report, log, dialog, `--pick`).
const char* FillKindName(FillKind kind);

/// The kinds a variation can have (all but the coarse fill), in FillKind's order: what
/// `--pick` takes.
std::vector<FillKind> VariationKinds();

/// The variation kind named `name` (FillKindName); false where no variation kind has that name.
bool VariationKindNamed(const std::string& name, FillKind* kind);

/// One way the validation tries a hole's fill: a kind, and for the embedded inpainter's
/// continuation the detail amplitude it is tried at.
struct TriedFill {
  FillKind kind = FillKind::kCoarse;
  double amplitude = -1; ///< -1: a kind without amplitudes
};

inline bool operator==(const TriedFill& a, const TriedFill& b) {
  return a.kind == b.kind && a.amplitude == b.amplitude;
}

/// As the report and the log name it: the kind's name, or "detail A" at an amplitude.
std::string TriedFillName(const TriedFill& fill);

} // namespace curvature_inpaint
