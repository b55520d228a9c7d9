// What a fill tells a person and a script about each hole: the log's lines (the numbers, and
// the same in words) and the JSON report.
#pragma once

#include "pipeline/hole_fill.h"

#include <string>
#include <vector>

namespace curvature_inpaint {

/// One line on a hole's fake-hole validation: the candidates' errors and the choice, or why
/// it was not validated.
std::string DescribeValidation(const ValidationRecord& validation);

/// Per hole of a preview: its validation line (as in the fill's log), then its variations by
/// number and kind with their scores and the pick fill makes with the same options, or why it
/// has none.
std::vector<std::string> DescribeVariations(const std::vector<HoleVariations>& holes);

/// The fill's log: the coarse fill's lines, the symmetry found, and per hole its validation
/// and its variation, deformation and times.
std::vector<std::string> DescribeHoleFill(const HoleFillResult& result);

/// One line per hole in words, "hole 3 (61 edges): the mirror image of the other side, better
/// than the smooth fill on 4 of 4 test cuts"; the numbers are DescribeHoleFill's.
std::vector<std::string> DescribeHolesInWords(const HoleFillResult& result);

/// The report as JSON (no keys, no URLs with credentials).
std::string HoleFillReportJson(const HoleFillResult& result, const HoleFillParams& params);

} // namespace curvature_inpaint
