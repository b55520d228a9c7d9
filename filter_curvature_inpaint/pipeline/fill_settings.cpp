#include "pipeline/fill_settings.h"

#include "pipeline/hole_fill.h"

#include <vcg_ext/mesh_errors.h>

#include <QString>

#include <stdexcept>

namespace curvature_inpaint {

namespace {

// clang-format off
/// In Setting's order. A choice's range is its indices (RequireSetting reads SettingChoices).
const std::vector<SettingSpec>& AllSettings() {
  static const std::vector<SettingSpec> settings{
    {Setting::kBackend, SettingType::kChoice, "Backend", "Inpainting backend", "--backend", "NAME",
     "the inpainter: embedded (offline), openai, sd-webui, stability or comfyui",
     "Who completes the curvature images. embedded: offline, on this computer. openai: DALL-E 2 "
     "or gpt-image-1 (key in OPENAI_API_KEY). sd-webui: AUTOMATIC1111, Forge or SD.Next (Basic "
     "auth from SD_WEBUI_AUTH). stability: Stability AI (STABILITY_API_KEY). comfyui: a ComfyUI "
     "server with the shipped workflow.",
     "the backend", 0, 0},
    {Setting::kServerUrl, SettingType::kText, "ServerUrl", "Server URL", "--url", "URL",
     "the service's address; repeat it for several servers of one service",
     "The service's address; empty: the backend's default (OpenAI's and Stability's public APIs, "
     "http://127.0.0.1:7860 for sd-webui, http://127.0.0.1:8188 for ComfyUI).",
     "the server URL", 0, 0},
    {Setting::kModel, SettingType::kText, "Model", "Model", "--model", "M",
     "openai: dall-e-2 or gpt-image-1",
     "OpenAI: dall-e-2 (the paper's) or gpt-image-1; empty: the default.",
     "the model", 0, 0},
    {Setting::kPrompt, SettingType::kText, "Prompt", "Prompt", "--prompt", "TEXT",
     "what the image shows, for the remote backends",
     "What the image model is told; empty: the paper's prompt for the backend (\"fill in the "
     "blanks\" for DALL-E 2; the curvature colour map description for Stable Diffusion).",
     "the prompt", 0, 0},
    {Setting::kVariations, SettingType::kInt, "Variations", "Variations", "--variations", "N",
     "curvature images the inpainter completes per hole",
     "How many completions of each hole's curvature image to ask for, to choose from.",
     "the number of variations", 1, 10},
    {Setting::kFakeHoles, SettingType::kInt, "FakeHoles", "Fake holes per hole", "--fake-holes", "K",
     "test cuts per hole that choose its fill; 0: faster, the image score chooses, for scans with "
     "hundreds of holes",
     "Embedded backend: cut this many holes of each hole's size into the known surface near it, "
     "fill them every way (the coarse fill, detail amplitudes 0 to 2, the priors) and fill the "
     "real hole the way that came closest to the surface cut out where it is also closer than the "
     "coarse fill on the fake holes that hold half of the coarse fill's error, else with the "
     "coarse fill. 0: every hole gets the detail amplitude given.",
     "the fake holes per hole", 0, 16},
    {Setting::kDetail, SettingType::kFloat, "Detail", "Detail", "--detail", "A",
     "embedded: the detail's amplitude (0: smooth); fill then uses it on every hole",
     "Embedded backend, with no fake holes: the amplitude of the synthesised detail, relative to "
     "the surroundings' own (0: the smooth continuation of the curvature).",
     "the embedded inpainter's detail", 0, 10},
    {Setting::kSymmetry, SettingType::kBool, "Symmetry", "Use the object's symmetry",
     "--no-symmetry", "", "never fill a hole from the object's mirror image",
     "Find the object's mirror planes: a hole whose mirror image is known surface gets its "
     "mirrored curvature (\"symmetry\") and its mirrored surface (\"symmetry surface\") as two "
     "more variations, used where the fake holes validate them.",
     "the symmetry prior", 0, 1},
    {Setting::kExemplar, SettingType::kBool, "Exemplar", "Offer exemplar variations", "--exemplar",
     "", "also offer patches of the known curvature copied in (embedded)",
     "Embedded backend: as many more variations copied from patches of the known curvature, "
     "ridges and valleys first (\"exemplar\"), used where the fake holes validate them.",
     "the exemplar variations", 0, 1},
    {Setting::kLearned, SettingType::kBool, "Learned", "Offer the learned inpainter's fill",
     "--learned", "", "also offer the learned inpainter's completion (embedded)",
     "Embedded backend: one more variation (\"learned\"): the continuation of the curvature "
     "corrected by a small network trained on curvature images of public meshes, used where the "
     "fake holes validate it.",
     "the learned inpainter", 0, 1},
    {Setting::kCreases, SettingType::kBool, "Creases", "Carry creases across holes",
     "--no-creases", "", "never extend sharp edges or flat faces across a hole",
     "A hole that sharp edges run into gets one more variation (\"creases\"): the smooth faces "
     "around it extended until they meet, so edges and corners come back sharp; a hole inside "
     "one smooth face with no sharp edge near, that face extended (\"face\"). Used where the fake "
     "holes validate it.",
     "the crease prior", 0, 1},
    {Setting::kTriLaplacian, SettingType::kBool, "TriLaplacian", "Continue the curvature",
     "--no-tri-laplacian", "", "never continue the curvature around a hole smoothly",
     "Each hole gets one more variation (\"tri-laplacian\"): its fill faired to continue the "
     "curvature of the surface around it, not only its tangents; used where the fake holes "
     "validate it.",
     "the tri-Laplacian prior", 0, 1},
    {Setting::kMode, SettingType::kChoice, "Mode", "Deformation", "--mode", "MODE",
     "the deformation: direct, or paper for the paper's loop",
     "How the fill follows its image. direct: a few sparse solves for the positions whose mean "
     "curvature matches the image (faster, closer). paper: the paper's small steps of control "
     "vertices along the normals.",
     "the deformation mode", 0, 0},
    {Setting::kSimilitude, SettingType::kFloat, "Similitude", "Similitude (paper mode)",
     "--similitude", "S", "paper mode: colour difference that marks a vertex to move",
     "Paper mode: a vertex moves while its colour differs from the image's by more than this in "
     "any channel (of 255; the paper's 30).",
     "the similitude", 0, 255},
    {Setting::kTransformationConstant, SettingType::kFloat, "TransformationConstant",
     "Transformation constant (paper mode)", "--transformation-constant", "T",
     "paper mode: a move per step",
     "Paper mode: each step of a differing vertex along its normal, as a fraction of the unit "
     "box (the paper's 0.00005).",
     "the transformation constant", 0, 1},
    {Setting::kImageSize, SettingType::kInt, "ImageSize", "Image size (pixels)", "--size", "PX",
     "the curvature images' size",
     "The side of the curvature images given to the inpainter: larger keeps finer detail and "
     "takes longer.",
     "the image size (pixels)", 16, 8192},
    {Setting::kMaxHoleSize, SettingType::kInt, "MaxHoleSize", "Max size to be closed",
     "--max-hole-edges", "N", "fill only holes of at most N boundary edges; 0: any size",
     "Holes with more boundary edges stay open (like MeshLab's Close Holes). 0: every hole.",
     "the maximum hole size (edges)", 0, 1e9},
    {Setting::kKeepLongestOpen, SettingType::kBool, "KeepLongestOpen",
     "Leave the outer border open", "--keep-longest-open", "",
     "leave the longest border open: the outer border of an open scan",
     "The longest boundary loop is the outer border of an open scan (a terrain, a relief, a face "
     "mask), not a hole: leave it open.",
     "leaving the outer border open", 0, 1},
    {Setting::kSelected, SettingType::kBool, "Selected", "Close holes with selected faces",
     "--selected-only", "", "fill only the holes beside selected faces (PLY, as MeshLab saves them)",
     "Only the holes with a selected face on their border are filled.",
     "filling selected holes only", 0, 1},
  };
  return settings;
}
// clang-format on

std::string Number(double x) {
  return QString::number(x, 'g', 6).toStdString();
}

} // namespace

const std::vector<SettingSpec>& Settings() {
  return AllSettings();
}

const SettingSpec& SettingOf(Setting id) {
  return AllSettings()[static_cast<size_t>(id)];
}

HoleFillParams DefaultSettings() {
  HoleFillParams p;
  p.images.image_size = 512;
  return p;
}

double SettingValue(Setting id, const HoleFillParams& p) {
  switch (id) {
  case Setting::kBackend:
    return double(static_cast<int>(p.inpaint.backend));
  case Setting::kServerUrl:
  case Setting::kModel:
  case Setting::kPrompt:
    return 0;
  case Setting::kVariations:
    return p.inpaint.variations;
  case Setting::kFakeHoles:
    return p.validation.fake_holes;
  case Setting::kDetail:
    return p.inpaint.detail;
  case Setting::kSymmetry:
    return p.symmetry.enabled;
  case Setting::kExemplar:
    return p.exemplar;
  case Setting::kLearned:
    return p.learned;
  case Setting::kCreases:
    return p.creases;
  case Setting::kTriLaplacian:
    return p.tri_laplacian;
  case Setting::kMode:
    return double(static_cast<int>(p.mode));
  case Setting::kSimilitude:
    return p.paper.similitude;
  case Setting::kTransformationConstant:
    return p.paper.transformation_constant;
  case Setting::kImageSize:
    return p.images.image_size;
  case Setting::kMaxHoleSize:
    return p.images.coarse.max_hole_edges;
  case Setting::kKeepLongestOpen:
    return p.images.coarse.keep_longest_open;
  case Setting::kSelected:
    return p.images.coarse.selected_only;
  }
  throw std::out_of_range("no such setting");
}

void SetSetting(Setting id, double value, HoleFillParams& p) {
  switch (id) {
  case Setting::kBackend:
    p.inpaint.backend = static_cast<Backend>(int(value));
    return;
  case Setting::kServerUrl:
  case Setting::kModel:
  case Setting::kPrompt:
    return; // texts: set where they are read
  case Setting::kVariations:
    p.inpaint.variations = int(value);
    return;
  case Setting::kFakeHoles:
    p.validation.fake_holes = int(value);
    return;
  case Setting::kDetail:
    p.inpaint.detail = value;
    return;
  case Setting::kSymmetry:
    p.symmetry.enabled = value != 0;
    return;
  case Setting::kExemplar:
    p.exemplar = value != 0;
    return;
  case Setting::kLearned:
    p.learned = value != 0;
    return;
  case Setting::kCreases:
    p.creases = value != 0;
    return;
  case Setting::kTriLaplacian:
    p.tri_laplacian = value != 0;
    return;
  case Setting::kMode:
    p.mode = static_cast<DeformationMode>(int(value));
    return;
  case Setting::kSimilitude:
    p.paper.similitude = value;
    return;
  case Setting::kTransformationConstant:
    p.paper.transformation_constant = value;
    return;
  case Setting::kImageSize:
    p.images.image_size = int(value);
    return;
  case Setting::kMaxHoleSize:
    p.images.coarse.max_hole_edges = int(value);
    return;
  case Setting::kKeepLongestOpen:
    p.images.coarse.keep_longest_open = value != 0;
    return;
  case Setting::kSelected:
    p.images.coarse.selected_only = value != 0;
    return;
  }
}

std::string SettingText(Setting id, const HoleFillParams& p) {
  switch (id) {
  case Setting::kServerUrl:
    return p.inpaint.url;
  case Setting::kModel:
    return p.inpaint.model;
  case Setting::kPrompt:
    return p.inpaint.prompt;
  default:
    return "";
  }
}

std::vector<std::string> SettingChoices(Setting id) {
  std::vector<std::string> names;
  if (id == Setting::kBackend)
    for (Backend b : InpaintBackends()) names.push_back(BackendName(b));
  if (id == Setting::kMode)
    for (DeformationMode m : {DeformationMode::kDirect, DeformationMode::kPaper})
      names.push_back(DeformationModeName(m));
  return names;
}

void RequireSetting(Setting id, double value) {
  const SettingSpec& s = SettingOf(id);
  const double max = s.type == SettingType::kChoice ? double(SettingChoices(id).size()) - 1 : s.max;
  vcg_ext::RequireRange(value, s.min, max, s.what);
}

std::string SettingHelp(const SettingSpec& s) {
  if (s.type != SettingType::kInt && s.type != SettingType::kFloat) return s.help;
  return std::string(s.help) + " (" + Number(s.min) + " to " + Number(s.max) + ")";
}

std::string SettingBrief(const SettingSpec& s) {
  if (s.type == SettingType::kBool || s.type == SettingType::kText) return s.brief;
  const double value = SettingValue(s.id, DefaultSettings());
  const std::vector<std::string> choices = SettingChoices(s.id);
  const std::string shown = choices.empty() ? Number(value) : choices[size_t(value)];
  return std::string(s.brief) + " (default " + shown + ")";
}

} // namespace curvature_inpaint
