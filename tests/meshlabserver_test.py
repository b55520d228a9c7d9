"""The plugin inside Debian's real meshlabserver, driven by the filter scripts we ship."""
import glob
import json
import os
import unittest

from support import (SCRIPTS, TOOL, TempDirTest, info, make_meshlab_prefix, png_size,
                     read_binary_ply_xyz, run, sha256, write_non_manifold_ply)


class MeshlabServer(TempDirTest):
    def setUp(self):
        super().setUp()
        self.bin = make_meshlab_prefix(self.path("prefix"))

    def meshlabserver(self, src, out, script):
        return run(["xvfb-run", "-a", os.path.join(self.bin, "meshlabserver"),
                    "-i", src, "-o", out, "-s", script])

    def test_every_shipped_script_runs_and_fills(self):
        scripts = sorted(glob.glob(os.path.join(SCRIPTS, "*.mlx")))
        self.assertIn("curvature_inpaint_coarse_hole_fill.mlx", [os.path.basename(s) for s in scripts])
        src = self.punched("nefertiti.ply", 33416, 0.03)
        self.assertEqual(info(src)["holes"], 1)
        for script in scripts:
            if script.endswith("deform_to_curvature_image.mlx"):
                continue  # needs a folder of images: its own test below
            with self.subTest(script=os.path.basename(script)):
                out = self.path(os.path.basename(script) + ".ply")
                r = self.meshlabserver(src, out, script)
                self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
                self.assertIn("filled 1 of 1 holes", r.stdout + r.stderr)
                after = info(out)
                self.assertEqual(after["holes"], 0)
                self.assertEqual(after["non_manifold_edges"], 0)

    def test_curvature_images_script_writes_the_images_of_two_holes(self):
        twice = self.punched_twice("nefertiti.ply", (33416, 0.03), (20000, 0.03))
        folder = self.path("images")
        with open(os.path.join(SCRIPTS, "curvature_inpaint_curvature_images.mlx")) as f:
            script = f.read()
        self.assertIn('name="OutputFolder" value=""', script)
        edited = self.path("images.mlx")
        with open(edited, "w") as f:
            f.write(script.replace('name="OutputFolder" value=""', f'name="OutputFolder" value="{folder}"'))
        out = self.path("coloured.ply")
        r = self.meshlabserver(twice, out, edited)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        for k in (1, 2):
            for kind in ("curvature", "rgba", "mask"):
                self.assertEqual(png_size(os.path.join(folder, f"hole_{k}_{kind}.png")), (1024, 1024))
            with open(os.path.join(folder, f"hole_{k}.json")) as f:
                meta = json.load(f)
            self.assertEqual(len(meta["vertices"]), meta["patch_vertices"])
            for v in meta["vertices"]:
                self.assertTrue(0 <= v["u"] <= 1 and 0 <= v["v"] <= 1)
        self.assertEqual(info(out)["holes"], 0)

    def test_hole_fill_script_fills_two_holes_and_keeps_the_rest_bit_for_bit(self):
        twice = self.punched_twice("igea_190k.ply", (21537, 0.04), (60000, 0.03))
        out = self.path("filled.ply")
        r = self.meshlabserver(twice, out, os.path.join(SCRIPTS, "curvature_inpaint_hole_fill.mlx"))
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertIn("filled 2 of 2 holes", r.stdout + r.stderr)
        self.assertEqual(info(out)["holes"], 0)
        self.assertEqual(info(out)["non_manifold_edges"], 0)
        before, after = read_binary_ply_xyz(twice), read_binary_ply_xyz(out)
        self.assertEqual(after[:len(before)], before)

    def test_detail_and_fake_holes_parameters_reach_the_mesh(self):
        # The shipped script validates each hole on fake holes and logs it; with no fake holes,
        # the Detail parameter is the amplitude, and it moves the filled vertices.
        src = self.punched("igea_190k.ply", 21537, 0.04)
        out = self.path("validated.ply")
        r = self.meshlabserver(src, out, os.path.join(SCRIPTS, "curvature_inpaint_hole_fill.mlx"))
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertRegex(r.stdout + r.stderr, r"validation 1: on \d fake holes, .*; chose ")
        with open(os.path.join(SCRIPTS, "curvature_inpaint_hole_fill.mlx")) as f:
            shipped = f.read()
        self.assertIn('name="FakeHoles" value="4"', shipped)
        self.assertIn('name="Detail" value="0"', shipped)
        filled = {}
        for detail in ("0", "2"):
            script = self.path(f"detail_{detail}.mlx")
            with open(script, "w") as f:
                f.write(shipped.replace('name="FakeHoles" value="4"', 'name="FakeHoles" value="0"')
                        .replace('name="Detail" value="0"', f'name="Detail" value="{detail}"'))
            out = self.path(f"detail_{detail}.ply")
            r = self.meshlabserver(src, out, script)
            self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
            self.assertNotIn("validation 1:", r.stdout + r.stderr)
            self.assertEqual(info(out)["holes"], 0)
            filled[detail] = read_binary_ply_xyz(out)
        n = len(read_binary_ply_xyz(src))
        self.assertEqual(filled["0"][:n], filled["2"][:n])
        self.assertNotEqual(filled["0"][n:], filled["2"][n:])
        # Variation -1: no variation, every hole keeps its coarse fill.
        script = self.path("coarse.mlx")
        with open(script, "w") as f:
            f.write(shipped.replace('name="Variation" value="0"', 'name="Variation" value="-1"'))
        out = self.path("coarse.ply")
        r = self.meshlabserver(src, out, script)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertIn("inpaint 1: none: asked to keep its coarse fill", r.stdout + r.stderr)
        # And in words, for the person reading MeshLab's log.
        self.assertRegex(r.stdout + r.stderr,
                         r"hole 1 \(\d+ edges\): kept the smooth fill: asked to keep its coarse fill")
        self.assertEqual(info(out)["holes"], 0)
        coarse = read_binary_ply_xyz(out)
        self.assertEqual(coarse[:n], filled["0"][:n])
        self.assertNotEqual(coarse[n:], filled["2"][n:])

    def test_symmetry_exemplar_learned_and_tri_laplacian_parameters_reach_the_pipeline(self):
        # Igea is mirror-symmetric: the shipped script finds its plane and validates the
        # tri-Laplacian and symmetry candidates (the hole's mirror image is scan), not the
        # exemplar and the learned one (off by default); with the four parameters swapped, the
        # exemplar and the learned one alone.
        src = self.punched("igea_190k.ply", 61000, 0.03)
        with open(os.path.join(SCRIPTS, "curvature_inpaint_hole_fill.mlx")) as f:
            shipped = f.read()
        self.assertIn('name="Symmetry" value="true"', shipped)
        self.assertIn('name="Exemplar" value="false"', shipped)
        self.assertIn('name="TriLaplacian" value="true"', shipped)
        self.assertIn('name="Learned" value="false"', shipped)
        r = self.meshlabserver(src, self.path("shipped.ply"),
                               os.path.join(SCRIPTS, "curvature_inpaint_hole_fill.mlx"))
        log = r.stdout + r.stderr
        self.assertEqual(r.returncode, 0, log)
        self.assertRegex(log, r"symmetry: plane \(")
        self.assertRegex(log, r"validation 1: .*detail 2 [\d.]+, tri-laplacian [\d.]+, symmetry "
                              r"[\d.]+, symmetry surface")
        self.assertNotIn("exemplar", log)
        self.assertNotIn("learned", log)
        script = self.path("swapped.mlx")
        with open(script, "w") as f:
            f.write(shipped.replace('name="Symmetry" value="true"', 'name="Symmetry" value="false"')
                    .replace('name="Exemplar" value="false"', 'name="Exemplar" value="true"')
                    .replace('name="TriLaplacian" value="true"', 'name="TriLaplacian" value="false"')
                    .replace('name="Learned" value="false"', 'name="Learned" value="true"'))
        r = self.meshlabserver(src, self.path("swapped.ply"), script)
        log = r.stdout + r.stderr
        self.assertEqual(r.returncode, 0, log)
        self.assertNotIn("symmetry", log)
        self.assertNotIn("tri-laplacian", log)
        # (The crease prior, on by default, may add the one smooth face around it extended.)
        self.assertRegex(log, r"validation 1: .*detail 2 [\d.]+, exemplar [\d.]+, learned [\d.]+"
                              r"(, face [\d.]+)?; "
                              r"chose")
        self.assertEqual(info(self.path("swapped.ply"))["holes"], 0)

    def edited_script(self, name, value_of):
        with open(os.path.join(SCRIPTS, name)) as f:
            script = f.read()
        for param, value in value_of.items():
            before = f'name="{param}" value=""'
            self.assertIn(before, script)
            script = script.replace(before, f'name="{param}" value="{value}"')
        path = self.path(name)
        with open(path, "w") as f:
            f.write(script)
        return path

    def test_deform_to_an_image_inpainted_by_hand(self):
        src = self.punched("nefertiti.ply", 33416, 0.03)
        folder = self.path("images")
        r = self.meshlabserver(src, self.path("coloured.ply"),
                               self.edited_script("curvature_inpaint_curvature_images.mlx", {"OutputFolder": folder}))
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        # "Inpaint by hand": the embedded backend stands in for a person with an image editor.
        r = run([TOOL, "inpaint", os.path.join(folder, "hole_1_curvature.png"),
                 os.path.join(folder, "hole_1_mask.png"), self.path("hand"), "-n", "1"])
        self.assertEqual(r.returncode, 0, r.stderr)
        os.rename(self.path("hand/variation_1.png"), os.path.join(folder, "hole_1_inpainted.png"))
        out = self.path("deformed.ply")
        r = self.meshlabserver(src, out, self.edited_script("curvature_inpaint_deform_to_curvature_image.mlx",
                                                            {"Folder": folder}))
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertIn("inpaint 1: 43 edges, variation 1 of 1", r.stdout + r.stderr)
        self.assertEqual(info(out)["holes"], 0)

    def test_deform_without_a_folder_is_refused(self):
        src = self.punched("nefertiti.ply", 33416, 0.03)
        out = self.path("out.ply")
        r = self.meshlabserver(src, out, os.path.join(SCRIPTS, "curvature_inpaint_deform_to_curvature_image.mlx"))
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("choose the folder of the images", r.stdout + r.stderr)
        self.assertFalse(os.path.exists(out))

    def test_unwritable_output_folder_changes_nothing(self):
        src = self.punched("nefertiti.ply", 33416, 0.03)
        blocker = self.path("a-file")
        with open(blocker, "w") as f:
            f.write("not a folder\n")
        with open(os.path.join(SCRIPTS, "curvature_inpaint_curvature_images.mlx")) as f:
            script = f.read().replace('name="OutputFolder" value=""',
                                      f'name="OutputFolder" value="{blocker}/images"')
        edited = self.path("images.mlx")
        with open(edited, "w") as f:
            f.write(script)
        out = self.path("out.ply")
        r = self.meshlabserver(src, out, edited)
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("cannot write to the output folder", r.stdout + r.stderr)
        self.assertFalse(os.path.exists(out))

    def test_parameters_out_of_range_are_refused_by_name(self):
        # A script may carry any value: an image size of 0 or a context of "nan" is refused
        # with the parameter's name and range, and nothing is written.
        src = self.punched("nefertiti.ply", 33416, 0.03)
        digest = sha256(src)
        for name, old, new, words in (
                ("curvature_inpaint_hole_fill.mlx", 'name="ImageSize" value="512"', 'name="ImageSize" value="0"',
                 "the image size (pixels) must be from 16 to 8192"),
                ("curvature_inpaint_curvature_images.mlx", 'name="Context" value="1"', 'name="Context" value="nan"',
                 "the context around each hole must be from 0.05 to 100")):
            with self.subTest(script=name):
                with open(os.path.join(SCRIPTS, name)) as f:
                    script = f.read()
                self.assertIn(old, script)
                edited = self.path("edited_" + name)
                with open(edited, "w") as f:
                    f.write(script.replace(old, new))
                out = self.path("out.ply")
                r = self.meshlabserver(src, out, edited)
                self.assertNotEqual(r.returncode, 0)
                self.assertIn(words, r.stdout + r.stderr)
                self.assertFalse(os.path.exists(out))
                self.assertEqual(sha256(src), digest)

    def test_refused_mesh_is_reported_and_not_written(self):
        src = write_non_manifold_ply(self.path("nonmanifold.ply"))
        digest = sha256(src)
        out = self.path("out.ply")
        r = self.meshlabserver(src, out, os.path.join(SCRIPTS, "curvature_inpaint_coarse_hole_fill.mlx"))
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("shared by more than two faces", r.stdout + r.stderr)
        self.assertIn("The mesh was not changed", r.stdout + r.stderr)
        self.assertFalse(os.path.exists(out))
        self.assertEqual(sha256(src), digest)


if __name__ == "__main__":
    unittest.main()
