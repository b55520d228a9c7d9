// The settings a person gives the hole fill, each declared once: its name in filter scripts,
// its label, its command-line option, its help, its range and where it lives in
// HoleFillParams. MeshLab's filter table (plugin/filter_table.cpp), the range checks
// (CheckHoleFillParams and the stages' own checks), the dialog's tooltips and ranges
// (gui/hole_fill_dialog.cpp) and the command line's help (cli/command_line.cpp) are made from
// this table, so a setting added here reaches all four.
#pragma once

#include <string>
#include <vector>

namespace curvature_inpaint {

struct HoleFillParams;

enum class Setting {
  kBackend,
  kServerUrl,
  kModel,
  kPrompt,
  kVariations,
  kFakeHoles,
  kDetail,
  kSymmetry,
  kExemplar,
  kLearned,
  kCreases,
  kTriLaplacian,
  kMode,
  kSimilitude,
  kTransformationConstant,
  kImageSize,
  kMaxHoleSize,
  kKeepLongestOpen,
  kSelected,
};

enum class SettingType { kBool, kInt, kFloat, kChoice, kText };

struct SettingSpec {
  Setting id;
  SettingType type;
  const char* script_name; ///< in filter scripts (meshlabserver XML, MeshLab's history)
  const char* label;       ///< in MeshLab's parameter dialog
  /// On the command line. A bool's option is a switch: "--no-..." turns the setting off, any
  /// other turns it on.
  const char* option;
  const char* value_name; ///< the option's placeholder ("K"); "" for a switch
  const char* brief;      ///< the command line's line of help, without the default
  const char* help;       ///< the tooltip, without the range
  const char* what;       ///< in an error: "the fake holes per hole must be from 0 to 16"
  double min, max; ///< the range checked (a choice's is its indices, max unused; a text has none)
};

/// Every setting, in Setting's order.
const std::vector<SettingSpec>& Settings();

const SettingSpec& SettingOf(Setting id);

/// The settings a person starts from, on every surface: the library's defaults, with the
/// curvature images at 512 pixels (the size Stable Diffusion takes; the stage's own 1024 is
/// DALL-E 2's).
HoleFillParams DefaultSettings();

/// The setting's value in `p` (a bool 0 or 1, a choice its index; a text 0, see SettingText).
double SettingValue(Setting id, const HoleFillParams& p);

/// A text setting's value in `p`; empty for the others.
std::string SettingText(Setting id, const HoleFillParams& p);

/// Sets it in `p` (a bool: nonzero is on; a choice: the index, as it is).
void SetSetting(Setting id, double value, HoleFillParams& p);

/// A choice's names, by index (the backends, the deformation modes); empty for the others.
std::vector<std::string> SettingChoices(Setting id);

/// Throws vcg_ext::InvalidParameterError naming the setting where `value` is out of its range.
void RequireSetting(Setting id, double value);

/// The tooltip: its help, and for a number its range.
std::string SettingHelp(const SettingSpec& s);

/// The command line's line of help: its brief, and for a value its default.
std::string SettingBrief(const SettingSpec& s);

} // namespace curvature_inpaint
