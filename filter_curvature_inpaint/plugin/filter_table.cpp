#include "filter_table.h"

#include "pipeline/curvature_images.h"
#include "pipeline/fill_settings.h"
#include "pipeline/hole_fill.h"
#include "report/json_text.h"

#include <cstdio>
#include <stdexcept>

namespace curvature_inpaint {
namespace plugin {
namespace {

ParamSpec Bool(const char* name, bool value, const char* label, const std::string& help) {
  ParamSpec p{ParamType::kBool, name, label, help, {}, {}};
  p.value.b = value;
  return p;
}

ParamSpec Int(const char* name, int value, const char* label, const std::string& help) {
  ParamSpec p{ParamType::kInt, name, label, help, {}, {}};
  p.value.i = value;
  return p;
}

ParamSpec Float(const char* name, double value, const char* label, const std::string& help) {
  ParamSpec p{ParamType::kFloat, name, label, help, {}, {}};
  p.value.f = float(value);
  return p;
}

ParamSpec String(const char* name, const std::string& value, const char* label,
                 const std::string& help) {
  ParamSpec p{ParamType::kString, name, label, help, {}, {}};
  p.value.s = value;
  return p;
}

ParamSpec Enum(const char* name, int value, std::vector<std::string> choices, const char* label,
               const std::string& help) {
  ParamSpec p{ParamType::kEnum, name, label, help, {}, std::move(choices)};
  p.value.i = value;
  return p;
}

/// A setting of the hole fill as its filters declare it (fill_settings.h): name, label, help
/// and the default a person starts from.
ParamSpec FromSetting(Setting id) {
  const SettingSpec& s = SettingOf(id);
  const double value = SettingValue(id, DefaultSettings());
  const std::string help = SettingHelp(s);
  switch (s.type) {
  case SettingType::kBool:
    return Bool(s.script_name, value != 0, s.label, help);
  case SettingType::kInt:
    return Int(s.script_name, int(value), s.label, help);
  case SettingType::kFloat:
    return Float(s.script_name, value, s.label, help);
  case SettingType::kChoice:
    return Enum(s.script_name, int(value), SettingChoices(id), s.label, help);
  case SettingType::kText:
    return String(s.script_name, SettingText(id, DefaultSettings()), s.label, help);
  }
  throw std::out_of_range("no such setting type");
}

// The paper's two constants, shared by Curvature Inpaint Hole Fill and Deform to Curvature Image.
void AddPaperModeParams(std::vector<ParamSpec>& params) {
  params.push_back(FromSetting(Setting::kSimilitude));
  params.push_back(FromSetting(Setting::kTransformationConstant));
}

FilterSpec CoarseHoleFill() {
  const vcg_ext::CoarseFillParams d;
  FilterSpec f{
      FilterId::kCoarseHoleFill,
      "Curvature Inpaint: Coarse Hole Fill",
      "meshing_close_holes_curvature_inpaint_coarse",
      "Closes the holes of the mesh with patches that match the density of the surrounding "
      "triangles and blend smoothly into them (Liepa, <i>Filling holes in meshes</i>, "
      "2003): a minimum-weight triangulation of each hole (vcglib's ear cutting for very "
      "large holes), refined with Delaunay edge flips, then faired by a bi-Laplacian with "
      "cotangent weights. This is the coarse repair the Curvature Inpaint Hole Fill "
      "refines with detail. Holes whose border touches itself at a vertex are split "
      "there. The new faces are selected afterwards. Requires a mesh whose edges have at "
      "most two faces.",
      kRemeshing | kCleaning,
      false,
      {}};
  auto& p = f.params;
  p.push_back(FromSetting(Setting::kMaxHoleSize));
  p.push_back(FromSetting(Setting::kKeepLongestOpen));
  p.push_back(FromSetting(Setting::kSelected));
  p.push_back(Bool("Refine", true, "Refine to the surrounding density",
                   "Insert vertices so the fill's edges are as long as the edges around the hole "
                   "(Liepa's refinement with Delaunay edge flips). Off: the hole is only "
                   "triangulated."));
  p.push_back(Bool("Fair", true, "Fair the fill",
                   "Move the inserted vertices to the smoothest surface (bi-Laplacian, cotangent "
                   "weights) that meets the mesh around the hole with matching tangents."));
  p.push_back(Int("LiepaMaxEdges", d.dp_max_edges, "Optimal triangulation up to (edges)",
                  "Holes up to this many boundary edges get Liepa's minimum-weight "
                  "triangulation, which takes cubic time; larger holes use vcglib's ear cutting, "
                  "which is fast on holes of any size. 3 to 1000."));
  p.push_back(Bool("NewFaceSelected", true, "Select the newly created faces",
                   "Afterwards the selection is exactly the faces that fill the holes."));
  return f;
}

FilterSpec CurvatureImages() {
  const CurvatureImagesParams d;
  FilterSpec f{FilterId::kCurvatureImages,
               "Curvature Inpaint: Curvature Images",
               "compute_color_curvature_inpaint_images",
               "Fills the holes as the Coarse Hole Fill does, then, around every hole, grows a "
               "disk-shaped patch, estimates its mean curvature by APSS sphere fitting, and "
               "colours the patch's vertices with it: blue convex, green flat, red concave. With "
               "an output folder it also writes, per hole, the curvature image an inpainter is "
               "given (the patch flattened onto a square by mean value coordinates), the same "
               "image with the hole transparent, the hole's black and white mask, and a JSON file "
               "with the patch, its UV coordinates and the normalization.",
               kRemeshing | kVertexColoring,
               false,
               {}};
  auto& p = f.params;
  p.push_back(Int("MaxHoleSize", 0, "Max size to be closed",
                  "Holes with more boundary edges than this stay open and get no image. 0: every "
                  "hole."));
  p.push_back(Float("Context", d.segmentation.context, "Context around each hole",
                    "Width of the known ring around each hole in the image, in hole radii. More "
                    "context shows the inpainter more of the shape; less gives the hole more "
                    "pixels."));
  p.push_back(Float("FilterScale", d.apss.filter_scale, "APSS filter scale",
                    "Support of the APSS sphere fits, in local point spacings (MeshLab's MLS "
                    "filter scale). Larger values smooth the curvature more."));
  p.push_back(Int("ImageSize", d.image_size, "Image size (pixels)",
                  "Side of the square images: 1024 for DALL-E 2, 512 for Stable Diffusion."));
  p.push_back(String("OutputFolder", "", "Output folder",
                     "Where to write hole_<k>_curvature.png, hole_<k>_rgba.png, hole_<k>_mask.png "
                     "and hole_<k>.json for every hole. Empty: only colour the mesh."));
  return f;
}

FilterSpec HoleFill() {
  FilterSpec f{FilterId::kHoleFill,
               "Curvature Inpaint Hole Fill",
               "meshing_close_holes_curvature_inpaint",
               "Fills the holes of the mesh with detail (\"Deep learning of curvature features for "
               "shape completion\"): a coarse fill, the mean curvature of a patch around each hole "
               "painted as an image, that image completed by an inpainter (the embedded one works "
               "offline; DALL-E 2 / gpt-image-1, Stable Diffusion web UIs, Stability AI and "
               "ComfyUI are options, their keys read from OPENAI_API_KEY, STABILITY_API_KEY, "
               "SD_WEBUI_AUTH), the best-scored of its variations chosen, and the patch deformed "
               "until its curvature matches. The mesh changes only when every stage succeeds.",
               kRemeshing | kCleaning,
               true,
               {}};
  auto& p = f.params;
  p.push_back(FromSetting(Setting::kBackend));
  p.push_back(FromSetting(Setting::kServerUrl));
  p.push_back(FromSetting(Setting::kModel));
  p.push_back(FromSetting(Setting::kPrompt));
  p.push_back(FromSetting(Setting::kVariations));
  p.push_back(Int("Variation", 0, "Variation to use",
                  "0: the one with the best score (continuity across the hole's border, colours "
                  "on the palette, values in the surroundings' range); k: the k-th; -1: none, "
                  "every hole keeps its coarse fill."));
  p.push_back(FromSetting(Setting::kFakeHoles));
  p.push_back(FromSetting(Setting::kDetail));
  p.push_back(FromSetting(Setting::kSymmetry));
  p.push_back(FromSetting(Setting::kExemplar));
  p.push_back(FromSetting(Setting::kLearned));
  p.push_back(FromSetting(Setting::kCreases));
  p.push_back(FromSetting(Setting::kTriLaplacian));
  AddPaperModeParams(p);
  p.push_back(FromSetting(Setting::kMode));
  p.push_back(FromSetting(Setting::kMaxHoleSize));
  p.push_back(FromSetting(Setting::kKeepLongestOpen));
  p.push_back(FromSetting(Setting::kSelected));
  p.push_back(FromSetting(Setting::kImageSize));
  p.push_back(String("OutputFolder", "", "Output folder",
                     "Where to write every hole's images (coarse, mask, variations, final) and a "
                     "montage; empty: nowhere."));
  return f;
}

FilterSpec DeformToImage() {
  const HoleFillParams d;
  FilterSpec f{FilterId::kDeformToImage,
               "Curvature Inpaint: Deform to Curvature Image",
               "meshing_close_holes_curvature_inpaint_from_images",
               "The last step of Curvature Inpaint Hole Fill with an image you inpainted yourself: "
               "run Curvature Images with an output folder, complete hole_<k>_curvature.png in any "
               "image editor and save it beside as hole_<k>_inpainted.png, then run this filter on "
               "the same mesh with the same settings. Holes without such a file keep their coarse "
               "fill.",
               kRemeshing | kCleaning,
               false,
               {}};
  auto& p = f.params;
  p.push_back(String("Folder", "", "Folder of the images",
                     "The output folder of Curvature Images, holding hole_<k>.json and your "
                     "hole_<k>_inpainted.png."));
  p.push_back(FromSetting(Setting::kMode));
  AddPaperModeParams(p);
  p.push_back(Int("MaxHoleSize", 0, "Max size to be closed", "As given to Curvature Images."));
  p.push_back(Float("Context", d.images.segmentation.context, "Context around each hole",
                    "As given to Curvature Images."));
  p.push_back(Float("FilterScale", d.images.apss.filter_scale, "APSS filter scale",
                    "As given to Curvature Images."));
  p.push_back(Int("ImageSize", d.images.image_size, "Image size (pixels)",
                  "As given to Curvature Images."));
  return f;
}

const char* TypeName(ParamType type) {
  switch (type) {
  case ParamType::kBool:
    return "bool";
  case ParamType::kInt:
    return "int";
  case ParamType::kFloat:
    return "float";
  case ParamType::kString:
    return "string";
  case ParamType::kEnum:
    return "enum";
  }
  return "";
}

std::string DefaultJson(const ParamSpec& p) {
  switch (p.type) {
  case ParamType::kBool:
    return p.value.b ? "true" : "false";
  case ParamType::kInt:
  case ParamType::kEnum:
    return std::to_string(p.value.i);
  case ParamType::kFloat: {
    char number[32];
    std::snprintf(number, sizeof number, "%.9g", double(p.value.f));
    return number;
  }
  case ParamType::kString:
    return JsonQuoted(p.value.s);
  }
  return "null";
}

} // namespace

const std::vector<FilterSpec>& Filters() {
  static const std::vector<FilterSpec> filters{CoarseHoleFill(), CurvatureImages(), HoleFill(),
                                               DeformToImage()};
  return filters;
}

const FilterSpec& Filter(FilterId id) {
  for (const FilterSpec& f : Filters())
    if (f.id == id) return f;
  throw std::out_of_range("no such filter");
}

std::string FiltersJson() {
  std::string out = "[";
  for (const FilterSpec& f : Filters()) {
    if (out.size() > 1) out += ",";
    std::string categories;
    const std::pair<unsigned, const char*> names[] = {
        {kRemeshing, "Remeshing"}, {kCleaning, "Cleaning"}, {kVertexColoring, "VertexColoring"}};
    for (const auto& n : names)
      if (f.categories & n.first)
        categories += std::string(categories.empty() ? "" : ",") + JsonQuoted(n.second);
    out += "\n {\"name\": " + JsonQuoted(f.name) +
           ", \"python_name\": " + JsonQuoted(f.python_name) + ", \"info\": " + JsonQuoted(f.info) +
           ", \"categories\": [" + categories +
           "], \"own_dialog\": " + (f.own_dialog ? "true" : "false") + ", \"params\": [";
    for (size_t k = 0; k < f.params.size(); ++k) {
      const ParamSpec& p = f.params[k];
      std::string choices;
      for (const std::string& c : p.choices)
        choices += std::string(choices.empty() ? "" : ", ") + JsonQuoted(c);
      out += std::string(k ? "," : "") + "\n  {\"type\": \"" + TypeName(p.type) +
             "\", \"name\": " + JsonQuoted(p.name) + ", \"label\": " + JsonQuoted(p.label) +
             ", \"help\": " + JsonQuoted(p.help) + ", \"default\": " + DefaultJson(p) +
             ", \"choices\": [" + choices + "]}";
    }
    out += "]}";
  }
  return out + "\n]\n";
}

} // namespace plugin
} // namespace curvature_inpaint
