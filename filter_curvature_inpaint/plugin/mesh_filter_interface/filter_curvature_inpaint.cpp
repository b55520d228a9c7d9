#include "filter_curvature_inpaint.h"

#include "filter_run.h"

using curvature_inpaint::plugin::FilterId;
using curvature_inpaint::plugin::Filters;

namespace {

const curvature_inpaint::plugin::FilterSpec& Spec(int id) {
  return curvature_inpaint::plugin::Filter(FilterId(id));
}

} // namespace

FilterCurvatureInpaintPlugin::FilterCurvatureInpaintPlugin() {
  for (const auto& f : Filters()) typeList << int(f.id);
  for (FilterIDType t : types()) actionList << new QAction(filterName(t), this);
}

QString FilterCurvatureInpaintPlugin::pluginName() const {
  return "FilterCurvatureInpaint";
}

QString FilterCurvatureInpaintPlugin::filterName(FilterIDType filter) const {
  return QString::fromStdString(Spec(filter).name);
}

QString FilterCurvatureInpaintPlugin::filterInfo(FilterIDType filter) const {
  return QString::fromStdString(Spec(filter).info);
}

MeshFilterInterface::FilterClass FilterCurvatureInpaintPlugin::getClass(QAction* a) {
  return FilterClass(curvature_inpaint::plugin::MeshLabFilterClass(Spec(ID(a))));
}

int FilterCurvatureInpaintPlugin::getRequirements(QAction*) {
  return MeshModel::MM_NONE;
}

int FilterCurvatureInpaintPlugin::getPreConditions(QAction*) const {
  return MeshModel::MM_FACENUMBER;
}

int FilterCurvatureInpaintPlugin::postCondition(QAction*) const {
  return curvature_inpaint::plugin::ChangedMeshParts();
}

void FilterCurvatureInpaintPlugin::initParameterSet(QAction* action, MeshModel&,
                                                    RichParameterList& par) {
  curvature_inpaint::plugin::AddRichParameters(Spec(ID(action)), par);
}

bool FilterCurvatureInpaintPlugin::applyFilter(QAction* action, MeshDocument& md,
                                               const RichParameterList& par, vcg::CallBackPos* cb) {
  using namespace curvature_inpaint::plugin;
  FilterEnvironment env;
  env.progress = cb;
  env.log = [this](const std::string& line) { Log(line); };
  // meshlabserver prints only the log, not errorMessage: failures go to both.
  env.warn = [this](const std::string& line) { Log(GLLogStream::WARNING, line); };
  try {
    RunFilter(Spec(ID(action)), md, par, env);
  } catch (const std::exception& e) {
    errorMessage = QString::fromStdString(e.what());
    env.warn(e.what());
    return false;
  }
  return true;
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterCurvatureInpaintPlugin)
