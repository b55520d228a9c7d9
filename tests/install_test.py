"""`cmake --install`: the plugin where the MeshLab built against loads plugins, the tool, the
filter scripts and the docs, below the prefix and DESTDIR given."""
import os
import subprocess
import unittest

from support import BUILD, MESHLAB_LIB, SOURCE, TempDirTest, run


class Install(TempDirTest):
    def install(self, prefix):
        stage = self.path("stage")
        r = subprocess.run(["cmake", "--install", BUILD, "--prefix", prefix], capture_output=True,
                           text=True, env=dict(os.environ, DESTDIR=stage), timeout=120)
        self.assertEqual(r.returncode, 0, r.stderr)
        return stage + prefix

    def test_a_debian_prefix_puts_the_plugin_where_meshlab_loads_it(self):
        root = self.install("/usr")
        plugin = os.path.join(root, os.path.relpath(MESHLAB_LIB, "/usr"), "plugins",
                              "libfilter_curvature_inpaint.so")
        self.assertTrue(os.path.isfile(plugin), plugin)
        tool = os.path.join(root, "bin", "curvature-inpaint")
        r = run([tool, "--version"])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertTrue(r.stdout.startswith("curvature-inpaint "))
        scripts = sorted(os.listdir(os.path.join(root, "share", "curvature-inpaint", "scripts")))
        self.assertEqual(scripts, sorted(n for n in os.listdir(
            os.path.join(SOURCE, "filter_curvature_inpaint", "scripts")) if n.endswith(".mlx")))
        docs = os.path.join(root, "share", "doc", "curvature-inpaint")
        self.assertTrue(os.path.isfile(os.path.join(docs, "README.md")))
        self.assertTrue(os.path.isfile(os.path.join(docs, "docs", "cli.md")))
        # Nothing lands outside the prefix.
        self.assertEqual(os.listdir(self.path("stage")), ["usr"])

    def test_another_prefix_is_honoured(self):
        root = self.install("/opt/curvature-inpaint")
        self.assertTrue(os.path.isfile(os.path.join(root, "bin", "curvature-inpaint")))
        self.assertEqual(os.listdir(self.path("stage")), ["opt"])


if __name__ == "__main__":
    unittest.main()
