// curvature-inpaint: the command-line front end of the pipeline. The commands, their options
// and their help are declared in command_line.cpp; this file runs them.
#include "candidates/fill_candidate.h"
#include "candidates/symmetry_prior.h"
#include "command_line.h"
#include "inpaint/inpainter.h"
#include "inpaint/server_pool.h"
#include "io/mesh_io.h"
#include "io/output_files.h"
#include "manual_page.h"
#include "pipeline/batch.h"
#include "pipeline/curvature_images.h"
#include "pipeline/fill_settings.h"
#include "pipeline/hole_fill.h"
#include "pipeline/pipeline.h"
#include "report/hole_report.h"

#include <vcg_ext/hole_loops.h>
#include <vcg_ext/punch_hole.h>
#include <wrap/io_trimesh/io_mask.h>

#include <QDir>
#include <QImage>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <strings.h>
#include <memory>
#include <string>
#include <unistd.h>
#include <vector>

#ifndef CURVATURE_INPAINT_VERSION
#define CURVATURE_INPAINT_VERSION "unknown"
#endif

namespace {

using curvature_inpaint::cli::Args;
using curvature_inpaint::cli::Command;
using curvature_inpaint::cli::UsageError;

/// Which holes to fill and on how many threads: the same options for coarse, images and fill.
void ReadHoleSelection(Args& args, vcg_ext::CoarseFillParams& p) {
  p.threads = int(args.Integer("--threads", 0, 0));
  p.max_hole_edges = int(args.Integer("--max-hole-edges", 0, 0));
  p.max_hole_diameter = args.Number("--max-hole-diameter", p.max_hole_diameter);
  p.keep_longest_open = args.Flag("--keep-longest-open");
  p.selected_only = args.Flag("--selected-only");
}

/// The pipeline's progress, one line per new message: while it waits on a slow task it asks
/// again every 50 ms with the same one.
bool ProgressToStderr(const int, const char* message) {
  static std::string last;
  if (message != last) std::fprintf(stderr, "%s\n", message);
  last = message;
  return true;
}

/// Where and how a command writes the mesh it makes.
struct MeshOutput {
  bool in_place = false; ///< the user allows the output to be the input
  bool mark_new = false; ///< the new faces are written selected
  std::string path;
};

/// Takes --in-place and --mark-new out of `args`.
MeshOutput ReadOutputFlags(Args& args) {
  MeshOutput out;
  out.in_place = args.Flag("--in-place");
  out.mark_new = args.Flag("--mark-new");
  return out;
}

/// Checks OUT before any work is done: its format, its folder, and that it is not the input
/// unless --in-place. Throws UsageError or OutputError.
void CheckOutput(MeshOutput& out, const std::string& input, const std::string& path) {
  out.path = path;
  curvature_inpaint::CheckMeshFormat(path);
  if (out.mark_new && (path.size() < 4 || strcasecmp(path.c_str() + path.size() - 4, ".ply") != 0))
    throw UsageError("--mark-new needs a .ply output (the other formats keep no selection)");
  curvature_inpaint::CheckMeshOutput(input, path, out.in_place);
}

/// Writes `m` whole or not at all (see SaveMesh), through a link to the file it names.
void SaveOutput(const MeshOutput& out, CMeshO& m, int mask) {
  if (out.mark_new) mask |= vcg::tri::io::Mask::IOM_FACEFLAGS;
  curvature_inpaint::SaveMesh(curvature_inpaint::WriteTarget(out.path), m, mask);
}

/// The last line of fill and coarse: what was written, and what is left open.
void SayWritten(const MeshOutput& out, const vcg_ext::CoarseFillResult& coarse,
                const std::string& report) {
  const int filled = coarse.FilledCount();
  const int open = int(coarse.holes.size()) - filled + coarse.skipped_by_size +
                   coarse.skipped_by_selection + coarse.kept_as_border;
  std::string line = "wrote " + out.path + ": " + std::to_string(filled) +
                     (filled == 1 ? " hole" : " holes") + " filled, " + std::to_string(open) +
                     " left open";
  if (out.mark_new) line += ", the new faces selected";
  if (!report.empty()) line += " (report: " + report + ")";
  std::fprintf(stderr, "%s\n", line.c_str());
}

int Coarse(Args& args, const Command& command) {
  vcg_ext::CoarseFillParams params;
  ReadHoleSelection(args, params);
  params.dp_max_edges = int(args.Integer("--liepa-max-edges", params.dp_max_edges, 3));
  params.refine = !args.Flag("--no-refine");
  params.fair = !args.Flag("--no-fair");
  MeshOutput out = ReadOutputFlags(args);
  const auto files = args.Files(2, command.synopsis);
  CheckOutput(out, files[0], files[1]);
  CMeshO m;
  const int mask = curvature_inpaint::LoadMesh(files[0], m);
  const auto result = curvature_inpaint::CoarseFill(m, params, ProgressToStderr);
  for (const auto& line : curvature_inpaint::DescribeCoarseFill(result))
    std::fprintf(stderr, "%s\n", line.c_str());
  SaveOutput(out, m, mask);
  SayWritten(out, result, "");
  return 0;
}

int Images(Args& args, const Command& command) {
  curvature_inpaint::CurvatureImagesParams params;
  params.image_size = int(args.Integer("--size", params.image_size, 16));
  ReadHoleSelection(args, params.coarse);
  params.segmentation.context = args.Number("--context", params.segmentation.context);
  params.apss.filter_scale = float(args.Number("--filter-scale", params.apss.filter_scale));
  const auto files = args.Files(2, command.synopsis);
  curvature_inpaint::CheckFolderWritable(files[1]);
  CMeshO m;
  curvature_inpaint::LoadMesh(files[0], m);
  const auto result = curvature_inpaint::ComputeCurvatureImages(m, params, ProgressToStderr);
  for (const auto& line : curvature_inpaint::DescribeCurvatureImages(result))
    std::fprintf(stderr, "%s\n", line.c_str());
  curvature_inpaint::WriteHoleImages(files[1], result);
  curvature_inpaint::WriteMontage(files[1] + "/montage.png", result);
  std::fprintf(stderr, "wrote the images of %zu holes into %s\n", result.holes.size(),
               files[1].c_str());
  return 0;
}

/// The servers of --url (repeated) and --url-file.
std::vector<std::string> ReadUrls(Args& args) {
  std::vector<std::string> urls = args.Texts("--url");
  const std::string url_file = args.Text("--url-file", "");
  if (url_file.empty()) return urls;
  std::FILE* f = std::fopen(url_file.c_str(), "r");
  if (!f) throw UsageError("cannot read --url-file " + url_file);
  char line[4096];
  const size_t given = urls.size();
  while (std::fgets(line, sizeof line, f)) {
    std::string u(line);
    u = u.substr(0, u.find('#'));
    u.erase(0, u.find_first_not_of(" \t\r\n"));
    u.erase(u.find_last_not_of(" \t\r\n") + 1);
    if (!u.empty()) urls.push_back(u);
  }
  std::fclose(f);
  if (urls.size() == given) throw UsageError("--url-file " + url_file + " lists no server");
  return urls;
}

/// The backend's options, shared by `inpaint` and `fill` (which differ only in how they name
/// the number of variations).
void ReadBackendOptions(Args& args, curvature_inpaint::InpaintParams& p) {
  p.backend = curvature_inpaint::ParseBackend(
      args.Text("--backend", curvature_inpaint::BackendName(p.backend)));
  const std::vector<std::string> urls = ReadUrls(args);
  if (urls.size() == 1) p.url = urls[0];
  if (urls.size() > 1) p.urls = urls;
  p.per_server = int(args.Integer("--per-server", p.per_server, 1));
  p.model = args.Text("--model", "");
  p.prompt = args.Text("--prompt", "");
  p.negative_prompt = args.Text("--negative-prompt", "");
  p.seed = uint32_t(args.Integer("--seed", p.seed, 0));
  p.workflow_file = args.Text("--workflow", "");
  p.http.total_timeout_s = args.Number("--timeout", p.http.total_timeout_s);
  p.http.max_response_bytes = size_t(args.Integer("--max-response-mb", 64, 1)) << 20;
  p.http.max_retries = int(args.Integer("--retries", p.http.max_retries, 0));
  p.detail = args.Number("--detail", p.detail, true);
}

int InpaintCommand(Args& args, const Command& command) {
  curvature_inpaint::InpaintParams p;
  ReadBackendOptions(args, p);
  p.variations = int(args.Integer("-n", p.variations, 1));
  p.size = int(args.Integer("--size", 0, 0));
  const auto files = args.Files(3, command.synopsis);
  QImage image(QString::fromStdString(files[0])), mask(QString::fromStdString(files[1]));
  if (image.isNull()) throw std::runtime_error(files[0] + ": not a readable image");
  if (mask.isNull()) throw std::runtime_error(files[1] + ": not a readable image");
  curvature_inpaint::CheckFolderWritable(files[2]);
  std::fprintf(stderr, "inpainting with %s, %d variations\n",
               curvature_inpaint::BackendName(p.backend).c_str(), p.variations);
  std::unique_ptr<curvature_inpaint::ServerPool> pool;
  if (!p.urls.empty()) pool = std::make_unique<curvature_inpaint::ServerPool>(p.urls, p.per_server);
  p.pool = pool.get();
  const auto variations = curvature_inpaint::Inpaint(image, mask, p);
  if (!QDir().mkpath(QString::fromStdString(files[2])))
    throw std::runtime_error("cannot create " + files[2]);
  for (size_t i = 0; i < variations.size(); ++i) {
    const std::string path = files[2] + "/variation_" + std::to_string(i + 1) + ".png";
    curvature_inpaint::SavePngAtomically(variations[i], path);
    std::fprintf(stderr, "wrote %s\n", path.c_str());
  }
  return 0;
}

/// One entry of --pick: 0 auto, -1 coarse, k >= 1 variation k; throws UsageError otherwise.
int PickEntry(const std::string& entry) {
  if (entry == "auto") return 0;
  if (entry == "coarse") return -1;
  char* end = nullptr;
  const long n = std::strtol(entry.c_str(), &end, 10);
  if (entry.empty() || *end != '\0' || n < 1 || n > 1000) {
    std::string kinds;
    for (curvature_inpaint::FillKind kind : curvature_inpaint::VariationKinds())
      kinds += (kinds.empty() ? "" : ", ") + std::string(curvature_inpaint::FillKindName(kind));
    throw UsageError("--pick: \"" + entry +
                     "\" is not auto, coarse, a variation number (1 to 1000) or a kind (" + kinds +
                     ")");
  }
  return int(n);
}

/// --pick: auto, coarse, a variation number or a kind for every hole, or a comma-separated list
/// with one entry per hole, each auto, coarse or a number (what `preview` showed).
void ReadPick(const std::string& pick, curvature_inpaint::HoleFillParams& p) {
  if (curvature_inpaint::VariationKindNamed(pick, &p.pick_kind)) return;
  if (pick.find(',') == std::string::npos) {
    p.pick = PickEntry(pick);
    return;
  }
  size_t from = 0;
  for (;;) {
    const size_t comma = pick.find(',', from);
    p.hole_picks.push_back(PickEntry(pick.substr(from, comma - from)));
    if (comma == std::string::npos) break;
    from = comma + 1;
  }
}

/// The options of `fill` that set its parameters (every one but the files, --report, --oracle
/// and the output's flags), taken out of `args`.
curvature_inpaint::HoleFillParams ReadFillOptions(Args& args) {
  curvature_inpaint::HoleFillParams p = curvature_inpaint::DefaultSettings();
  const bool detail_given = args.Has("--detail");
  ReadBackendOptions(args, p.inpaint);
  p.inpaint.variations = int(args.Integer("--variations", p.inpaint.variations, 1));
  // A detail amplitude given is used on every hole; otherwise the fake holes choose.
  p.validation.fake_holes =
      int(args.Integer("--fake-holes", detail_given ? 0 : p.validation.fake_holes, 0));
  p.validation.image_size = int(args.Integer("--fake-hole-size", p.validation.image_size, 16));
  p.direct.apss_passes = int(args.Integer("--curvature-passes", p.direct.apss_passes, 0));
  p.symmetry.enabled = !args.Flag("--no-symmetry");
  p.exemplar = args.Flag("--exemplar");
  p.learned = args.Flag("--learned");
  p.creases = !args.Flag("--no-creases");
  p.tri_laplacian = !args.Flag("--no-tri-laplacian");
  ReadPick(args.Text("--pick", "auto"), p);
  if (!curvature_inpaint::DeformationModeFromName(
          args.Text("--mode", curvature_inpaint::DeformationModeName(p.mode)), &p.mode))
    throw UsageError("--mode is direct or paper");
  p.paper.similitude = args.Number("--similitude", p.paper.similitude);
  p.paper.transformation_constant =
      args.Number("--transformation-constant", p.paper.transformation_constant);
  ReadHoleSelection(args, p.images.coarse);
  p.images.coarse.density_alpha = args.Number("--density", p.images.coarse.density_alpha);
  p.images.image_size = int(args.Integer("--size", p.images.image_size, 16));
  p.images_dir = args.Text("--images", "");
  p.inpainted_dir = args.Text("--from-images", "");
  p.images.segmentation.context = args.Number("--context", p.images.segmentation.context);
  return p;
}

int Fill(Args& args, const Command& command) {
  const bool density_given = args.Has("--density");
  curvature_inpaint::HoleFillParams p = ReadFillOptions(args);
  const std::string report = args.Text("--report", "");
  const std::string oracle_path = args.Text("--oracle", "");
  if (!oracle_path.empty() && !density_given)
    p.images.coarse.density_alpha = curvature_inpaint::kOracleDensity;
  const bool verbose = args.Flag("--verbose");
  MeshOutput out = ReadOutputFlags(args);
  const auto files = args.Files(2, command.synopsis);
  CheckOutput(out, files[0], files[1]);
  if (!report.empty()) {
    if (curvature_inpaint::SameFile(report, files[0]))
      throw curvature_inpaint::OutputError(report +
                                           ": is the input scan; give another report file");
    curvature_inpaint::CheckWritable(curvature_inpaint::WriteTarget(report));
  }
  if (!p.images_dir.empty()) curvature_inpaint::CheckFolderWritable(p.images_dir);
  CMeshO m;
  const int mask = curvature_inpaint::LoadMesh(files[0], m);
  CMeshO ground_truth;
  std::unique_ptr<curvature_inpaint::GroundTruthOracle> oracle;
  if (!oracle_path.empty()) {
    curvature_inpaint::LoadMesh(oracle_path, ground_truth);
    oracle = std::make_unique<curvature_inpaint::GroundTruthOracle>(ground_truth, m, p.images);
    p.oracle = oracle.get();
  }
  p.measure_detail = !report.empty() || oracle;
  const auto result = curvature_inpaint::FillHoles(m, p, ProgressToStderr);
  // A line per hole in words; the numbers (the coarse fill's, the test cuts' errors, the
  // scores, the times) with --verbose, and a warning always.
  for (const auto& line : curvature_inpaint::DescribeHoleFill(result))
    if (verbose || line.compare(0, 8, "warning:") == 0) std::fprintf(stderr, "%s\n", line.c_str());
  for (const auto& line : curvature_inpaint::DescribeHolesInWords(result))
    std::fprintf(stderr, "%s\n", line.c_str());
  SaveOutput(out, m, mask);
  if (!report.empty())
    curvature_inpaint::WriteFileAtomically(report,
                                           curvature_inpaint::HoleFillReportJson(result, p));
  SayWritten(out, result.coarse, report);
  return 0;
}

/// The dialog's preview on the command line: every hole's variations and the pick fill would
/// make, written as pictures; the mesh file is only read. `fill --pick A,B,...` then applies a
/// choice per hole: the same options and seed give the same variations.
int Preview(Args& args, const Command& command) {
  const curvature_inpaint::HoleFillParams p = ReadFillOptions(args);
  const auto files = args.Files(2, command.synopsis);
  curvature_inpaint::CheckFolderWritable(files[1]);
  CMeshO m;
  curvature_inpaint::LoadMesh(files[0], m);
  const auto holes = curvature_inpaint::InpaintHoles(m, p, ProgressToStderr);
  curvature_inpaint::SaveVariationImages(holes, files[1], p.images.coarse.threads);
  for (const auto& line : curvature_inpaint::DescribeVariations(holes))
    std::printf("%s\n", line.c_str());
  return 0;
}

/// This task's shard: --shard K/N, else a Slurm job array's task (SLURM_ARRAY_TASK_ID less
/// SLURM_ARRAY_TASK_MIN, of SLURM_ARRAY_TASK_COUNT), else the whole manifest.
void ReadShard(Args& args, curvature_inpaint::BatchParams& p) {
  const std::string shard = args.Text("--shard", "");
  if (!shard.empty()) {
    int k = 0, n = 0;
    char extra = 0;
    if (std::sscanf(shard.c_str(), "%d/%d%c", &k, &n, &extra) != 2 || n < 1 || k < 1 || k > n)
      throw UsageError("--shard needs K/N with 1 <= K <= N");
    p.shard = k - 1, p.shards = n;
    return;
  }
  const char* id = std::getenv("SLURM_ARRAY_TASK_ID");
  const char* count = std::getenv("SLURM_ARRAY_TASK_COUNT");
  if (!id || !count) return;
  const char* min = std::getenv("SLURM_ARRAY_TASK_MIN");
  const int n = std::atoi(count), k = std::atoi(id) - (min ? std::atoi(min) : 0);
  if (n < 1 || k < 0 || k >= n)
    throw UsageError("SLURM_ARRAY_TASK_ID " + std::string(id) + " is not one of " +
                     std::to_string(n) + " array tasks");
  p.shard = k, p.shards = n;
}

int Batch(Args& args, const Command& command) {
  const std::string summary = args.Text("--summary", "");
  if (!summary.empty()) {
    args.Files(0, "no file");
    return curvature_inpaint::SummarizeBatch(summary) ? 1 : 0;
  }
  curvature_inpaint::BatchParams p;
  p.jobs = int(args.Integer("--jobs", 1, 1));
  ReadShard(args, p);
  const std::vector<std::string> rest = args.Rest();
  if (rest.size() < 2 || rest[0][0] == '-' || rest[1][0] == '-')
    throw UsageError("expected " + std::string(command.synopsis) + " before the fill options");
  p.outdir = rest[1];
  p.options.assign(rest.begin() + 2, rest.end());
  auto parse = [](const std::vector<std::string>& options) {
    Args a(options);
    a.Check(*curvature_inpaint::cli::FindCommand("batch"));
    curvature_inpaint::HoleFillParams params = ReadFillOptions(a);
    a.Files(0, "no file");
    return params;
  };
  parse(p.options); // a bad option is the whole batch's error, before any scan
  curvature_inpaint::CheckFolderWritable(p.outdir);
  p.progress_bar = isatty(fileno(stderr));
  const auto scans = curvature_inpaint::ReadManifest(rest[0]);
  const auto done = curvature_inpaint::RunBatch(scans, p, parse);
  std::fprintf(stderr, "batch: %d scans: %d filled, %d done before, %d failed\n", done.scans,
               done.done, done.skipped, done.failed);
  return done.failed ? 1 : 0;
}

int Info(Args& args, const Command& command) {
  const bool symmetry = args.Flag("--symmetry");
  vcg_ext::CoarseFillParams selection;
  ReadHoleSelection(args, selection);
  const auto files = args.Files(1, command.synopsis);
  CMeshO m;
  curvature_inpaint::LoadMesh(files[0], m);
  const auto c = curvature_inpaint::CountHoles(m);
  const auto holes = curvature_inpaint::ListHoles(m, selection);
  std::printf("vertices %d\nfaces %d\nnon_manifold_edges %zu\ninconsistent_edges %zu\nholes %zu\n",
              c.vertices, c.faces, c.non_manifold_edges, c.inconsistent_edges, c.loop_edges.size());
  std::printf("hole_edges");
  for (const auto& h : holes) std::printf(" %d", h.edges);
  std::printf("\n");
  const double diagonal = double(m.bbox.Diag());
  for (const auto& h : holes) {
    const std::string name = h.number > 0 ? "hole " + std::to_string(h.number) : "left open";
    std::printf("%s: %d edges, diameter %.6g (%.2g %% of the diagonal), centre %.6g %.6g %.6g\n",
                name.c_str(), h.edges, h.diameter, diagonal > 0 ? 100 * h.diameter / diagonal : 0.0,
                h.centre[0], h.centre[1], h.centre[2]);
  }
  if (symmetry) {
    vcg_ext::CoarseFillResult scan; // nothing filled: every vertex is the scan's
    scan.box = vcg_ext::ComputeUnitBox(m);
    const auto prior = curvature_inpaint::DetectSymmetry(m, scan, vcg_ext::SymmetryParams());
    std::printf(
        "%s\n",
        curvature_inpaint::DescribeSymmetry(prior->planes, prior->best, prior->partial).c_str());
  }
  return 0;
}

int Punch(Args& args, const Command& command) {
  const long seed = args.Integer("--seed-vertex", -1, 0);
  if (seed < 0) throw UsageError("--seed-vertex is required");
  if (!args.Has("--radius-frac")) throw UsageError("--radius-frac is required");
  const double frac = args.Number("--radius-frac", 0);
  MeshOutput out = ReadOutputFlags(args);
  const auto files = args.Files(2, command.synopsis);
  CheckOutput(out, files[0], files[1]);
  CMeshO m;
  const int mask = curvature_inpaint::LoadMesh(files[0], m);
  if (seed >= long(m.vert.size()))
    throw UsageError("--seed-vertex " + std::to_string(seed) + " is not a vertex of " + files[0]);
  const auto center = m.vert[size_t(seed)].cP();
  const int removed = vcg_ext::PunchHole(m, center, Scalarm(frac * m.bbox.Diag()));
  std::fprintf(stderr, "removed %d faces\n", removed);
  SaveOutput(out, m, mask);
  std::fprintf(stderr, "wrote %s\n", out.path.c_str());
  return 0;
}

/// Runs `command` on `args` (the words after its name).
int Run(const Command& command, Args& args) {
  const std::string name = command.name;
  // Options that belong to fill and not here get their own reason.
  if (name == "preview")
    for (const char* own : {"--report", "--oracle", "--in-place", "--mark-new"})
      if (args.Has(own))
        throw UsageError(std::string(own) + " is a fill option: preview writes only pictures");
  if (name == "batch")
    for (const char* own : {"--report", "--oracle", "--images", "--from-images"})
      if (args.Has(own))
        throw UsageError(std::string(own) +
                         " is not a batch option (each scan's result line has its report)");
  args.Check(command);
  if (name == "fill") return Fill(args, command);
  if (name == "preview") return Preview(args, command);
  if (name == "coarse") return Coarse(args, command);
  if (name == "info") return Info(args, command);
  if (name == "images") return Images(args, command);
  if (name == "inpaint") return InpaintCommand(args, command);
  if (name == "batch") return Batch(args, command);
  return Punch(args, command);
}

} // namespace

