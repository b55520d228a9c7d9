#include "filter_curvature_inpaint.h"

#include "curvature_images.h"
#include "hole_fill.h"
#include "hole_fill_dialog.h"
#include "pipeline.h"

#include <QApplication>
#include <QDir>
#include <QFileInfo>

#include <cstdlib>

namespace {

/// Whether the filter runs in the MeshLab GUI, where Curvature Inpaint Hole Fill opens its own
/// dialog. meshlabserver and scripts never block on one (nor does the GUI when
/// CURVATURE_INPAINT_NO_DIALOG is set: it then shows MeshLab's parameter dialog).
bool InteractiveSession() {
  return qobject_cast<QApplication*>(QCoreApplication::instance()) != nullptr &&
         QCoreApplication::applicationName().startsWith("MeshLab") &&
         std::getenv("CURVATURE_INPAINT_NO_DIALOG") == nullptr;
}

// The paper's two constants, shared by Curvature Inpaint Hole Fill and Deform to Curvature Image.
void AddPaperModeParams(RichParameterList& par) {
  const curvature_inpaint::HoleFillParams d;
  par.addParam(RichFloat("Similitude", float(d.paper.similitude), "Similitude (paper mode)",
                         "Colour difference (0-255, any channel) above which a vertex is moved."));
  par.addParam(RichFloat("TransformationConstant", float(d.paper.transformation_constant),
                         "Transformation constant (paper mode)",
                         "How far a differing vertex moves per step, in the unit box."));
}

void ReadDeformationParams(const RichParameterList& par, curvature_inpaint::HoleFillParams& p) {
  p.mode = par.getEnum("Mode") == 1 ? "paper" : "direct";
  p.paper.similitude = par.getFloat("Similitude");
  p.paper.transformation_constant = par.getFloat("TransformationConstant");
}

} // namespace

FilterCurvatureInpaintPlugin::FilterCurvatureInpaintPlugin() {
  typeList << FP_COARSE_HOLE_FILL << FP_CURVATURE_IMAGES << FP_HOLE_FILL << FP_DEFORM_TO_IMAGE;
  for (FilterIDType t : types()) actionList << new QAction(filterName(t), this);
}

QString FilterCurvatureInpaintPlugin::pluginName() const {
  return "FilterCurvatureInpaint";
}

QString FilterCurvatureInpaintPlugin::filterName(FilterIDType filter) const {
  switch (filter) {
  case FP_COARSE_HOLE_FILL:
    return "Curvature Inpaint: Coarse Hole Fill";
  case FP_CURVATURE_IMAGES:
    return "Curvature Inpaint: Curvature Images";
  case FP_HOLE_FILL:
    return "Curvature Inpaint Hole Fill";
  case FP_DEFORM_TO_IMAGE:
    return "Curvature Inpaint: Deform to Curvature Image";
  }
  return {};
}

QString FilterCurvatureInpaintPlugin::filterInfo(FilterIDType filter) const {
  switch (filter) {
  case FP_COARSE_HOLE_FILL:
    return "Closes the holes of the mesh with patches that match the density of the surrounding "
           "triangles and blend smoothly into them (Liepa, <i>Filling holes in meshes</i>, 2003): "
           "a minimum-weight triangulation of each hole (vcglib's ear cutting for very large "
           "holes), refined with Delaunay edge flips, then faired by a bi-Laplacian with "
           "cotangent weights. This is the coarse repair the Curvature Inpaint Hole Fill refines "
           "with detail. Holes whose border touches itself at a vertex are split there. The new "
           "faces are selected afterwards. Requires a mesh whose edges have at most two faces.";
  case FP_CURVATURE_IMAGES:
    return "Fills the holes as the Coarse Hole Fill does, then, around every hole, grows a "
           "disk-shaped patch, estimates its mean curvature by APSS sphere fitting, and "
           "colours the patch's vertices with it: blue convex, green flat, red concave. With "
           "an output folder it also writes, per hole, the curvature image an inpainter is "
           "given (the patch flattened onto a square by mean value coordinates), the same "
           "image with the hole transparent, the hole's black and white mask, and a JSON file "
           "with the patch, its UV coordinates and the normalization.";
  case FP_HOLE_FILL:
    return "Fills the holes of the mesh with detail (\"Deep learning of curvature features for "
           "shape completion\"): a coarse fill, the mean curvature of a patch around each hole "
           "painted as an image, that image completed by an inpainter (the embedded one works "
           "offline; DALL-E 2 / gpt-image-1, Stable Diffusion web UIs, Stability AI and ComfyUI "
           "are options, their keys read from OPENAI_API_KEY, STABILITY_API_KEY, SD_WEBUI_AUTH), "
           "the best-scored of its variations chosen, and the patch deformed until its "
           "curvature matches. The mesh changes only when every stage succeeds.";
  case FP_DEFORM_TO_IMAGE:
    return "The last step of Curvature Inpaint Hole Fill with an image you inpainted yourself: run "
           "Curvature Images with an output folder, complete hole_<k>_curvature.png in any "
           "image editor and save it beside as hole_<k>_inpainted.png, then run this filter on "
           "the same mesh with the same settings. Holes without such a file keep their coarse "
           "fill.";
  }
  return {};
}

