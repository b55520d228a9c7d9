#include "command_line.h"

#include "pipeline/fill_settings.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

namespace curvature_inpaint {
namespace cli {

namespace {

using Options = std::vector<Option>;

/// A setting of the hole fill as an option (pipeline/fill_settings.h): its name, placeholder
/// and line of help with its default.
Option FromSetting(Setting id) {
  const SettingSpec& s = SettingOf(id);
  return {s.option, s.value_name, SettingBrief(s)};
}

Options Join(std::initializer_list<Options> groups) {
  Options all;
  for (const Options& g : groups) all.insert(all.end(), g.begin(), g.end());
  return all;
}

Options Without(Options options, std::initializer_list<const char*> names) {
  options.erase(std::remove_if(options.begin(), options.end(),
                               [&](const Option& o) {
                                 return std::any_of(names.begin(), names.end(), [&](const char* n) {
                                   return std::string(n) == o.name;
                                 });
                               }),
                options.end());
  return options;
}

/// Which holes are filled: the same for every command that finds holes, so that they number
/// the holes alike.
const Options kHoleSelection{
    FromSetting(Setting::kMaxHoleSize),
    {"--max-hole-diameter", "F",
     "leave open the holes whose border spans more than F x the bounding-box diagonal"},
    FromSetting(Setting::kKeepLongestOpen),
    FromSetting(Setting::kSelected),
};

const Options kThreads{{"--threads", "T", "holes filled at once (default: one per core)"}};

const Options kOutput{
    {"--in-place", "", "allow OUT to be IN: the scan is then replaced, whole or not at all"},
    {"--mark-new", "",
     "select the new faces in OUT (a .ply; MeshLab shows them selected, as after Close Holes)"},
};

const Options kBackend{
    FromSetting(Setting::kBackend),
    FromSetting(Setting::kServerUrl),
    {"--url-file", "FILE", "the services' addresses, one a line ('#' starts a comment)"},
    {"--per-server", "M", "requests in flight on each server (default 1)"},
    FromSetting(Setting::kModel),
    FromSetting(Setting::kPrompt),
    {"--negative-prompt", "TEXT", "what it must not show (sd-webui, stability, comfyui)"},
    {"--seed", "S", "the inpainter's seed (default 1): the same seed, the same fill"},
    {"--workflow", "FILE", "comfyui: an edited copy of the shipped workflow"},
    {"--timeout", "SECONDS", "per request (default 300)"},
    {"--retries", "N", "tries again after a failed request (default 3)"},
    {"--max-response-mb", "MB", "the largest answer a service may send (default 64)"},
    FromSetting(Setting::kDetail),
};

const Options kFill = Join(
    {kBackend,
     {
         FromSetting(Setting::kVariations),
         {"--pick", "WHICH",
          "auto (default: the fill that did clearly best on test cuts near the hole, else the "
          "smooth fill), coarse (the smooth fill), a variation number, a kind (continuation, "
          "exemplar, learned, tri-laplacian, symmetry, symmetry surface, creases, face), or one "
          "entry "
          "per hole: A,B,..."},
         FromSetting(Setting::kFakeHoles),
         {"--fake-hole-size", "PX", "the test cuts' images (default 128)"},
         FromSetting(Setting::kSymmetry),
         FromSetting(Setting::kExemplar),
         FromSetting(Setting::kLearned),
         FromSetting(Setting::kCreases),
         FromSetting(Setting::kTriLaplacian),
         FromSetting(Setting::kMode),
         FromSetting(Setting::kSimilitude),
         FromSetting(Setting::kTransformationConstant),
         {"--curvature-passes", "N", "direct mode: extra rounds towards the image (default 0)"},
         {"--density", "D", "the fill's vertex density (default 2; the coarse fill's 1.41)"},
         FromSetting(Setting::kImageSize),
         {"--context", "C", "the known ring around a hole, in hole radii (default 1)"},
         {"--images", "DIR", "also write every hole's images and a montage into DIR"},
         {"--from-images", "DIR",
          "deform to hole_<k>_inpainted.png, inpainted by hand in DIR after `images`"},
     },
     kHoleSelection,
     kThreads});

std::vector<Command> MakeCommands() {
  return {
      {"fill", "IN OUT", "fill every hole of a scan with the shape that is missing",
       "Fills every hole of IN and writes OUT: each hole is closed smoothly, its curvature is\n"
       "painted as an image, completed by the inpainter, and the fill is deformed to follow it.\n"
       "Test cuts in the known surface near each hole choose among the ways to fill it (the\n"
       "smooth fill among them), so a hole is never given a shape that did worse there.\n"
       "OUT must differ from IN unless --in-place is given. Holes are numbered as `info` lists\n"
       "them.",
       Join({kFill,
             {{"--report", "FILE.json", "write what was done to each hole, as JSON"},
              {"--verbose", "",
               "log the numbers too: the test cuts' errors, the scores, the times per stage"},
              {"--oracle", "GT",
               "benchmarks: deform to the curvature of GT, the mesh before its holes were cut"}},
             kOutput})},
      {"preview", "IN DIR", "show each hole's variations without changing the scan",
       "Writes into DIR every hole's images (hole_<k>_coarse.png, hole_<k>_mask.png,\n"
       "hole_<k>_variation_<j>.png) and montage.png, and prints per hole its variations and the\n"
       "one fill would pick. `fill IN OUT --pick A,B,...` with the same options then applies\n"
       "a choice per hole. IN is only read.",
       Without(kFill, {"--images"})},
      {"coarse", "IN OUT", "close every hole smoothly (the first stage alone)",
       "Closes every hole of IN with a smooth, refined and faired patch and writes OUT.\n"
       "Formats: .ply .off .obj .stl. OUT must differ from IN unless --in-place is given.",
       Join({kHoleSelection,
             kThreads,
             {{"--liepa-max-edges", "M",
               "holes up to M edges get the optimal triangulation, larger ones ears (200)"},
              {"--no-refine", "", "do not add vertices inside the fill"},
              {"--no-fair", "", "do not smooth the fill"}},
             kOutput})},
      {"info", "IN", "count a scan's holes and number them as the other commands do",
       "Prints the vertex, face and hole counts of IN, and a line per hole: its number (the one\n"
       "fill, preview, the report and --pick use), its boundary edges, its diameter and its\n"
       "centre. Give the hole options fill will get, and the numbers are fill's.",
       Join({kHoleSelection,
             {{"--symmetry", "", "also print the mirror planes the symmetry prior finds"}}})},
      {"images", "IN DIR", "write each hole's curvature image, to inpaint by hand",
       "Closes the holes of IN and writes into DIR per hole its curvature image\n"
       "(hole_<k>_curvature.png), the same with the hole transparent (hole_<k>_rgba.png), its\n"
       "mask (hole_<k>_mask.png, white = hole), hole_<k>.json, and montage.png. Inpaint them in\n"
       "any editor and run `fill IN OUT --from-images DIR`.",
       Join({{{"--size", "PX", "pixels per side (default 1024)"},
              {"--context", "C", "the known ring around a hole, in hole radii (default 1)"},
              {"--filter-scale", "S", "the curvature's smoothing scale (default 4)"}},
             kHoleSelection,
             kThreads})},
      {"inpaint", "IMAGE MASK OUTDIR", "complete one curvature image with an inpainter",
       "Completes the hole (white in MASK) of a curvature image into N variations,\n"
       "OUTDIR/variation_<i>.png. See docs/backends.md for each service.",
       Join({kBackend,
             {{"-n", "N", "variations (default 4)"},
              {"--size", "PX", "the size the backend works at (default: its own)"}}})},
      {"batch", "MANIFEST OUTDIR", "fill a collection of scans, resumably, on one machine or many",
       "Fills every scan of MANIFEST (a folder of .ply/.obj/.off/.stl files, or a text file of\n"
       "paths, each optionally followed by its own fill options) into OUTDIR, one JSON line per\n"
       "scan in OUTDIR/results.jsonl. A scan done before with the same bytes and options is\n"
       "skipped; a killed batch loses no finished scan; a failed scan is recorded and the rest\n"
       "go on (exit status 1). The fill options hold for every scan.\n\n"
       "`batch --summary OUTDIR` prints the results of every shard as a table.",
       Join({{{"--jobs", "J", "scans at once (default 1)"},
              {"--shard", "K/N",
               "every N-th scan from the K-th (default: a Slurm job array's task)"},
              {"--summary", "OUTDIR", "summarize the results in OUTDIR instead"}},
             Without(kFill, {"--images", "--from-images"})})},
      {"punch",
       "IN OUT",
       "cut a round hole into a mesh (to test a fill against the truth)",
       "Removes every face with a vertex within R x the bounding-box diagonal of vertex V.",
       {{"--seed-vertex", "V", "the hole's centre, a vertex index (required)"},
        {"--radius-frac", "R", "the hole's radius, a fraction of the diagonal (required)"},
        {"--in-place", "", "allow OUT to be IN: the mesh is then replaced, whole or not at all"}}},
  };
}

bool TakesValue(const Option& o) {
  return o.value[0] != '\0';
}

const Option* FindOption(const Command& command, const std::string& name) {
  for (const Option& o : command.options)
    if (name == o.name) return &o;
  return nullptr;
}

/// A command-line word that is an option's name rather than a file or a value.
bool LooksLikeOption(const std::string& word) {
  return word.size() > 1 && word[0] == '-' && !std::isdigit(static_cast<unsigned char>(word[1]));
}

} // namespace

const std::vector<Command>& Commands() {
  static const std::vector<Command> commands = MakeCommands();
  return commands;
}

const Command* FindCommand(const std::string& name) {
  for (const Command& c : Commands())
    if (name == c.name) return &c;
  return nullptr;
}

/// `text` wrapped to a terminal's 80 columns, each line after the first indented by `column`.
std::string Wrap(const std::string& help, size_t column) {
  const size_t width = 80;
  std::string text;
  size_t used = column;
  size_t from = 0;
  while (from < help.size()) {
    size_t end = help.find(' ', from);
    if (end == std::string::npos) end = help.size();
    const std::string word = help.substr(from, end - from);
    if (used > column && used + 1 + word.size() > width) {
      text += "\n" + std::string(column, ' ');
      used = column;
    } else if (used > column) {
      text += ' ';
      ++used;
    }
    text += word;
    used += word.size();
    from = end + 1;
  }
  return text + "\n";
}

/// `head` (an option and its value) in a column of its own, then `help` beside it.
std::string HelpLine(const std::string& head, const std::string& help) {
  const size_t column = 26;
  return (head.size() + 2 <= column ? head + std::string(column - head.size(), ' ')
                                    : head + "\n" + std::string(column, ' ')) +
         Wrap(help, column);
}

std::vector<std::string> Paragraphs(const std::string& description) {
  std::vector<std::string> paragraphs;
  size_t from = 0;
  while (from < description.size()) {
    size_t end = description.find("\n\n", from);
    if (end == std::string::npos) end = description.size();
    std::string paragraph = description.substr(from, end - from);
    std::replace(paragraph.begin(), paragraph.end(), '\n', ' ');
    paragraphs.push_back(paragraph);
    from = end + 2;
  }
  return paragraphs;
}

std::string CommandHelp(const Command& command) {
  std::string text = "usage: curvature-inpaint " + std::string(command.name) + " " +
                     command.synopsis + " [options]\n\n";
  const std::vector<std::string> paragraphs = Paragraphs(command.description);
  for (size_t i = 0; i < paragraphs.size(); ++i) text += (i ? "\n" : "") + Wrap(paragraphs[i], 0);
  text += "\noptions:\n";
  for (const Option& o : command.options)
    text += HelpLine("  " + std::string(o.name) + (TakesValue(o) ? " " + std::string(o.value) : ""),
                     o.help);
  return text + HelpLine("  --help", "this help");
}

std::string ToolHelp() {
  std::string text = "usage: curvature-inpaint COMMAND [options]\n"
                     "       curvature-inpaint COMMAND --help | help COMMAND | --version\n\n"
                     "Fills the holes of 3D scans with the shape that is missing.\n\ncommands:\n";
  for (const Command& c : Commands()) {
    const std::string head = "  " + std::string(c.name);
    text += head + std::string(12 - head.size(), ' ') + c.summary + "\n";
  }
  text += "\nexit status: 0 done, 1 failed (the message says why; no input is changed), 2 a\n"
          "mistake in the command line.\n"
          "Options take their value as `--opt value` or `--opt=value`.\n";
  return text;
}

Args::Args(std::vector<std::string> args) {
  for (std::string& a : args) {
    const size_t eq = a.find('=');
    if (a.compare(0, 2, "--") == 0 && eq != std::string::npos) {
      args_.push_back(a.substr(0, eq));
      args_.push_back(a.substr(eq + 1));
    } else {
      args_.push_back(std::move(a));
    }
  }
}

void Args::Check(const Command& command) const {
  for (size_t i = 0; i < args_.size(); ++i) {
    if (!LooksLikeOption(args_[i])) continue;
    const Option* o = FindOption(command, args_[i]);
    if (!o) throw UsageError("unknown option " + args_[i]);
    if (TakesValue(*o) && ++i >= args_.size())
      throw UsageError(args_[i - 1] + " needs a value (" + o->value + ")");
  }
}

bool Args::Has(const std::string& name) const {
  return std::find(args_.begin(), args_.end(), name) != args_.end();
}

bool Args::Flag(const std::string& name) {
  const auto it = std::find(args_.begin(), args_.end(), name);
  if (it == args_.end()) return false;
  args_.erase(it);
  return true;
}

std::string Args::Text(const std::string& name, const std::string& fallback) {
  const auto it = std::find(args_.begin(), args_.end(), name);
  if (it == args_.end()) return fallback;
  if (it + 1 == args_.end()) throw UsageError(name + " needs a value");
  const std::string v = *(it + 1);
  args_.erase(it, it + 2);
  return v;
}

std::vector<std::string> Args::Texts(const std::string& name) {
  std::vector<std::string> values;
  while (Has(name)) values.push_back(Text(name, ""));
  return values;
}

long Args::Integer(const std::string& name, long fallback, long lo) {
  const std::string v = Text(name, "");
  if (v.empty()) return fallback;
  char* end = nullptr;
  const long x = std::strtol(v.c_str(), &end, 10);
  if (*end != '\0' || x < lo) throw UsageError(name + " needs an integer >= " + std::to_string(lo));
  return x;
}

double Args::Number(const std::string& name, double fallback, bool zero_allowed) {
  if (!Has(name)) return fallback;
  const std::string v = Text(name, "");
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  if (v.empty() || *end != '\0' || !std::isfinite(x) || x < 0 || (x == 0 && !zero_allowed))
    throw UsageError(name + (zero_allowed ? " needs a number >= 0" : " needs a positive number"));
  return x;
}

std::vector<std::string> Args::Files(size_t count, const char* synopsis) {
  for (const auto& a : args_)
    if (LooksLikeOption(a)) throw UsageError("unknown option " + a);
  if (args_.size() != count)
    throw UsageError("expected " + std::string(synopsis) + ", got " + std::to_string(args_.size()) +
                     (args_.size() == 1 ? " file" : " files"));
  return args_;
}

} // namespace cli
} // namespace curvature_inpaint
