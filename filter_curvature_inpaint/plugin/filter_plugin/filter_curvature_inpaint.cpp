#include "filter_curvature_inpaint.h"

#include "filter_run.h"

#include <common/mlexception.h>

using curvature_inpaint::plugin::FilterId;
using curvature_inpaint::plugin::Filters;

namespace {

const curvature_inpaint::plugin::FilterSpec& Spec(FilterPlugin::ActionIDType id) {
  return curvature_inpaint::plugin::Filter(FilterId(id));
}

} // namespace

FilterCurvatureInpaintPlugin::FilterCurvatureInpaintPlugin() {
  for (const auto& f : Filters()) typeList.push_back(ActionIDType(f.id));
  for (ActionIDType t : types()) actionList.push_back(new QAction(filterName(t), this));
}

QString FilterCurvatureInpaintPlugin::pluginName() const {
  return "FilterCurvatureInpaint";
}

QString FilterCurvatureInpaintPlugin::filterName(ActionIDType filter) const {
  return QString::fromStdString(Spec(filter).name);
}

QString FilterCurvatureInpaintPlugin::pythonFilterName(ActionIDType filter) const {
  return QString::fromStdString(Spec(filter).python_name);
}

QString FilterCurvatureInpaintPlugin::filterInfo(ActionIDType filter) const {
  return QString::fromStdString(Spec(filter).info);
}

FilterPlugin::FilterClass FilterCurvatureInpaintPlugin::getClass(const QAction* a) const {
  return FilterClass(curvature_inpaint::plugin::MeshLabFilterClass(Spec(ID(a))));
}

int FilterCurvatureInpaintPlugin::getPreConditions(const QAction*) const {
  return MeshModel::MM_FACENUMBER;
}

int FilterCurvatureInpaintPlugin::postCondition(const QAction*) const {
  return curvature_inpaint::plugin::ChangedMeshParts();
}

RichParameterList FilterCurvatureInpaintPlugin::initParameterList(const QAction* action,
                                                                  const MeshModel&) {
  RichParameterList par;
  curvature_inpaint::plugin::AddRichParameters(Spec(ID(action)), par);
  return par;
}

std::map<std::string, QVariant>
FilterCurvatureInpaintPlugin::applyFilter(const QAction* action, const RichParameterList& par,
                                          MeshDocument& md, unsigned int&, vcg::CallBackPos* cb) {
  using namespace curvature_inpaint::plugin;
  FilterEnvironment env;
  env.progress = cb;
  env.log = [this](const std::string& line) { this->log(line); };
  env.warn = [this](const std::string& line) { this->log(GLLogStream::WARNING, line); };
  try {
    RunFilter(Spec(ID(action)), md, par, env);
  } catch (const std::exception& e) {
    env.warn(e.what());
    throw MLException(QString::fromStdString(e.what()));
  }
  return {};
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterCurvatureInpaintPlugin)
