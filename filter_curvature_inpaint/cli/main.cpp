// curvature-inpaint: the command-line front end of the pipeline.
#include "curvature_images.h"
#include "batch.h"
#include "inpaint/server_pool.h"
#include "hole_fill.h"
#include "symmetry_prior.h"
#include "inpaint/inpainter.h"
#include "mesh_io.h"
#include "pipeline.h"

#include <vcg_ext/punch_hole.h>

#include <QDir>
#include <QImage>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <unistd.h>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace {

const char* const kUsage =
    "usage:\n"
    "  curvature-inpaint fill IN OUT [--backend NAME] [--url URL] [--model M] [--prompt TEXT]\n"
    "                   [--variations N] [--pick auto|coarse|K|KIND|A,B,...]\n"
    "                   [--mode direct|paper] [--similitude S] [--transformation-constant T]\n"
    "                   [--max-hole-edges N] [--size PX]\n"
    "                   [--images DIR] [--report FILE.json] [--from-images DIR] [--context C]\n"
    "                   [--fake-holes K] [--fake-hole-size PX] [--detail A] [--density D]\n"
    "                   [--no-symmetry] [--exemplar] [--no-creases] [--no-tri-laplacian]\n"
    "                   [--curvature-passes N] [--oracle GT]\n"
    "      The main job: fill every hole of IN with detail (coarse fill, curvature images,\n"
    "      inpainting, deformation to the chosen variation) and write OUT. --pick auto (default)\n"
    "      takes the validated (or best-scored) variation; --pick coarse keeps every hole's\n"
    "      coarse fill (at the fill's density); --pick KIND the first variation of\n"
    "      that kind where a hole has one (exemplar, symmetry, symmetry surface, creases,\n"
    "      face, tri-laplacian); --pick A,B,... one entry per hole as `preview` numbers them,\n"
    "      each auto, coarse (keep the coarse fill) or a variation number.\n"
    "      Backends and their options as for inpaint.\n"
    "      --from-images DIR deforms to hole_<k>_inpainted.png, inpainted by hand in DIR\n"
    "      after `images IN DIR --size PX` (same --max-hole-edges, --context, --size).\n"
    "      --fake-holes K (default 4): fill each hole the way (coarse fill, or detail 0, 0.5,\n"
    "      1, 2) that came closest on K holes of its size cut into known surface near it;\n"
    "      --detail A instead uses amplitude A on every hole (0: the smooth continuation).\n"
    "      --fake-hole-size PX: the fake holes' images (default 128).\n"
    "      Where the object is mirror-symmetric and a hole's mirror image is known surface,\n"
    "      its mirrored curvature and surface are two more variations (validated like the\n"
    "      rest, never picked unvalidated); --no-symmetry leaves them out. --exemplar: the\n"
    "      embedded backend also offers N exemplar variations (patches of the known\n"
    "      curvature copied in, ridges first; validated like the rest).\n"
    "      A hole that creases run into also gets its context's faces extended across it\n"
    "      until they meet (sharp edges and corners; validated), a hole inside one smooth\n"
    "      face with no crease near, that face extended (\"face\"); --no-creases leaves\n"
    "      both out.\n"
    "      Every hole also gets its fill faired to continue the curvature around it, not only\n"
    "      its tangents (a tri-Laplacian; validated); --no-tri-laplacian leaves it out.\n"
    "      --density D: the fill's vertex density (Liepa's alpha; default 2, coarse 1.41).\n"
    "      --curvature-passes N (direct mode, default 0): after the first deformation, up to\n"
    "      N more rounds, each asking for half of what the result's curvature, measured as\n"
    "      the image was painted, still lacks of the image's (a round that comes no closer\n"
    "      to the image, or folds the fill, is not taken).\n"
    "      --oracle GT (benchmarks): deform to the curvature image painted from GT, the mesh\n"
    "      before its holes were cut: the best any inpainter can do with this deformation\n"
    "      (the fill at density 2.5 unless --density is given: a finer one, to carry\n"
    "      the truth's detail).\n"
    "  curvature-inpaint preview IN DIR [fill options but --images, --report, --oracle]\n"
    "      The variations fill would choose from, without changing any mesh: per hole its\n"
    "      validation and its variations by number and kind with their scores and the pick\n"
    "      fill would make on stdout, and in DIR hole_<k>_coarse.png, hole_<k>_mask.png,\n"
    "      hole_<k>_variation_<j>.png and montage.png (the pick framed). Then `fill IN OUT\n"
    "      --pick A,B,...` with the same options applies a choice per hole.\n"
    "  curvature-inpaint coarse IN OUT [--max-hole-edges N] [--max-hole-diameter F]\n"
    "                   [--keep-longest-open] [--selected-only] [--liepa-max-edges M] [--threads "
    "T]\n"
    "                   [--no-refine] [--no-fair]\n"
    "      Fill every hole of IN (stages 0-2: Liepa triangulation, refinement, fairing) and\n"
    "      write OUT. Formats: .ply .off .obj .stl. N = 0 (default) fills holes of any size;\n"
    "      F: holes whose border spans more than F x the bounding-box diagonal stay open.\n"
    "      --keep-longest-open leaves the longest loop open: the outer border of an open\n"
    "      scan. --selected-only fills holes beside selected faces (PLY). Holes up to M\n"
    "      edges (default 200) get the optimal triangulation, larger ones vcglib's ears.\n"
    "      --threads T: holes filled at once (default: one per core). The hole options hold\n"
    "      for images and fill too.\n"
    "  curvature-inpaint images IN DIR [--size N] [--max-hole-edges N] [--context C]\n"
    "                                  [--filter-scale S]\n"
    "      Fill the holes of IN, then write for every hole its curvature image\n"
    "      (hole_<k>_curvature.png), the same with the hole transparent (hole_<k>_rgba.png),\n"
    "      the hole's mask (hole_<k>_mask.png, white = hole), hole_<k>.json (patch, UV,\n"
    "      normalization), and montage.png with all of them. N: pixels (default 1024); C:\n"
    "      context ring width in hole radii (default 1); S: APSS filter scale (default 4).\n"
    "  curvature-inpaint inpaint IMAGE MASK OUTDIR [--backend NAME] [--url URL] [--model M]\n"
    "                  [--prompt TEXT] [--negative-prompt TEXT] [-n N] [--seed S] [--size PX]\n"
    "                  [--timeout SECONDS] [--retries N] [--max-response-mb MB] [--workflow FILE]\n"
    "                  [--detail A]\n"
    "      Complete the hole (white in MASK) of a curvature image into N variations,\n"
    "      OUTDIR/variation_<i>.png. Backends: embedded (default, offline), openai\n"
    "      (OPENAI_API_KEY, OPENAI_BASE_URL; --model dall-e-2 or gpt-image-1), sd-webui\n"
    "      (--url, SD_WEBUI_AUTH=user:pass), stability (STABILITY_API_KEY), comfyui (--url,\n"
    "      --workflow to use an edited copy of the shipped workflow). Several servers of\n"
    "      one service: --url repeated, or --url-file F (one URL a line); fill spreads the\n"
    "      holes over them, --per-server M (default 1) at once on each, a failing server\n"
    "      set aside and its request sent to another.\n"
    "  curvature-inpaint batch MANIFEST OUTDIR [--jobs J] [--shard K/N] [fill options]\n"
    "      The main job over a collection: MANIFEST is a folder (its PLY/OBJ/OFF/STL files)\n"
    "      or a text file of paths, each optionally followed by its own fill options. Each\n"
    "      result goes to OUTDIR under the input's name, one JSON line per scan to\n"
    "      OUTDIR/results.jsonl (results.K-of-N.jsonl for a shard). Resumable: a scan done\n"
    "      before with the same bytes and options is skipped; a killed batch loses no\n"
    "      finished scan. A failed scan is recorded and the rest go on (exit status 1).\n"
    "      --jobs J: scans at once. --shard K/N, or a Slurm job array's SLURM_ARRAY_TASK_ID\n"
    "      and SLURM_ARRAY_TASK_COUNT: every N-th scan from the K-th.\n"
    "  curvature-inpaint batch --summary OUTDIR\n"
    "      The results of every shard as a table, and OUTDIR/summary.csv.\n"
    "  curvature-inpaint info IN [--symmetry]\n"
    "      Print the vertex, face and hole counts of IN (boundary edges of each hole);\n"
    "      --symmetry also the mirror planes the symmetry prior finds in it.\n"
    "  curvature-inpaint punch IN OUT --seed-vertex V --radius-frac R\n"
    "      Remove every face with a vertex within R x (bounding-box diagonal) of vertex V:\n"
    "      the hole cases of the benchmark.\n";

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Args {
public:
  Args(int argc, char** argv) : args_(argv + 1, argv + argc) {}
  explicit Args(std::vector<std::string> args) : args_(std::move(args)) {}
  /// What is left, in order.
  const std::vector<std::string>& Rest() const { return args_; }
  std::string Command() {
    if (args_.empty()) throw UsageError("no command given");
    std::string c = args_.front();
    args_.erase(args_.begin());
    return c;
  }
  bool Has(const std::string& name) const {
    return std::find(args_.begin(), args_.end(), name) != args_.end();
  }
  bool Flag(const std::string& name) {
    for (size_t i = 0; i < args_.size(); ++i)
      if (args_[i] == name) {
        args_.erase(args_.begin() + i);
        return true;
      }
    return false;
  }
  /// Every value of an option given several times, in order.
  std::vector<std::string> Options(const std::string& name) {
    std::vector<std::string> values;
    for (std::string v = Option(name, ""); !v.empty(); v = Option(name, "")) values.push_back(v);
    return values;
  }
  std::string Option(const std::string& name, const std::string& fallback) {
    for (size_t i = 0; i < args_.size(); ++i)
      if (args_[i] == name) {
        if (i + 1 >= args_.size()) throw UsageError(name + " needs a value");
        std::string v = args_[i + 1];
        args_.erase(args_.begin() + i, args_.begin() + i + 2);
        return v;
      }
    return fallback;
  }
  long Integer(const std::string& name, long fallback, long lo) {
    const std::string v = Option(name, "");
    if (v.empty()) return fallback;
    char* end = nullptr;
    const long x = std::strtol(v.c_str(), &end, 10);
    if (*end != '\0' || x < lo)
      throw UsageError(name + " needs an integer >= " + std::to_string(lo));
    return x;
  }
  double Real(const std::string& name);
  std::vector<std::string> Positional(size_t count) {
    for (const auto& a : args_)
      if (a.size() > 1 && a[0] == '-') throw UsageError("unknown option " + a);
    if (args_.size() != count)
      throw UsageError("expected " + std::to_string(count) + " file arguments");
    return args_;
  }

private:
  std::vector<std::string> args_;
};