int main(int argc, char** argv) {
  using curvature_inpaint::cli::FindCommand;
  std::vector<std::string> words(argv + 1, argv + argc);
  const Command* command = nullptr;
  try {
    if (words.empty()) throw UsageError("no command given");
    const std::string first = words.front();
    if (first == "--version") {
      std::printf("curvature-inpaint %s (built for MeshLab %s)\n", CURVATURE_INPAINT_VERSION,
                  MESHLAB_VERSION_TEXT);
      return 0;
    }
    // For the build, which installs the manual page; the page itself names every command.
    if (first == "--man") {
      std::printf("%s", curvature_inpaint::cli::ManualPage(CURVATURE_INPAINT_VERSION).c_str());
      return 0;
    }
    if (first == "-h" || first == "--help" || (first == "help" && words.size() == 1)) {
      std::printf("%s", curvature_inpaint::cli::ToolHelp().c_str());
      return 0;
    }
    if (first == "help") {
      command = FindCommand(words[1]);
      if (!command) throw UsageError("no command \"" + words[1] + "\"");
      std::printf("%s", curvature_inpaint::cli::CommandHelp(*command).c_str());
      return 0;
    }
    command = FindCommand(first);
    if (!command) throw UsageError("unknown command \"" + first + "\"");
    words.erase(words.begin());
    if (std::find(words.begin(), words.end(), "--help") != words.end() ||
        std::find(words.begin(), words.end(), "-h") != words.end()) {
      std::printf("%s", curvature_inpaint::cli::CommandHelp(*command).c_str());
      return 0;
    }
    Args args(words);
    return Run(*command, args);
  } catch (const UsageError& e) {
    const std::string where = command ? std::string(command->name) + ": " : "";
    const std::string help = command ? std::string(command->name) + " --help" : "--help";
    std::fprintf(stderr, "curvature-inpaint: %s%s\nsee 'curvature-inpaint %s'\n", where.c_str(),
                 e.what(), help.c_str());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "curvature-inpaint: %s\n", e.what());
    return 1;
  }
}
