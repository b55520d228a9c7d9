"""The plugin built for MeshLab 2020.09 (MeshFilterInterface) lists exactly the filters of the one
table (plugin/filter_table.h): names, help, classes, parameters with their defaults and help.
The builds for the newer releases are checked the same way by current_meshlab_test."""
import json
import os
import unittest

from support import BUILD, PLUGIN, run

PLUGIN_FILTERS = os.path.join(BUILD, "bin", "plugin_filters")


def filters(what):
    r = run([PLUGIN_FILTERS, what])
    if r.returncode != 0:
        raise AssertionError(r.stderr)
    return json.loads(r.stdout)


class FilterTable(unittest.TestCase):
    def test_the_2020_09_plugin_lists_the_filters_of_the_table(self):
        os.environ["QT_QPA_PLATFORM"] = "offscreen"
        table, listed = filters("--table"), filters(PLUGIN)
        self.assertEqual([f["name"] for f in listed], [f["name"] for f in table])
        for mine, declared in zip(listed, table):
            for key in ("info", "categories", "params"):
                self.assertEqual(mine[key], declared[key], f"{mine['name']}: {key}")
            self.assertIsNone(mine["python_name"])  # 2020.09 has no Python names

    def test_the_shipped_scripts_list_every_parameter_in_the_tables_order(self):
        # meshlabserver reads a script's parameters by position and aborts when one is missing.
        import xml.etree.ElementTree as ET
        scripts = os.path.join(os.environ["CI_SOURCE_DIR"], "filter_curvature_inpaint", "scripts")
        by_name = {f["name"]: f for f in filters("--table")}
        seen = set()
        for name in sorted(os.listdir(scripts)):
            for node in ET.parse(os.path.join(scripts, name)).getroot().iter("filter"):
                declared = by_name[node.get("name")]
                self.assertEqual([p.get("name") for p in node.iter("Param")],
                                 [p["name"] for p in declared["params"]], name)
                seen.add(node.get("name"))
        self.assertEqual(seen, set(by_name))


if __name__ == "__main__":
    unittest.main()