/// A finite number above zero, or from zero on when `zero_allowed`.
double ParseNumber(const std::string& name, const std::string& v, bool zero_allowed) {
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  if (v.empty() || *end != '\0' || !std::isfinite(x) || x < 0 || (x == 0 && !zero_allowed))
    throw UsageError(name + (zero_allowed ? " needs a number >= 0" : " needs a positive number"));
  return x;
}

double ParsePositive(const std::string& name, const std::string& v) {
  return ParseNumber(name, v, false);
}

double ParseNonNegative(const std::string& name, const std::string& v) {
  return ParseNumber(name, v, true);
}

/// Which holes to fill and on how many threads: the same options for coarse, images and fill.
void ReadHoleSelection(Args& args, vcg_ext::CoarseFillParams& p) {
  p.threads = int(args.Integer("--threads", 0, 0));
  p.max_hole_edges = int(args.Integer("--max-hole-edges", 0, 0));
  const std::string diameter = args.Option("--max-hole-diameter", "");
  if (!diameter.empty()) p.max_hole_diameter = ParsePositive("--max-hole-diameter", diameter);
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

int Coarse(Args& args) {
  vcg_ext::CoarseFillParams params;
  ReadHoleSelection(args, params);
  params.dp_max_edges = int(args.Integer("--liepa-max-edges", params.dp_max_edges, 3));
  params.refine = !args.Flag("--no-refine");
  params.fair = !args.Flag("--no-fair");
  const auto files = args.Positional(2);
  CMeshO m;
  const int mask = curvature_inpaint::LoadMesh(files[0], m);
  const auto result = curvature_inpaint::CoarseFill(m, params, ProgressToStderr);
  for (const auto& line : curvature_inpaint::DescribeCoarseFill(result))
    std::fprintf(stderr, "%s\n", line.c_str());
  curvature_inpaint::SaveMesh(files[1], m, mask);
  return 0;
}

int Images(Args& args) {
  curvature_inpaint::CurvatureImagesParams params;
  params.image_size = int(args.Integer("--size", params.image_size, 16));
  ReadHoleSelection(args, params.coarse);
  const std::string context = args.Option("--context", "");
  if (!context.empty()) params.segmentation.context = ParsePositive("--context", context);
  const std::string scale = args.Option("--filter-scale", "");
  if (!scale.empty()) params.apss.filter_scale = float(ParsePositive("--filter-scale", scale));
  const auto files = args.Positional(2);
  CMeshO m;
  curvature_inpaint::LoadMesh(files[0], m);
  const auto result = curvature_inpaint::ComputeCurvatureImages(m, params, ProgressToStderr);
  for (const auto& line : curvature_inpaint::DescribeCurvatureImages(result))
    std::fprintf(stderr, "%s\n", line.c_str());
  curvature_inpaint::WriteHoleImages(files[1], result);
  curvature_inpaint::WriteMontage(files[1] + "/montage.png", result);
  return 0;
}

/// The backend's options, shared by `inpaint` and `fill` (which differ only in how they name
/// the number of variations).
void ReadBackendOptions(Args& args, curvature_inpaint::InpaintParams& p) {
  p.backend = args.Option("--backend", p.backend);
  std::vector<std::string> urls = args.Options("--url");
  const std::string url_file = args.Option("--url-file", "");
  if (!url_file.empty()) {
    std::FILE* f = std::fopen(url_file.c_str(), "r");
    if (!f) throw UsageError("cannot read --url-file " + url_file);
    char line[4096];
    while (std::fgets(line, sizeof line, f)) {
      std::string u(line);
      u = u.substr(0, u.find('#'));
      u.erase(0, u.find_first_not_of(" \t\r\n"));
      u.erase(u.find_last_not_of(" \t\r\n") + 1);
      if (!u.empty()) urls.push_back(u);
    }
    std::fclose(f);
    if (urls.empty()) throw UsageError("--url-file " + url_file + " lists no server");
  }
  if (urls.size() == 1) p.url = urls[0];
  if (urls.size() > 1) p.urls = urls;
  p.per_server = int(args.Integer("--per-server", p.per_server, 1));
  p.model = args.Option("--model", "");
  p.prompt = args.Option("--prompt", "");
  p.negative_prompt = args.Option("--negative-prompt", "");
  p.seed = uint32_t(args.Integer("--seed", p.seed, 0));
  p.workflow_file = args.Option("--workflow", "");
  const std::string timeout = args.Option("--timeout", "");
  if (!timeout.empty()) p.http.total_timeout_s = ParsePositive("--timeout", timeout);
  p.http.max_response_bytes = size_t(args.Integer("--max-response-mb", 64, 1)) << 20;
  p.http.max_retries = int(args.Integer("--retries", p.http.max_retries, 0));
  const std::string detail = args.Option("--detail", "");
  if (!detail.empty()) p.detail = ParseNonNegative("--detail", detail);
}

int InpaintCommand(Args& args) {
  curvature_inpaint::InpaintParams p;
  ReadBackendOptions(args, p);
  p.variations = int(args.Integer("-n", p.variations, 1));
  p.size = int(args.Integer("--size", 0, 0));
  const auto files = args.Positional(3);
  QImage image(QString::fromStdString(files[0])), mask(QString::fromStdString(files[1]));
  if (image.isNull()) throw std::runtime_error(files[0] + ": not a readable image");
  if (mask.isNull()) throw std::runtime_error(files[1] + ": not a readable image");
  std::fprintf(stderr, "inpainting with %s, %d variations\n", p.backend.c_str(), p.variations);
  std::unique_ptr<curvature_inpaint::ServerPool> pool;
  if (!p.urls.empty()) pool = std::make_unique<curvature_inpaint::ServerPool>(p.urls, p.per_server);
  p.pool = pool.get();
  const auto variations = curvature_inpaint::Inpaint(image, mask, p);
  if (!QDir().mkpath(QString::fromStdString(files[2])))
    throw std::runtime_error("cannot create " + files[2]);
  for (size_t i = 0; i < variations.size(); ++i) {
    const std::string path = files[2] + "/variation_" + std::to_string(i + 1) + ".png";
    if (!variations[i].save(QString::fromStdString(path), "PNG"))
      throw std::runtime_error("cannot write " + path);
    std::fprintf(stderr, "wrote %s\n", path.c_str());
  }
  return 0;
}

/// --pick: auto, coarse, a variation number or a kind for every hole, or a comma-separated list
/// with one entry per hole, each auto, coarse or a number (what `preview` showed).
void ReadPick(const std::string& pick, curvature_inpaint::HoleFillParams& p) {
  const std::vector<std::string> kinds{"continuation",     "exemplar", "symmetry",
                                       "symmetry surface", "creases",  "face",
                                       "tri-laplacian"};
  if (std::find(kinds.begin(), kinds.end(), pick) != kinds.end()) {
    p.pick_kind = pick;
    return;
  }
  auto number = [](const std::string& k) {
    char* end = nullptr;
    const long n = std::strtol(k.c_str(), &end, 10);
    return k.empty() || *end != '\0' || n < 1 || n > 1000 ? 0 : int(n);
  };
  if (pick.find(',') == std::string::npos) {
    if (pick == "auto") return;
    p.pick = pick == "coarse" ? -1 : number(pick);
    if (p.pick == 0)
      throw UsageError("--pick needs auto, coarse, a variation number >= 1 or a kind "
                       "(continuation, exemplar, symmetry, symmetry surface, creases, face, "
                       "tri-laplacian), or one entry per hole (auto, coarse or a number) "
                       "separated by commas");
    return;
  }
  size_t from = 0;
  for (;;) {
    const size_t comma = pick.find(',', from);
    const std::string entry = pick.substr(from, comma - from);
    const int k = entry == "auto" ? 0 : entry == "coarse" ? -1 : number(entry);
    if (k == 0 && entry != "auto")
      throw UsageError("--pick: \"" + entry + "\" is not auto, coarse or a variation number >= 1");
    p.hole_picks.push_back(k);
    if (comma == std::string::npos) break;
    from = comma + 1;
  }
}

/// The options of `fill` that set its parameters (every one but the files, --report and
/// --oracle), taken out of `args`.
curvature_inpaint::HoleFillParams ReadFillOptions(Args& args) {
  curvature_inpaint::HoleFillParams p;
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
  p.creases = !args.Flag("--no-creases");
  p.tri_laplacian = !args.Flag("--no-tri-laplacian");
  ReadPick(args.Option("--pick", "auto"), p);
  p.mode = args.Option("--mode", p.mode);
  if (p.mode != "direct" && p.mode != "paper") throw UsageError("--mode is direct or paper");
  const std::string sim = args.Option("--similitude", "");
  if (!sim.empty()) p.paper.similitude = ParsePositive("--similitude", sim);
  const std::string tc = args.Option("--transformation-constant", "");
  if (!tc.empty()) p.paper.transformation_constant = ParsePositive("--transformation-constant", tc);
  ReadHoleSelection(args, p.images.coarse);
  const std::string density = args.Option("--density", "");
  if (!density.empty()) p.images.coarse.density_alpha = ParsePositive("--density", density);
  p.images.image_size = int(args.Integer("--size", 512, 16));
  p.images_dir = args.Option("--images", "");
  p.inpainted_dir = args.Option("--from-images", "");
  const std::string context = args.Option("--context", "");
  if (!context.empty()) p.images.segmentation.context = ParsePositive("--context", context);
  return p;
}

int Fill(Args& args) {
  const bool density_given = args.Has("--density");
  curvature_inpaint::HoleFillParams p = ReadFillOptions(args);
  const std::string report = args.Option("--report", "");
  const std::string oracle_path = args.Option("--oracle", "");
  if (!oracle_path.empty() && !density_given)
    p.images.coarse.density_alpha = curvature_inpaint::kOracleDensity;
  const auto files = args.Positional(2);
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
  for (const auto& line : curvature_inpaint::DescribeHoleFill(result))
    std::fprintf(stderr, "%s\n", line.c_str());
  curvature_inpaint::SaveMesh(files[1], m, mask);
  if (!report.empty()) {
    std::FILE* f = std::fopen(report.c_str(), "w");
    const std::string json = curvature_inpaint::HoleFillReportJson(result, p);
    if (!f || std::fwrite(json.data(), 1, json.size(), f) != json.size() || std::fclose(f) != 0)
      throw std::runtime_error("cannot write " + report);
  }
  return 0;
}

/// The dialog's preview on the command line: every hole's variations and the pick fill would
/// make, written as pictures; the mesh file is only read. `fill --pick A,B,...` then applies a
/// choice per hole: the same options and seed give the same variations.
int Preview(Args& args) {
  if (args.Has("--images") || args.Has("--report") || args.Has("--oracle"))
    throw UsageError("preview writes its pictures into DIR; --images, --report and --oracle are "
                     "fill options");
  const curvature_inpaint::HoleFillParams p = ReadFillOptions(args);
  const auto files = args.Positional(2);
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
  const std::string shard = args.Option("--shard", "");
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

int Batch(Args& args) {
  const std::string summary = args.Option("--summary", "");
  if (!summary.empty()) {
    args.Positional(0);
    return curvature_inpaint::SummarizeBatch(summary) ? 1 : 0;
  }
  curvature_inpaint::BatchParams p;
  p.jobs = int(args.Integer("--jobs", 1, 1));
  ReadShard(args, p);
  const std::vector<std::string> rest = args.Rest();
  if (rest.size() < 2 || rest[0][0] == '-' || rest[1][0] == '-')
    throw UsageError("batch needs MANIFEST OUTDIR before the fill options");
  p.outdir = rest[1];
  p.options.assign(rest.begin() + 2, rest.end());
  for (const char* own : {"--report", "--oracle", "--images", "--from-images"})
    if (std::find(p.options.begin(), p.options.end(), own) != p.options.end())
      throw UsageError(std::string(own) + " is not a batch option (each scan's result line has "
                                          "its report)");
  auto parse = [](const std::vector<std::string>& options) {
    Args a(options);
    curvature_inpaint::HoleFillParams params = ReadFillOptions(a);
    a.Positional(0);
    return params;
  };
  parse(p.options); // a bad option is the whole batch's error, before any scan
  p.progress_bar = isatty(fileno(stderr));
  const auto scans = curvature_inpaint::ReadManifest(rest[0]);
  const auto done = curvature_inpaint::RunBatch(scans, p, parse);
  std::fprintf(stderr, "batch: %d scans: %d filled, %d done before, %d failed\n", done.scans,
               done.done, done.skipped, done.failed);
  return done.failed ? 1 : 0;
}

int Info(Args& args) {
  const bool symmetry = args.Flag("--symmetry");
  const auto files = args.Positional(1);
  CMeshO m;
  curvature_inpaint::LoadMesh(files[0], m);
  const auto c = curvature_inpaint::CountHoles(m);
  std::printf("vertices %d\nfaces %d\nnon_manifold_edges %zu\ninconsistent_edges %zu\nholes %zu\n",
              c.vertices, c.faces, c.non_manifold_edges, c.inconsistent_edges, c.loop_edges.size());
  std::printf("hole_edges");
  for (int e : c.loop_edges) std::printf(" %d", e);
  std::printf("\n");
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

int Punch(Args& args) {
  const long seed = args.Integer("--seed-vertex", -1, 0);
  if (seed < 0) throw UsageError("--seed-vertex is required");
  const double frac = args.Real("--radius-frac");
  const auto files = args.Positional(2);
  CMeshO m;
  const int mask = curvature_inpaint::LoadMesh(files[0], m);
  if (seed >= long(m.vert.size()))
    throw UsageError("--seed-vertex " + std::to_string(seed) + " is not a vertex of " + files[0]);
  const auto center = m.vert[seed].cP();
  const int removed = vcg_ext::PunchHole(m, center, Scalarm(frac * m.bbox.Diag()));
  std::fprintf(stderr, "removed %d faces\n", removed);
  curvature_inpaint::SaveMesh(files[1], m, mask);
  return 0;
}

double Args::Real(const std::string& name) {
  return ParsePositive(name, Option(name, ""));
}

} // namespace

int main(int argc, char** argv) {
  Args args(argc, argv);
  try {
    const std::string command = args.Command();
    if (command == "fill") return Fill(args);
    if (command == "coarse") return Coarse(args);
    if (command == "images") return Images(args);
    if (command == "info") return Info(args);
    if (command == "batch") return Batch(args);
    if (command == "inpaint") return InpaintCommand(args);
    if (command == "punch") return Punch(args);
    if (command == "preview") return Preview(args);
    if (command == "-h" || command == "--help" || command == "help") {
      std::printf("%s", kUsage);
      return 0;
    }
    throw UsageError("unknown command \"" + command + "\"");
  } catch (const UsageError& e) {
    std::fprintf(stderr, "curvature-inpaint: %s\n%s", e.what(), kUsage);
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "curvature-inpaint: %s\n", e.what());
    return 1;
  }
}
