// The plugin for MeshLab 2021.05 and later (FilterPlugin; built for 2022.02 and 2025.07): thin
// glue over filter_table.h and filter_run.h.
#pragma once

#include <common/plugins/interfaces/filter_plugin.h>

class FilterCurvatureInpaintPlugin : public QObject, public FilterPlugin {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(FILTER_PLUGIN_IID)
  Q_INTERFACES(FilterPlugin)

public:
  FilterCurvatureInpaintPlugin();

  QString pluginName() const override;
  QString filterName(ActionIDType filter) const override;
  QString pythonFilterName(ActionIDType filter) const override;
  QString filterInfo(ActionIDType filter) const override;
  FilterClass getClass(const QAction* a) const override;
  FilterArity filterArity(const QAction*) const override { return SINGLE_MESH; }
  int getPreConditions(const QAction*) const override;
  int postCondition(const QAction*) const override;
  RichParameterList initParameterList(const QAction* action, const MeshModel& m) override;
  std::map<std::string, QVariant> applyFilter(const QAction* action, const RichParameterList& par,
                                              MeshDocument& md, unsigned int& postConditionMask,
                                              vcg::CallBackPos* cb) override;
};
