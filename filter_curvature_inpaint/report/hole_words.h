// What the log, the montage and the dialog tell a person about a hole's fill: the kind of fill
// in words, and why it was chosen, from the record of the choice (the test cuts' errors, the
// pick, the reason a hole kept its smooth fill). The numbers stay in the report and in the
// verbose log.
#pragma once

#include "pipeline/hole_records.h"

#include <string>
#include <vector>

namespace curvature_inpaint {

/// A variation's or a validation candidate's kind ("symmetry surface", "detail 0.5", "coarse")
/// in words ("the mirror image of the other side").
std::string KindInWords(const std::string& kind);

/// How candidate `c` did on the test cuts against the smooth fill: "better than the smooth
/// fill on 3 of 4 test cuts" (for the smooth fill itself: "best on 3 of 4 test cuts"); empty
/// where the hole was not validated.
std::string TestCutsInWords(const ValidationRecord& validation, size_t c);

/// What the hole was filled with and why, in a clause: "the mirror image of the other side,
/// better than the smooth fill on 4 of 4 test cuts", "kept the smooth fill: a flat cap in its
/// plane".
std::string ChoiceInWords(const HoleChoice& choice);

} // namespace curvature_inpaint
