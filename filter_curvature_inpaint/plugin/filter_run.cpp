#include "filter_run.h"

#include "meshlab_api.h"

#include "hole_fill_dialog.h"
#include "pipeline/curvature_images.h"
#include "pipeline/hole_fill.h"
#include "pipeline/pipeline.h"
#include "report/hole_report.h"

#include <QApplication>
#include <QDir>
#include <QFileInfo>

#include <algorithm>
#include <cstdlib>

namespace curvature_inpaint {
namespace plugin {
namespace {

/// Whether the filter runs in the MeshLab GUI, where the filters with their own dialog open it.
/// meshlabserver, PyMeshLab and scripts never block on one (nor does the GUI when
/// CURVATURE_INPAINT_NO_DIALOG is set: it then shows MeshLab's parameter dialog).
bool InteractiveSession() {
  return qobject_cast<QApplication*>(QCoreApplication::instance()) != nullptr &&
         QCoreApplication::applicationName().startsWith("MeshLab") &&
         std::getenv("CURVATURE_INPAINT_NO_DIALOG") == nullptr;
}

/// A text parameter without the blanks a dialog field easily gets around a path or address.
std::string Trimmed(const ParamValues& v, const char* name) {
  return QString::fromStdString(v.String(name)).trimmed().toStdString();
}

// After the coordinates changed; MeshModel's method was renamed in 2021.05.
void UpdateBoxAndNormals(MeshModel& mm) {
#if CURVATURE_INPAINT_MESHLAB_FILTER_PLUGIN
  mm.updateBoxAndNormals();
#else
  mm.UpdateBoxAndNormals();
#endif
}

void ReadDeformationParams(const ParamValues& v, HoleFillParams& p) {
  p.mode = v.Enum("Mode") == 1 ? DeformationMode::kPaper : DeformationMode::kDirect;
  p.paper.similitude = v.Float("Similitude");
  p.paper.transformation_constant = v.Float("TransformationConstant");
}

void RunHoleFill(MeshModel& mm, const HoleFillParams& p, const FilterEnvironment& env,
                 const std::vector<HoleVariations>* chosen = nullptr) {
  try {
    const auto result = FillHoles(mm.cm, p, env.progress, chosen);
    // The numbers first, then a line per hole in words, which ends the log where a person
    // looks first.
    for (const std::string& line : DescribeHoleFill(result)) env.log(line);
    for (const std::string& line : DescribeHolesInWords(result)) env.log(line);
  } catch (const std::exception& e) {
    throw FilterError(std::string("Curvature Inpaint Hole Fill: ") + e.what() +
                      ". The mesh was not changed.");
  }
  UpdateBoxAndNormals(mm);
}

void RunCoarseHoleFill(MeshModel& mm, const ParamValues& v, const FilterEnvironment& env) {
  vcg_ext::CoarseFillParams params;
  params.max_hole_edges = v.Int("MaxHoleSize");
  params.keep_longest_open = v.Bool("KeepLongestOpen");
  params.selected_only = v.Bool("Selected");
  params.refine = v.Bool("Refine");
  params.fair = v.Bool("Fair");
  params.dp_max_edges = v.Int("LiepaMaxEdges");
  params.select_new_faces = v.Bool("NewFaceSelected");
  try {
    const vcg_ext::CoarseFillResult result = CoarseFill(mm.cm, params, env.progress);
    for (const std::string& line : DescribeCoarseFill(result)) env.log(line);
  } catch (const std::exception& e) {
    throw FilterError(std::string("Coarse Hole Fill: ") + e.what() + ". The mesh was not changed.");
  }
  UpdateBoxAndNormals(mm);
}

void RunCurvatureImages(MeshModel& mm, const ParamValues& v, const FilterEnvironment& env) {
  CurvatureImagesParams params;
  params.coarse.max_hole_edges = v.Int("MaxHoleSize");
  params.segmentation.context = v.Float("Context");
  params.apss.filter_scale = v.Float("FilterScale");
  params.image_size = v.Int("ImageSize");
  const std::string folder = Trimmed(v, "OutputFolder");
  // Refuse an unusable folder before the mesh is touched.
  const QString qfolder = QString::fromStdString(folder);
  if (!folder.empty() && (!QDir().mkpath(qfolder) || !QFileInfo(qfolder).isWritable()))
    throw FilterError("Curvature Images: cannot write to the output folder " + folder +
                      ". The mesh was not changed.");
  try {
    const auto result = ComputeCurvatureImages(mm.cm, params, env.progress);
    for (const std::string& line : DescribeCurvatureImages(result)) env.log(line);
    if (!folder.empty()) {
      WriteHoleImages(folder, result);
      env.log("wrote the images of " + std::to_string(result.holes.size()) + " holes to " + folder);
    }
  } catch (const std::exception& e) {
    throw FilterError(std::string("Curvature Images: ") + e.what() + ".");
  }
  mm.updateDataMask(MeshModel::MM_VERTCOLOR);
  UpdateBoxAndNormals(mm);
}

void RunHoleFillFromParams(MeshModel& mm, const ParamValues& v, const FilterEnvironment& env) {
  HoleFillParams p;
  p.inpaint.backend = BackendAt(v.Enum("Backend"));
  p.inpaint.url = Trimmed(v, "ServerUrl");
  p.inpaint.model = Trimmed(v, "Model");
  p.inpaint.prompt = v.String("Prompt");
  p.inpaint.variations = v.Int("Variations");
  p.pick = v.Int("Variation");
  p.validation.fake_holes = v.Int("FakeHoles");
  p.inpaint.detail = v.Float("Detail");
  p.symmetry.enabled = v.Bool("Symmetry");
  p.exemplar = v.Bool("Exemplar");
  p.learned = v.Bool("Learned");
  p.creases = v.Bool("Creases");
  p.tri_laplacian = v.Bool("TriLaplacian");
  ReadDeformationParams(v, p);
  p.images.coarse.max_hole_edges = v.Int("MaxHoleSize");
  p.images.coarse.keep_longest_open = v.Bool("KeepLongestOpen");
  p.images.coarse.selected_only = v.Bool("Selected");
  p.images.image_size = v.Int("ImageSize");
  p.images_dir = Trimmed(v, "OutputFolder");
  RunHoleFill(mm, p, env);
}

void RunHoleFillDialog(MeshModel& mm, const FilterEnvironment& env) {
  HoleFillDialog dialog(mm.cm, QApplication::activeWindow());
  // MeshLab shows a wait cursor while a filter runs; the dialog is for pointing and clicking.
  QApplication::setOverrideCursor(Qt::ArrowCursor);
  const int answer = dialog.exec();
  QApplication::restoreOverrideCursor();
  if (answer != QDialog::Accepted) {
    env.log("Curvature Inpaint Hole Fill: cancelled; the mesh was not changed.");
    return;
  }
  HoleFillParams p = dialog.Params();
  p.images.coarse.select_new_faces = true;
  RunHoleFill(mm, p, env, &dialog.Holes());
  mm.updateDataMask(MeshModel::MM_FACEFLAGSELECT);
}

void RunDeformToImage(MeshModel& mm, const ParamValues& v, const FilterEnvironment& env) {
  HoleFillParams p;
  p.inpainted_dir = Trimmed(v, "Folder");
  if (p.inpainted_dir.empty())
    throw FilterError("Deform to Curvature Image: choose the folder of the images.");
  ReadDeformationParams(v, p);
  p.images.coarse.max_hole_edges = v.Int("MaxHoleSize");
  p.images.segmentation.context = v.Float("Context");
  p.images.apss.filter_scale = v.Float("FilterScale");
  p.images.image_size = v.Int("ImageSize");
  RunHoleFill(mm, p, env);
}

} // namespace

void AddRichParameters(const FilterSpec& filter, RichParameterList& list) {
  if (filter.own_dialog && InteractiveSession()) return;
  for (const ParamSpec& p : filter.params) {
    const QString name = QString::fromStdString(p.name);
    const QString label = QString::fromStdString(p.label);
    const QString help = QString::fromStdString(p.help);
    switch (p.type) {
    case ParamType::kBool:
      list.addParam(RichBool(name, p.value.b, label, help));
      break;
    case ParamType::kInt:
      list.addParam(RichInt(name, p.value.i, label, help));
      break;
    case ParamType::kFloat:
      list.addParam(RichFloat(name, p.value.f, label, help));
      break;
    case ParamType::kString:
      list.addParam(RichString(name, QString::fromStdString(p.value.s), label, help));
      break;
    case ParamType::kEnum: {
      QStringList choices;
      for (const std::string& c : p.choices) choices << QString::fromStdString(c);
      list.addParam(RichEnum(name, p.value.i, choices, label, help));
      break;
    }
    }
  }
}

ParamValues ReadRichParameters(const FilterSpec& filter, const RichParameterList& list) {
  ParamValues values;
  for (const ParamSpec& p : filter.params) {
    const QString name = QString::fromStdString(p.name);
    if (!list.hasParameter(name)) continue;
    ParamValue v;
    switch (p.type) {
    case ParamType::kBool:
      v.b = list.getBool(name);
      break;
    case ParamType::kInt:
      v.i = list.getInt(name);
      break;
    case ParamType::kFloat:
      v.f = float(list.getFloat(name));
      break;
    case ParamType::kString:
      v.s = list.getString(name).toStdString();
      break;
    case ParamType::kEnum:
      v.i = list.getEnum(name);
      break;
    }
    values.Set(p.name, v);
  }
  if (!values.Empty())
    for (const ParamSpec& p : filter.params)
      if (!values.Has(p.name))
        throw FilterError(filter.name + ": the parameter " + p.name +
                          " is missing. The mesh was not changed.");
  return values;
}

void RunFilter(const FilterSpec& filter, MeshModel& mesh, const ParamValues& values,
               const FilterEnvironment& env) {
  if (values.Empty() && !filter.params.empty()) {
    if (filter.own_dialog && InteractiveSession()) {
      RunHoleFillDialog(mesh, env);
      return;
    }
    throw FilterError(filter.name + ": no parameters were given. The mesh was not changed.");
  }
  switch (filter.id) {
  case FilterId::kCoarseHoleFill:
    return RunCoarseHoleFill(mesh, values, env);
  case FilterId::kCurvatureImages:
    return RunCurvatureImages(mesh, values, env);
  case FilterId::kHoleFill:
    return RunHoleFillFromParams(mesh, values, env);
  case FilterId::kDeformToImage:
    return RunDeformToImage(mesh, values, env);
  }
}

void RunFilter(const FilterSpec& filter, MeshDocument& document, const RichParameterList& list,
               const FilterEnvironment& env) {
  if (document.mm() == nullptr) throw FilterError("There is no mesh to fill.");
  RunFilter(filter, *document.mm(), ReadRichParameters(filter, list), env);
}

int MeshLabFilterClass(const FilterSpec& filter) {
#if CURVATURE_INPAINT_MESHLAB_FILTER_PLUGIN
  using Interface = FilterPlugin;
#else
  using Interface = MeshFilterInterface;
#endif
  int c = 0;
  if (filter.categories & kRemeshing) c |= Interface::Remeshing;
  if (filter.categories & kCleaning) c |= Interface::Cleaning;
  if (filter.categories & kVertexColoring) c |= Interface::VertexColoring;
  return c;
}

int ChangedMeshParts() {
  return MeshModel::MM_VERTNUMBER | MeshModel::MM_FACENUMBER | MeshModel::MM_FACEVERT |
         MeshModel::MM_VERTCOORD | MeshModel::MM_VERTNORMAL | MeshModel::MM_FACENORMAL |
         MeshModel::MM_FACEFLAGSELECT | MeshModel::MM_VERTCOLOR | MeshModel::MM_VERTQUALITY;
}

} // namespace plugin
} // namespace curvature_inpaint
