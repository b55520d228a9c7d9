// The tool's manual page, written from the same table of commands and options as its help, so
// that `man curvature-inpaint` says what `curvature-inpaint COMMAND --help` says.
#pragma once

#include <string>

namespace curvature_inpaint {
namespace cli {

/// The manual page in roff (man(7)), section 1, for the tool of `version`.
std::string ManualPage(const std::string& version);

} // namespace cli
} // namespace curvature_inpaint
