#include "manual_page.h"

#include "command_line.h"

namespace curvature_inpaint {
namespace cli {

namespace {

/// `text` as roff prints it: backslashes escaped, and a line that would start with a control
/// character kept as text.
std::string Roff(std::string text) {
  std::string out;
  for (char c : text) out += c == '\\' ? std::string("\\e") : std::string(1, c);
  return out.empty() || (out[0] != '.' && out[0] != '\'') ? out : "\\&" + out;
}

/// An option's name with its hyphens as minus signs, so that it can be copied from the page.
std::string OptionName(const std::string& name) {
  std::string out;
  for (char c : name) out += c == '-' ? std::string("\\-") : std::string(1, c);
  return out;
}

std::string CommandSection(const Command& command) {
  std::string text = ".SS \"" + std::string(command.name) + " " + command.synopsis + "\"\n";
  const std::vector<std::string> paragraphs = Paragraphs(command.description);
  for (size_t i = 0; i < paragraphs.size(); ++i)
    text += (i ? ".PP\n" : "") + Roff(paragraphs[i]) + "\n";
  for (const Option& o : command.options) {
    text += *o.value ? ".TP\n.BI \"" + OptionName(o.name) + " \" " + o.value
                     : ".TP\n.B " + OptionName(o.name);
    text += "\n" + Roff(o.help) + "\n";
  }
  return text;
}

} // namespace

std::string ManualPage(const std::string& version) {
  std::string text = ".TH CURVATURE-INPAINT 1 \"\" \"curvature-inpaint " + Roff(version) +
                     "\" \"User Commands\"\n"
                     ".SH NAME\n"
                     "curvature-inpaint \\- fill the holes of 3D scans with the shape that is "
                     "missing\n"
                     ".SH SYNOPSIS\n"
                     ".B curvature-inpaint\n.I COMMAND\n[options]\n.br\n"
                     ".B curvature-inpaint\n.I COMMAND\n.B \\-\\-help\n.br\n"
                     ".B curvature-inpaint \\-\\-version\n"
                     ".SH DESCRIPTION\n"
                     "Fills the holes of 3D scans with the shape that is missing. Options take "
                     "their value as\n.B \\-\\-opt value\nor\n.BR \\-\\-opt=value .\n"
                     ".SH COMMANDS\n";
  for (const Command& c : Commands()) text += CommandSection(c);
  text += ".SH \"EXIT STATUS\"\n"
          "0 done, 1 failed (the message says why; no input is changed), 2 a mistake in the "
          "command line.\n"
          ".SH \"SEE ALSO\"\n"
          ".BR meshlab (1),\n.BR meshlabserver (1);\n"
          "the guides in /usr/share/doc/curvature\\-inpaint/.\n";
  return text;
}

} // namespace cli
} // namespace curvature_inpaint
