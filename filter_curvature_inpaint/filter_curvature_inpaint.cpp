#include "filter_curvature_inpaint.h"

#include "pipeline.h"

FilterCurvatureInpaintPlugin::FilterCurvatureInpaintPlugin() {
  typeList << FP_COARSE_HOLE_FILL;
  for (FilterIDType t : types()) actionList << new QAction(filterName(t), this);
}

QString FilterCurvatureInpaintPlugin::pluginName() const {
  return "FilterCurvatureInpaint";
}

QString FilterCurvatureInpaintPlugin::filterName(FilterIDType filter) const {
  switch (filter) {
  case FP_COARSE_HOLE_FILL:
    return "Curvature Inpaint: Coarse Hole Fill";
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
  }
  return {};
}

MeshFilterInterface::FilterClass FilterCurvatureInpaintPlugin::getClass(QAction*) {
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
                         "ear cutting, which is fast on holes of any size."));
    par.addParam(RichBool("NewFaceSelected", true, "Select the newly created faces",
                          "Afterwards the selection is exactly the faces that fill the holes."));
    break;
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
  }
  return false;
}

bool FilterCurvatureInpaintPlugin::applyCoarseHoleFill(MeshModel& mm, const RichParameterList& par,
                                                       vcg::CallBackPos* cb) {
  vcg_ext::CoarseFillParams params;
  params.max_hole_edges = std::max(0, par.getInt("MaxHoleSize"));
  params.selected_only = par.getBool("Selected");
  params.refine = par.getBool("Refine");
  params.fair = par.getBool("Fair");
  params.dp_max_edges = std::max(3, par.getInt("LiepaMaxEdges"));
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

MESHLAB_PLUGIN_NAME_EXPORTER(FilterCurvatureInpaintPlugin)
