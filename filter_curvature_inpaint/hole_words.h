// What the log, the montage and the dialog tell a person about a hole's fill: the kind of fill
// in words, and why it was chosen, from the record of the choice (the test cuts' errors, the
// pick, the reason a hole kept its smooth fill). The numbers stay in the report and in the
// verbose log.
#pragma once

#include <string>
#include <vector>

namespace curvature_inpaint {

/// A variation's or a validation candidate's kind ("symmetry surface", "detail 0.5", "coarse")
/// in words ("the mirror image of the other side").
std::string KindInWords(const std::string& kind);

/// The facts a choice is told from; HoleFillReport and HoleVariations both carry them.
struct ChoiceFacts {
  const std::vector<std::string>& candidates;               ///< validated ways to fill it
  const std::vector<std::vector<double>>& fake_hole_errors; ///< per test cut, per candidate
  int choice;                   ///< index into candidates; -1: not validated
  int pick;                     ///< 1-based variation; 0: the smooth fill kept
  const std::string& kind;      ///< of the variation picked
  bool asked;                   ///< the user asked for this variation or kind
  const std::string& pick_note; ///< why the kind asked for was not picked
  const std::string& problem;   ///< why the hole kept its smooth fill; empty if it did not
};

/// How candidate `c` did on the test cuts against the smooth fill: "better than the smooth
/// fill on 3 of 4 test cuts" (for the smooth fill itself: "best on 3 of 4 test cuts"); empty
/// where the hole was not validated.
std::string TestCutsInWords(const std::vector<std::string>& candidates,
                            const std::vector<std::vector<double>>& fake_hole_errors, size_t c);

/// What the hole was filled with and why, in a clause: "the mirror image of the other side,
/// better than the smooth fill on 4 of 4 test cuts", "kept the smooth fill: a flat cap in its
/// plane".
std::string ChoiceInWords(const ChoiceFacts& facts);

} // namespace curvature_inpaint