MeshFilterInterface::FilterClass FilterCurvatureInpaintPlugin::getClass(QAction* a) {
  if (ID(a) == FP_HOLE_FILL || ID(a) == FP_DEFORM_TO_IMAGE)
    return FilterClass(MeshFilterInterface::Remeshing + MeshFilterInterface::Cleaning);
  if (ID(a) == FP_CURVATURE_IMAGES)
    return FilterClass(MeshFilterInterface::Remeshing + MeshFilterInterface::VertexColoring);
  return FilterClass(MeshFilterInterface::Remeshing + MeshFilterInterface::Cleaning);
}

int FilterCurvatureInpaintPlugin::getRequirements(QAction*) {
  return MeshModel::MM_NONE;
}

int FilterCurvatureInpaintPlugin::getPreConditions(QAction*) const {
  return MeshModel::MM_FACENUMBER;
}

int FilterCurvatureInpaintPlugin::postCondition(QAction*) const {
  return MeshModel::MM_VERTNUMBER | MeshModel::MM_FACENUMBER | MeshModel::MM_VERTCOORD |
         MeshModel::MM_VERTNORMAL | MeshModel::MM_FACENORMAL | MeshModel::MM_FACEFLAGSELECT |
         MeshModel::MM_VERTCOLOR | MeshModel::MM_VERTQUALITY;
}

void FilterCurvatureInpaintPlugin::initParameterSet(QAction* action, MeshModel&,
                                                    RichParameterList& par) {
  // meshlabserver reads script parameters by position: keep this order in the shipped .mlx.
  switch (ID(action)) {
  case FP_COARSE_HOLE_FILL:
    par.addParam(RichInt("MaxHoleSize", 0, "Max size to be closed",
                         "Holes with more boundary edges than this stay open (like MeshLab's "
                         "Close Holes). 0 fills holes of any size."));
    par.addParam(RichBool("KeepLongestOpen", false, "Leave the outer border open",
                          "The longest boundary loop is the outer border of an open scan (a "
                          "terrain, a relief, a face mask), not a hole: leave it open."));
    par.addParam(RichBool("Selected", false, "Close holes with selected faces",
                          "Only the holes with at least one selected face on their border are "
                          "filled."));
    par.addParam(RichBool("Refine", true, "Refine to the surrounding density",
                          "Insert vertices so the fill's edges are as long as the edges around "
                          "the hole (Liepa's refinement with Delaunay edge flips). Off: the "
                          "hole is only triangulated."));
    par.addParam(RichBool("Fair", true, "Fair the fill",
                          "Move the inserted vertices to the smoothest surface (bi-Laplacian, "
                          "cotangent weights) that meets the mesh around the hole with matching "
                          "tangents."));
    par.addParam(RichInt("LiepaMaxEdges", vcg_ext::CoarseFillParams().dp_max_edges,
                         "Optimal triangulation up to (edges)",
                         "Holes up to this many boundary edges get Liepa's minimum-weight "
                         "triangulation, which takes cubic time; larger holes use vcglib's "
                         "ear cutting, which is fast on holes of any size. 3 to 1000."));
    par.addParam(RichBool("NewFaceSelected", true, "Select the newly created faces",
                          "Afterwards the selection is exactly the faces that fill the holes."));
    break;
  case FP_CURVATURE_IMAGES: {
    const curvature_inpaint::CurvatureImagesParams d;
    par.addParam(RichInt("MaxHoleSize", 0, "Max size to be closed",
                         "Holes with more boundary edges than this stay open and get no image. "
                         "0: every hole."));
    par.addParam(RichFloat("Context", float(d.segmentation.context), "Context around each hole",
                           "Width of the known ring around each hole in the image, in hole "
                           "radii. More context shows the inpainter more of the shape; less "
                           "gives the hole more pixels."));
    par.addParam(RichFloat("FilterScale", d.apss.filter_scale, "APSS filter scale",
                           "Support of the APSS sphere fits, in local point spacings (MeshLab's "
                           "MLS filter scale). Larger values smooth the curvature more."));
    par.addParam(RichInt("ImageSize", d.image_size, "Image size (pixels)",
                         "Side of the square images: 1024 for DALL-E 2, 512 for Stable "
                         "Diffusion."));
    par.addParam(RichString("OutputFolder", "", "Output folder",
                            "Where to write hole_<k>_curvature.png, hole_<k>_rgba.png, "
                            "hole_<k>_mask.png and hole_<k>.json for every hole. Empty: only "
                            "colour the mesh."));
    break;
  }
  case FP_HOLE_FILL: {
    // In the GUI the product's dialog takes the parameters (applyHoleFillInteractive); with
    // none declared, MeshLab goes straight to applyFilter instead of its generic dialog.
    if (InteractiveSession()) break;
    const curvature_inpaint::HoleFillParams d;
    QStringList backends;
    for (const auto& b : curvature_inpaint::InpaintBackends())
      backends << QString::fromStdString(b);
    par.addParam(
        RichEnum("Backend", 0, backends, "Inpainting backend",
                 "embedded: offline, the default. openai: DALL-E 2 or gpt-image-1 (key in "
                 "OPENAI_API_KEY). sd-webui: AUTOMATIC1111, Forge or SD.Next (Basic auth "
                 "from SD_WEBUI_AUTH). stability: Stability AI (STABILITY_API_KEY). comfyui: "
                 "a ComfyUI server with the shipped workflow."));
    par.addParam(RichString("ServerUrl", "", "Server URL",
                            "The service's address; empty: the backend's default (OpenAI's and "
                            "Stability's public APIs, http://127.0.0.1:7860 for sd-webui, "
                            "http://127.0.0.1:8188 for ComfyUI)."));
    par.addParam(RichString("Model", "", "Model", "openai: dall-e-2 (default) or gpt-image-1."));
    par.addParam(
        RichString("Prompt", "", "Prompt",
                   "Empty: the paper's prompt for the backend (\"fill in the blanks\" for "
                   "DALL-E 2; the curvature colour map description for Stable Diffusion)."));
    par.addParam(RichInt("Variations", d.inpaint.variations, "Variations",
                         "How many completions of each hole's image to ask for (1-10)."));
    par.addParam(
        RichInt("Variation", 0, "Variation to use",
                "0: the one with the best score (continuity across the hole's border, "
                "colours on the palette, values in the surroundings' range); k: the k-th."));
    par.addParam(RichInt("FakeHoles", d.validation.fake_holes, "Fake holes per hole",
                         "Embedded backend: cut this many holes of each hole's size into the "
                         "known surface near it, fill them every way (the coarse fill, detail "
                         "amplitudes 0 to 2, the priors below) and fill the real hole the way "
                         "that came closest to the surface cut out (0-16). 0: every hole gets "
                         "the detail below."));
    par.addParam(RichFloat("Detail", float(d.inpaint.detail), "Detail",
                           "Embedded backend, with no fake holes: the amplitude of the "
                           "synthesised detail, relative to the surroundings' own (0-10; 0: "
                           "the smooth continuation of the curvature)."));
    par.addParam(RichBool("Symmetry", d.symmetry.enabled, "Use the object's symmetry",
                          "Find the mirror planes of the object; a hole whose mirror image is "
                          "known surface gets its mirrored curvature and its mirrored surface as "
                          "two more variations, used where the fake holes validate them."));
    par.addParam(RichBool("Exemplar", d.exemplar, "Offer exemplar variations",
                          "Embedded backend: as many more variations copied from patches of "
                          "the known curvature, ridges and valleys first, used where the fake "
                          "holes validate them."));
    par.addParam(RichBool("Creases", d.creases, "Carry creases across holes",
                          "A hole that sharp edges run into gets one more variation: the smooth "
                          "faces around it extended until they meet, so edges and corners come "
                          "back sharp; used where the fake holes validate it."));
    AddPaperModeParams(par);
    par.addParam(
        RichEnum("Mode", 0,
                 QStringList() << "direct"
                               << "paper",
                 "Deformation",
                 "direct: a few sparse solves for the positions whose mean curvature "
                 "matches the image. paper: the paper's small steps of control vertices."));
    par.addParam(RichInt("MaxHoleSize", 0, "Max size to be closed",
                         "Holes with more boundary edges stay open. 0: every hole."));
    par.addParam(RichBool("KeepLongestOpen", false, "Leave the outer border open",
                          "The longest boundary loop is the outer border of an open scan, not "
                          "a hole: leave it open."));
    par.addParam(RichBool("Selected", false, "Close holes with selected faces",
                          "Only the holes with a selected face on their border are filled."));
    par.addParam(RichInt("ImageSize", 512, "Image size (pixels)",
                         "Side of the curvature images given to the inpainter."));
    par.addParam(RichString("OutputFolder", "", "Output folder",
                            "Where to write every hole's images (coarse, mask, variations, final) "
                            "and a montage; empty: nowhere."));
    break;
  }
  case FP_DEFORM_TO_IMAGE: {
    const curvature_inpaint::HoleFillParams d;
    par.addParam(RichString("Folder", "", "Folder of the images",
                            "The output folder of Curvature Images, holding hole_<k>.json and your "
                            "hole_<k>_inpainted.png."));
    par.addParam(RichEnum("Mode", 0,
                          QStringList() << "direct"
                                        << "paper",
                          "Deformation",
                          "direct: a few sparse solves. paper: the paper's small steps."));
    AddPaperModeParams(par);
    par.addParam(
        RichInt("MaxHoleSize", 0, "Max size to be closed", "As given to Curvature Images."));
    par.addParam(RichFloat("Context", float(d.images.segmentation.context),
                           "Context around each hole", "As given to Curvature Images."));
    par.addParam(RichFloat("FilterScale", d.images.apss.filter_scale, "APSS filter scale",
                           "As given to Curvature Images."));
    par.addParam(RichInt("ImageSize", d.images.image_size, "Image size (pixels)",
                         "As given to Curvature Images."));
    break;
  }
  }
}

