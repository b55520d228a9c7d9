// MeshLab filter plugin "Curvature Inpaint": hole filling with detail, after "Deep learning
// of curvature features for shape completion". A thin layer over pipeline.h.
#pragma once

#include <common/interfaces.h>

#include "hole_fill.h"

class FilterCurvatureInpaintPlugin : public QObject, public MeshFilterInterface {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
  Q_INTERFACES(MeshFilterInterface)

public:
  enum { FP_COARSE_HOLE_FILL, FP_CURVATURE_IMAGES, FP_HOLE_FILL, FP_DEFORM_TO_IMAGE };

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

private:
  bool applyCoarseHoleFill(MeshModel& mm, const RichParameterList& par, vcg::CallBackPos* cb);
  bool applyCurvatureImages(MeshModel& mm, const RichParameterList& par, vcg::CallBackPos* cb);
  bool applyHoleFill(MeshModel& mm, const RichParameterList& par, vcg::CallBackPos* cb);
  bool applyHoleFillInteractive(MeshModel& mm, vcg::CallBackPos* cb);
  bool runHoleFill(MeshModel& mm, const curvature_inpaint::HoleFillParams& p, vcg::CallBackPos* cb,
                   const std::vector<curvature_inpaint::HoleVariations>* chosen = nullptr);
};
