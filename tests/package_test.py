"""The Debian package of one MeshLab release (PACKAGE_RELEASE: 2020.09, 2022.02 or 2025.07), as
scripts/package.sh made it into dist/: lintian finds no error; in that release's Debian root
`apt-get install ./<package>.deb` pulls what it needs, the real MeshLab loads the plugin from
where it loads its own and fills a hole with it, the tool names the release, and
`apt-get remove` leaves no file of the package behind."""
import glob
import json
import os
import shutil
import subprocess
import tempfile
import unittest

from support import BUILD, SOURCE, TempDirTest, info, run

RELEASE = os.environ.get("PACKAGE_RELEASE", "")
DIST = os.path.join(SOURCE, "dist")
IN_ROOT = os.path.join(SOURCE, "scripts", "in-meshlab-root.sh")
# The build that lists the filters the table declares (bookworm's is 2020.09's).
RELEASE_BUILD = BUILD if RELEASE == "2020.09" else os.path.join(SOURCE, f"build-{RELEASE}")
SCRIPTS = "/usr/share/curvature-inpaint/scripts"
APT = ["env", "DEBIAN_FRONTEND=noninteractive", "apt-get", "-o", "Acquire::Check-Valid-Until=false",
       "-o", "APT::Sandbox::User=root", "-y", "-q"]


def inside(path):
    """Where a path of this checkout is inside the root (the checkout is mounted at /project)."""
    return "/project/" + os.path.relpath(path, SOURCE)


class Package(TempDirTest):
    def setUp(self):
        debs = glob.glob(os.path.join(DIST, f"curvature-inpaint_*+meshlab{RELEASE}_*.deb"))
        if len(debs) != 1:
            self.fail(f"expected one package for MeshLab {RELEASE!r} in {DIST}, found {debs}: "
                      "run scripts/package.sh")
        self.deb = debs[0]
        # Inside the checkout, so the root sees it.
        self.tmp = tempfile.mkdtemp(prefix="package-test-", dir=BUILD)
        self.addCleanup(shutil.rmtree, self.tmp, ignore_errors=True)

    def in_root(self, *args, timeout=600):
        return run([IN_ROOT, RELEASE, *args], timeout=timeout)

    def test_lintian_finds_no_error(self):
        r = subprocess.run(["lintian", "--fail-on", "error", "--suppress-tags",
                            "bad-distribution-in-changes-file", self.deb],
                           capture_output=True, text=True, timeout=600)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertNotRegex(r.stdout, r"(?m)^E: ")

    def test_installs_works_in_meshlab_and_removes_cleanly(self):
        r = self.in_root(*APT, "install", inside(self.deb), timeout=900)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.addCleanup(self.in_root, *APT, "remove", "curvature-inpaint")
        r = self.in_root("dpkg", "-L", "curvature-inpaint")
        self.assertEqual(r.returncode, 0, r.stderr)
        files = r.stdout.split()
        plugins = [f for f in files if f.endswith("/plugins/libfilter_curvature_inpaint.so")]
        self.assertEqual(len(plugins), 1, files)
        self.assertIn("/usr/bin/curvature-inpaint", files)

        r = self.in_root("curvature-inpaint", "--version")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn(f"MeshLab {RELEASE}", r.stdout)

        self.assert_meshlab_lists_the_filters(plugins[0])
        self.assert_meshlab_fills_a_hole()

        r = self.in_root(*APT, "remove", "curvature-inpaint")
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        left = self.in_root("bash", "-c", 'for f in "$@"; do [ -d "$f" ] || [ ! -e "$f" ] || echo "$f"; done',
                            "left", *files)
        self.assertEqual(left.stdout, "", "files of the package left after apt-get remove")

    def assert_meshlab_lists_the_filters(self, plugin):
        """The installed plugin as MeshLab's own loader reads it, against the one table."""
        lister = inside(os.path.join(RELEASE_BUILD, "bin", "plugin_filters"))
        listed = self.in_root("env", "QT_QPA_PLATFORM=offscreen", lister, plugin)
        self.assertEqual(listed.returncode, 0, listed.stderr)
        table = run([os.path.join(BUILD, "bin", "plugin_filters"), "--table"])
        self.assertEqual([f["name"] for f in json.loads(listed.stdout)],
                         [f["name"] for f in json.loads(table.stdout)])

    def assert_meshlab_fills_a_hole(self):
        scan = self.punched("igea_190k.ply", 21537, 0.04)
        out = self.path("filled.ply")
        if RELEASE == "2020.09":
            # bookworm's meshlabserver, with the filter script the package ships.
            r = self.in_root("xvfb-run", "-a", "meshlabserver", "-i", inside(scan), "-o", inside(out),
                             "-s", f"{SCRIPTS}/curvature_inpaint_hole_fill.mlx")
            log = r.stdout + r.stderr
        else:
            # The release's meshlab GUI, the product's dialog, with the plugin where the package put it.
            shots = os.path.join(self.tmp, "screenshots")
            os.makedirs(shots)
            r = self.in_root("python3", inside(os.path.join(SOURCE, "tests", "meshlab_gui_driver.py")),
                             "hole-fill", RELEASE, "installed", inside(scan), inside(out), inside(shots))
            log = r.stdout
        self.assertEqual(r.returncode, 0, log)
        self.assertIn("filled 1 of 1 holes", log)
        self.assertEqual(info(out)["holes"], 0)


if __name__ == "__main__":
    unittest.main()