bool FilterCurvatureInpaintPlugin::applyFilter(QAction* action, MeshDocument& md,
                                               const RichParameterList& par, vcg::CallBackPos* cb) {
  if (md.mm() == nullptr) {
    errorMessage = "There is no mesh to fill.";
    return false;
  }
  switch (ID(action)) {
  case FP_COARSE_HOLE_FILL:
    return applyCoarseHoleFill(*md.mm(), par, cb);
  case FP_CURVATURE_IMAGES:
    return applyCurvatureImages(*md.mm(), par, cb);
  case FP_HOLE_FILL:
    if (!par.hasParameter("Backend") && InteractiveSession())
      return applyHoleFillInteractive(*md.mm(), cb);
    return applyHoleFill(*md.mm(), par, cb);
  case FP_DEFORM_TO_IMAGE: {
    curvature_inpaint::HoleFillParams p;
    p.inpainted_dir = par.getString("Folder").trimmed().toStdString();
    if (p.inpainted_dir.empty()) {
      errorMessage = "Deform to Curvature Image: choose the folder of the images.";
      Log(GLLogStream::WARNING, errorMessage.toStdString());
      return false;
    }
    ReadDeformationParams(par, p);
    p.images.coarse.max_hole_edges = par.getInt("MaxHoleSize");
    p.images.segmentation.context = par.getFloat("Context");
    p.images.apss.filter_scale = par.getFloat("FilterScale");
    p.images.image_size = par.getInt("ImageSize");
    return runHoleFill(*md.mm(), p, cb);
  }
  }
  return false;
}

bool FilterCurvatureInpaintPlugin::applyCoarseHoleFill(MeshModel& mm, const RichParameterList& par,
                                                       vcg::CallBackPos* cb) {
  vcg_ext::CoarseFillParams params;
  params.max_hole_edges = par.getInt("MaxHoleSize");
  params.keep_longest_open = par.getBool("KeepLongestOpen");
  params.selected_only = par.getBool("Selected");
  params.refine = par.getBool("Refine");
  params.fair = par.getBool("Fair");
  params.dp_max_edges = par.getInt("LiepaMaxEdges");
  params.select_new_faces = par.getBool("NewFaceSelected");
  try {
    const vcg_ext::CoarseFillResult result = curvature_inpaint::CoarseFill(mm.cm, params, cb);
    for (const std::string& line : curvature_inpaint::DescribeCoarseFill(result)) Log(line);
  } catch (const std::exception& e) {
    errorMessage = QString("Coarse Hole Fill: ") + e.what() + ". The mesh was not changed.";
    Log(GLLogStream::WARNING, errorMessage.toStdString()); // meshlabserver prints only the log
    return false;
  }
  mm.UpdateBoxAndNormals();
  return true;
}

bool FilterCurvatureInpaintPlugin::applyCurvatureImages(MeshModel& mm, const RichParameterList& par,
                                                        vcg::CallBackPos* cb) {
  curvature_inpaint::CurvatureImagesParams params;
  params.coarse.max_hole_edges = par.getInt("MaxHoleSize");
  params.segmentation.context = par.getFloat("Context");
  params.apss.filter_scale = par.getFloat("FilterScale");
  params.image_size = par.getInt("ImageSize");
  const std::string folder = par.getString("OutputFolder").trimmed().toStdString();
  // Refuse an unusable folder before the mesh is touched.
  if (!folder.empty() && (!QDir().mkpath(QString::fromStdString(folder)) ||
                          !QFileInfo(QString::fromStdString(folder)).isWritable())) {
    errorMessage = QString("Curvature Images: cannot write to the output folder ") +
                   QString::fromStdString(folder) + ". The mesh was not changed.";
    Log(GLLogStream::WARNING, errorMessage.toStdString());
    return false;
  }
  try {
    const auto result = curvature_inpaint::ComputeCurvatureImages(mm.cm, params, cb);
    for (const std::string& line : curvature_inpaint::DescribeCurvatureImages(result)) Log(line);
    if (!folder.empty()) {
      curvature_inpaint::WriteHoleImages(folder, result);
      Log("wrote the images of %zu holes to %s", result.holes.size(), folder.c_str());
    }
  } catch (const std::exception& e) {
    errorMessage = QString("Curvature Images: ") + e.what() + ".";
    Log(GLLogStream::WARNING, errorMessage.toStdString());
    return false;
  }
  mm.updateDataMask(MeshModel::MM_VERTCOLOR);
  mm.UpdateBoxAndNormals();
  return true;
}

bool FilterCurvatureInpaintPlugin::applyHoleFill(MeshModel& mm, const RichParameterList& par,
                                                 vcg::CallBackPos* cb) {
  curvature_inpaint::HoleFillParams p;
  p.inpaint.backend = curvature_inpaint::InpaintBackends().at(std::max(
      0, std::min(int(curvature_inpaint::InpaintBackends().size()) - 1, par.getEnum("Backend"))));
  p.inpaint.url = par.getString("ServerUrl").trimmed().toStdString();
  p.inpaint.model = par.getString("Model").trimmed().toStdString();
  p.inpaint.prompt = par.getString("Prompt").toStdString();
  p.inpaint.variations = par.getInt("Variations");
  p.pick = par.getInt("Variation");
  p.validation.fake_holes = par.getInt("FakeHoles");
  p.inpaint.detail = par.getFloat("Detail");
  p.symmetry.enabled = par.getBool("Symmetry");
  p.exemplar = par.getBool("Exemplar");
  p.creases = par.getBool("Creases");
  ReadDeformationParams(par, p);
  p.images.coarse.max_hole_edges = par.getInt("MaxHoleSize");
  p.images.coarse.keep_longest_open = par.getBool("KeepLongestOpen");
  p.images.coarse.selected_only = par.getBool("Selected");
  p.images.image_size = par.getInt("ImageSize");
  p.images_dir = par.getString("OutputFolder").trimmed().toStdString();
  return runHoleFill(mm, p, cb);
}

bool FilterCurvatureInpaintPlugin::applyHoleFillInteractive(MeshModel& mm, vcg::CallBackPos* cb) {
  curvature_inpaint::HoleFillDialog dialog(mm.cm, QApplication::activeWindow());
  // MeshLab shows a wait cursor while a filter runs; the dialog is for pointing and clicking.
  QApplication::setOverrideCursor(Qt::ArrowCursor);
  const int answer = dialog.exec();
  QApplication::restoreOverrideCursor();
  if (answer != QDialog::Accepted) {
    Log("Curvature Inpaint Hole Fill: cancelled; the mesh was not changed.");
    return true;
  }
  curvature_inpaint::HoleFillParams p = dialog.Params();
  p.images.coarse.select_new_faces = true;
  if (!runHoleFill(mm, p, cb, &dialog.Holes())) return false;
  mm.updateDataMask(MeshModel::MM_FACEFLAGSELECT);
  return true;
}

bool FilterCurvatureInpaintPlugin::runHoleFill(
    MeshModel& mm, const curvature_inpaint::HoleFillParams& p, vcg::CallBackPos* cb,
    const std::vector<curvature_inpaint::HoleVariations>* chosen) {
  try {
    const auto result = curvature_inpaint::FillHoles(mm.cm, p, cb, chosen);
    for (const std::string& line : curvature_inpaint::DescribeHoleFill(result)) Log(line);
  } catch (const std::exception& e) {
    errorMessage =
        QString("Curvature Inpaint Hole Fill: ") + e.what() + ". The mesh was not changed.";
    Log(GLLogStream::WARNING, errorMessage.toStdString());
    return false;
  }
  mm.UpdateBoxAndNormals();
  return true;
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterCurvatureInpaintPlugin)
