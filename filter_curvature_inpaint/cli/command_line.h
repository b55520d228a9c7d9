// The command line's words: each command's options, declared once with their help, and the
// arguments as the commands take them out. The help a user reads and the options a command
// accepts come from the same table, so they cannot drift apart.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace curvature_inpaint {
namespace cli {

/// A mistake in the command line: reported in one line with a pointer to the command's help,
/// exit status 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// One option: its name, its value's placeholder (empty for a flag) and a line of help.
struct Option {
  const char* name;
  const char* value;
  std::string help;
};

/// One command: how it is called, what it does, and the options it accepts.
struct Command {
  const char* name;
  const char* synopsis; ///< the files it takes, e.g. "IN OUT"
  const char* summary;  ///< one line, for the list of commands
  const char* description;
  std::vector<Option> options;
};

/// Every command, in the order the help lists them.
const std::vector<Command>& Commands();

/// The command called `name`, or nullptr.
const Command* FindCommand(const std::string& name);

/// A command's description as paragraphs (split at its blank lines), each on one line.
std::vector<std::string> Paragraphs(const std::string& description);

/// The help of one command (its synopsis, description and every option it accepts).
std::string CommandHelp(const Command& command);

/// The help of the tool: the commands, a line each, and the exit statuses.
std::string ToolHelp();

/// The arguments after the command's name. `--opt=value` is read as `--opt value`.
class Args {
public:
  explicit Args(std::vector<std::string> args);

  /// Throws UsageError for an option `command` does not accept or one without its value.
  void Check(const Command& command) const;

  /// Whether `name` is among the arguments.
  bool Has(const std::string& name) const;
  /// Takes the flag `name` out; whether it was there.
  bool Flag(const std::string& name);
  /// Takes option `name` and its value out; `fallback` if it is not there.
  std::string Text(const std::string& name, const std::string& fallback);
  /// Every value of an option given several times, in order.
  std::vector<std::string> Texts(const std::string& name);
  /// An integer >= `lo`, or `fallback`.
  long Integer(const std::string& name, long fallback, long lo);
  /// A finite number above zero (from zero on when `zero_allowed`), or `fallback`.
  double Number(const std::string& name, double fallback, bool zero_allowed = false);
  /// The `count` file arguments left once every option is taken; throws UsageError otherwise.
  std::vector<std::string> Files(size_t count, const char* synopsis);
  /// What is left, in order.
  const std::vector<std::string>& Rest() const { return args_; }

private:
  std::vector<std::string> args_;
};

} // namespace cli
} // namespace curvature_inpaint
