"""The plugin in a MeshLab of 2021.05 or later (FilterPlugin): MESHLAB_RELEASE (2022.02 or
2025.07) names the release, whose Debian root scripts/setup-meshlab-roots.sh made and whose
build scripts/build-for-meshlab.sh made in build-<release>/. The real `meshlab` of that root,
under Xvfb, with the plugin in its per-user plugin folder: Coarse Hole Fill through MeshLab's
dialog, Curvature Inpaint Hole Fill through the product's, each exported and checked here.
Screenshots of both dialogs go to build-<release>/screenshots/."""
import json
import os
import shutil
import tempfile
import unittest

from support import BUILD, SOURCE, TempDirTest, info, read_binary_ply_xyz, run

RELEASE = os.environ.get("MESHLAB_RELEASE", "")
RELEASE_BUILD = os.path.join(SOURCE, f"build-{RELEASE}")
PLUGIN = os.path.join(RELEASE_BUILD, "plugins", "libfilter_curvature_inpaint.so")
SCREENSHOTS = os.path.join(RELEASE_BUILD, "screenshots")
IN_ROOT = os.path.join(SOURCE, "scripts", "in-meshlab-root.sh")


def inside(path):
    """Where a path of this checkout is inside the root (the checkout is mounted at /project)."""
    return "/project/" + os.path.relpath(path, SOURCE)


class CurrentMeshLab(TempDirTest):
    def setUp(self):
        if not os.path.exists(PLUGIN):
            self.fail(f"no plugin for MeshLab {RELEASE!r} at {PLUGIN}: run scripts/build-for-meshlab.sh")
        # Inside the checkout, so the root sees it.
        self.tmp = tempfile.mkdtemp(prefix="test-", dir=RELEASE_BUILD)
        self.addCleanup(shutil.rmtree, self.tmp, ignore_errors=True)
        os.makedirs(SCREENSHOTS, exist_ok=True)

    def in_root(self, *args, timeout=600):
        return run([IN_ROOT, RELEASE, *args], timeout=timeout)

    def filters(self, what):
        r = self.in_root("env", "QT_QPA_PLATFORM=offscreen", inside(os.path.join(RELEASE_BUILD, "bin", "plugin_filters")),
                         what)
        self.assertEqual(r.returncode, 0, r.stderr)
        return json.loads(r.stdout)

    def test_the_plugin_lists_the_filters_of_the_one_table(self):
        table = self.filters("--table")
        listed = self.filters(inside(PLUGIN))
        self.assertEqual([f["name"] for f in listed], [f["name"] for f in table])
        for mine, declared in zip(listed, table):
            for key in ("python_name", "info", "categories", "params"):
                self.assertEqual(mine[key], declared[key], f"{mine['name']}: {key}")
        self.assertIn("meshing_close_holes_curvature_inpaint", [f["python_name"] for f in listed])
        # The same table as the 2020.09 build's: one declaration for every release.
        r = run([os.path.join(BUILD, "bin", "plugin_filters"), "--table"])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(table, json.loads(r.stdout))

    def gui(self, action, mesh):
        out = self.path("saved.ply")
        r = self.in_root("python3", inside(os.path.join(SOURCE, "tests", "meshlab_gui_driver.py")), action,
                         RELEASE, inside(PLUGIN), inside(mesh), inside(out), inside(SCREENSHOTS))
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertTrue(os.path.exists(out), r.stdout)
        return out, r.stdout

    def assert_filled_keeping_the_scan(self, scan, out):
        self.assertEqual(info(out)["holes"], 0)
        self.assertEqual(info(out)["non_manifold_edges"], 0)
        before, after = read_binary_ply_xyz(scan), read_binary_ply_xyz(out)
        self.assertGreater(len(after), len(before))
        self.assertEqual(after[:len(before)], before)

    def test_coarse_hole_fill_in_meshlabs_dialog(self):
        scan = self.punched("igea_190k.ply", 21537, 0.04)
        out, log = self.gui("coarse-hole-fill", scan)
        self.assertIn("filled 1 of 1 holes", log)
        self.assert_filled_keeping_the_scan(scan, out)

    def test_hole_fill_in_the_products_dialog_with_its_variations(self):
        scan = self.punched("igea_190k.ply", 21537, 0.05)
        out, log = self.gui("hole-fill", scan)
        self.assertIn("filled 1 of 1 holes", log)
        self.assertRegex(log, r"validation 1: on \d fake holes, .*; chose ")
        self.assert_filled_keeping_the_scan(scan, out)

    def test_cancelling_the_products_dialog_leaves_the_mesh_as_it_was(self):
        scan = self.punched("igea_190k.ply", 21537, 0.05)
        out, log = self.gui("hole-fill-cancelled", scan)
        self.assertEqual(info(out)["holes"], 1)
        self.assertEqual(read_binary_ply_xyz(out), read_binary_ply_xyz(scan))


if __name__ == "__main__":
    unittest.main()
