// What the log, the montage and the dialog tell a person about a hole's fill: the kind of fill
// in words, and why it was chosen, from the record of the choice (the test cuts' errors, the
// pick, the reason a hole kept its smooth fill). The numbers stay in the report and in the
// verbose log.
#pragma once

#include "pipeline/hole_records.h"

#include <string>
#include <vector>

namespace curvature_inpaint {

/// A kind of fill in words (kSymmetrySurface: "the mirror image of the other side").
std::string KindInWords(FillKind kind);

/// A way the validation tried in words: its kind's, or for an amplitude of the continuation
/// "the inpainted curvature with detail 0.5".
std::string TriedFillInWords(const TriedFill& fill);

/// How candidate `c` did on the test cuts against the smooth fill: "better than the smooth
/// fill on 3 of 4 test cuts" (for the smooth fill itself: "best on 3 of 4 test cuts"); empty
/// where the hole was not validated.
std::string TestCutsInWords(const ValidationRecord& validation, size_t c);

/// What the hole was filled with and why, in a clause: "the mirror image of the other side,
/// better than the smooth fill on 4 of 4 test cuts", "kept the smooth fill: a flat cap in its
/// plane".
std::string ChoiceInWords(const HoleChoice& choice);

} // namespace curvature_inpaint
