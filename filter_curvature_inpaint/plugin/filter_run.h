// Runs one of the table's filters on a MeshLab mesh: the one implementation behind both
// adapters. The adapters turn MeshLab's parameter list into ParamValues, pass MeshLab's log and
// progress callback, and turn a FilterError into their interface's way of failing.
#pragma once

#include "filter_table.h"

#include <functional>
#include <stdexcept>
#include <string>

#include <cstring> // wrap/callback.h uses strcpy without including it
#include <wrap/callback.h>

class MeshDocument;
class MeshModel;
class RichParameterList;

namespace curvature_inpaint {
namespace plugin {

/// A filter failed; what() says why and that the mesh was not changed.
struct FilterError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct FilterEnvironment {
  vcg::CallBackPos* progress = nullptr;
  std::function<void(const std::string&)> log;  ///< MeshLab's log, info level
  std::function<void(const std::string&)> warn; ///< MeshLab's log, warning level
};

/// Declares `filter`'s parameters to MeshLab, in the table's order (the same calls on both
/// interfaces): none in the GUI for a filter with its own dialog, so MeshLab calls it at once.
void AddRichParameters(const FilterSpec& filter, RichParameterList& list);

/// The values of `filter`'s parameters in `list`; empty when MeshLab was given none (the
/// filter's own dialog asks). Throws FilterError when some but not all are there.
ParamValues ReadRichParameters(const FilterSpec& filter, const RichParameterList& list);

/// Runs `filter` on `mesh`. With empty `values` a filter with its own dialog opens it (GUI
/// only); cancelling it leaves the mesh as it was and returns normally. Throws FilterError,
/// the mesh unchanged.
void RunFilter(const FilterSpec& filter, MeshModel& mesh, const ParamValues& values,
               const FilterEnvironment& env);

/// RunFilter on the document's current mesh with the values in MeshLab's `list`: what both
/// adapters' applyFilter does. Throws FilterError when there is no mesh.
void RunFilter(const FilterSpec& filter, MeshDocument& document, const RichParameterList& list,
               const FilterEnvironment& env);

/// MeshLab's filter class flags (its menus) of `filter`, as the interface built against names them.
int MeshLabFilterClass(const FilterSpec& filter);

/// What the filters may change, as MeshModel::MM_* flags (MeshLab's post-conditions).
int ChangedMeshParts();

} // namespace plugin
} // namespace curvature_inpaint
