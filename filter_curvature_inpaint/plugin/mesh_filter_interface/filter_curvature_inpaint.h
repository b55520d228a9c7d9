// The plugin for MeshLab 2020.09 and earlier (MeshFilterInterface, the interface meshlabserver
// loads): thin glue over filter_table.h and filter_run.h.
#pragma once

#include <common/interfaces.h>

class FilterCurvatureInpaintPlugin : public QObject, public MeshFilterInterface {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
  Q_INTERFACES(MeshFilterInterface)

public:
  FilterCurvatureInpaintPlugin();

  QString pluginName() const override;
  QString filterName(FilterIDType filter) const override;
  QString filterInfo(FilterIDType filter) const override;
  FilterClass getClass(QAction* a) override;
  FILTER_ARITY filterArity(QAction*) const override { return SINGLE_MESH; }
  int getRequirements(QAction*) override;
  int getPreConditions(QAction*) const override;
  int postCondition(QAction*) const override;
  void initParameterSet(QAction* action, MeshModel& m, RichParameterList& par) override;
  bool applyFilter(QAction* action, MeshDocument& md, const RichParameterList& par,
                   vcg::CallBackPos* cb) override;
};
