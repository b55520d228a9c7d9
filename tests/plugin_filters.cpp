// Prints the filters as the one table declares them (--table) or as a built plugin lists them
// to MeshLab (PLUGIN.so), in the same JSON, so a test can compare them for every release.
// The plugin is loaded as MeshLab loads it (QPluginLoader, then the interface's qobject_cast).
#include "filter_table.h"
#include "meshlab_api.h"
#include "report/json_text.h"

#include <QApplication>
#include <QFileInfo>
#include <QPluginLoader>

#include <cstdio>
#include <cstring>
#include <string>

namespace {

#if CURVATURE_INPAINT_MESHLAB_FILTER_PLUGIN
using Interface = FilterPlugin;
#else
using Interface = MeshFilterInterface;
#endif

std::string Json(const QString& text) {
  return curvature_inpaint::JsonQuoted(text.toStdString());
}

std::string Categories(int c) {
  std::string out;
  const std::pair<int, const char*> names[] = {{Interface::Remeshing, "Remeshing"},
                                               {Interface::Cleaning, "Cleaning"},
                                               {Interface::VertexColoring, "VertexColoring"}};
  for (const auto& n : names)
    if (c & n.first) out += std::string(out.empty() ? "" : ",") + "\"" + n.second + "\"";
  return out;
}

std::string Param(const RichParameter& p) {
  const QString type = p.stringType();
  std::string out = "\n  {\"type\": ";
  std::string value = "null", choices;
  if (type == "RichBool") {
    out += "\"bool\"";
    value = p.value().getBool() ? "true" : "false";
  } else if (type == "RichInt") {
    out += "\"int\"";
    value = std::to_string(p.value().getInt());
  } else if (type == "RichFloat") {
    out += "\"float\"";
    char number[32];
    std::snprintf(number, sizeof number, "%.9g", double(p.value().getFloat()));
    value = number;
  } else if (type == "RichString") {
    out += "\"string\"";
    value = Json(p.value().getString());
  } else if (type == "RichEnum") {
    out += "\"enum\"";
    value = std::to_string(p.value().getInt());
    for (const QString& c : static_cast<const RichEnum&>(p).enumvalues)
      choices += std::string(choices.empty() ? "" : ", ") + Json(c);
  } else {
    out += Json(type);
  }
  return out + ", \"name\": " + Json(p.name()) + ", \"label\": " + Json(p.fieldDescription()) +
         ", \"help\": " + Json(p.toolTip()) + ", \"default\": " + value + ", \"choices\": [" +
         choices + "]}";
}

int PrintPlugin(const char* path) {
  QPluginLoader loader(QFileInfo(QString::fromLocal8Bit(path)).absoluteFilePath());
  QObject* instance = loader.instance();
  Interface* plugin = qobject_cast<Interface*>(instance);
  if (plugin == nullptr) {
    std::fprintf(stderr, "plugin_filters: %s is not a filter plugin of this MeshLab: %s\n", path,
                 loader.errorString().toStdString().c_str());
    return 1;
  }
  MeshDocument document;
  MeshModel* mesh = document.addNewMesh("", "empty");
  std::string out = "[";
  for (QAction* action : plugin->actions()) {
    const auto id = plugin->ID(action);
#if CURVATURE_INPAINT_MESHLAB_FILTER_PLUGIN
    const RichParameterList params = plugin->initParameterList(action, *mesh);
    const std::string python_name = Json(plugin->pythonFilterName(id));
#else
    RichParameterList params;
    plugin->initParameterSet(action, *mesh, params);
    const std::string python_name = "null"; // 2020.09 has no Python names
#endif
    if (out.size() > 1) out += ",";
    out += "\n {\"name\": " + Json(plugin->filterName(id)) + ", \"python_name\": " + python_name +
           ", \"info\": " + Json(plugin->filterInfo(id)) + ", \"categories\": [" +
           Categories(plugin->getClass(action)) + "], \"params\": [";
    bool first = true;
    for (const RichParameter& p : params) {
      out += std::string(first ? "" : ",") + Param(p);
      first = false;
    }
    out += "]}";
  }
  std::printf("%s\n]\n", out.c_str());
  return 0;
}

} // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: plugin_filters --table | PLUGIN.so\n");
    return 2;
  }
  if (std::strcmp(argv[1], "--table") == 0) {
    std::printf("%s", curvature_inpaint::plugin::FiltersJson().c_str());
    return 0;
  }
  // A QApplication for the plugin's QActions; not named MeshLab, so no filter opens a dialog.
  QApplication app(argc, argv);
  QCoreApplication::setApplicationName("plugin_filters");
  return PrintPlugin(argv[1]);
}
