// The plugin's filters, declared once: names, help, parameters with their defaults. The
// adapters for MeshLab's two plugin interfaces (mesh_filter_interface/ for 2020.09,
// filter_plugin/ for 2021.05 and later) read this table and translate it; filter_run.h runs a
// filter. Nothing here depends on MeshLab, so the table can be printed and compared with what
// a built plugin lists.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace curvature_inpaint {
namespace plugin {

enum class FilterId { kCoarseHoleFill, kCurvatureImages, kHoleFill, kDeformToImage };

/// MeshLab's filter classes (menus) that the filters fall in; both interfaces have these.
enum FilterCategory : unsigned { kRemeshing = 1, kCleaning = 2, kVertexColoring = 4 };

enum class ParamType { kBool, kInt, kFloat, kString, kEnum };

/// A parameter's value: the member of its type is used (an enum's is `i`, the choice's index).
struct ParamValue {
  bool b = false;
  int i = 0;
  float f = 0;
  std::string s;
};

struct ParamSpec {
  ParamType type;
  std::string name;  ///< the name in filter scripts (meshlabserver XML, MeshLab's history)
  std::string label; ///< the label in MeshLab's parameter dialog
  std::string help;  ///< its tooltip
  ParamValue value;  ///< the default
  std::vector<std::string> choices; ///< kEnum only
};

struct FilterSpec {
  FilterId id;
  std::string name;        ///< MeshLab's menu entry and the scripts' filter name
  std::string python_name; ///< PyMeshLab's style of name (FilterPlugin::pythonFilterName)
  std::string info;        ///< the help shown by MeshLab (HTML)
  unsigned categories;     ///< FilterCategory flags
  /// In the MeshLab GUI the product's own dialog takes the parameters: the filter then declares
  /// none, so MeshLab calls it at once instead of showing its generic dialog.
  bool own_dialog;
  /// In this order: meshlabserver reads a script's parameters by position, so the shipped .mlx
  /// scripts list them the same way.
  std::vector<ParamSpec> params;
};

/// Every filter of the plugin, in menu order.
const std::vector<FilterSpec>& Filters();

/// The filter with this id (one of Filters()).
const FilterSpec& Filter(FilterId id);

/// The parameter values a filter is run with, by name; read from MeshLab's parameter list by
/// the adapters. Empty when the filter's own dialog asks for them.
class ParamValues {
public:
  void Set(const std::string& name, const ParamValue& value) { values_[name] = value; }
  bool Empty() const { return values_.empty(); }
  bool Has(const std::string& name) const { return values_.count(name) != 0; }

  /// These throw std::out_of_range for a name the filter does not declare.
  bool Bool(const std::string& name) const { return values_.at(name).b; }
  int Int(const std::string& name) const { return values_.at(name).i; }
  int Enum(const std::string& name) const { return values_.at(name).i; }
  float Float(const std::string& name) const { return values_.at(name).f; }
  const std::string& String(const std::string& name) const { return values_.at(name).s; }

private:
  std::map<std::string, ParamValue> values_;
};

/// The table as JSON (filters with name, python_name, info, categories, own_dialog and the
/// parameters with type, name, label, help, default and choices): what the adapters must list.
std::string FiltersJson();

} // namespace plugin
} // namespace curvature_inpaint
