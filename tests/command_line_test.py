"""The command line's conventions: help, usage errors, outputs that never replace the scan
unless asked, one hole numbering, --pick as documented, and the new faces marked."""
import json
import os
import re
import shutil
import signal
import subprocess
import unittest

import pngs
from support import (SOURCE, TOOL, TempDirTest, info, read_binary_ply_face_flags, run, sha256)

SAMPLE = os.path.join(SOURCE, "meshes", "sample_holes.ply")
COMMANDS = ["fill", "preview", "coarse", "info", "images", "inpaint", "batch", "punch"]


def montage_holes(folder):
    """{hole number: boundary edges} of the rows of the montage in `folder`."""
    with open(os.path.join(folder, "montage.json")) as f:
        return {row["hole"]: row["boundary_edges"] for row in json.load(f)["rows"]}


def help_options(command):
    """(option, takes a value) for every option `command --help` lists."""
    r = run([TOOL, command, "--help"])
    found = []
    for line in r.stdout.splitlines():
        m = re.match(r"^  (--?[a-z][a-z-]*)( [A-Z][A-Z./_]*)?(\s|$)", line)
        if m and m.group(1) != "--help":
            found.append((m.group(1), m.group(2) is not None))
    return found


class Help(TempDirTest):
    def test_each_command_prints_its_own_help(self):
        for command in COMMANDS:
            with self.subTest(command=command):
                r = run([TOOL, command, "--help"])
                self.assertEqual(r.returncode, 0, r.stderr)
                self.assertEqual(r.stderr, "")
                self.assertTrue(r.stdout.startswith(f"usage: curvature-inpaint {command} "), r.stdout)
                self.assertEqual(run([TOOL, "help", command]).stdout, r.stdout)
                self.assertEqual(run([TOOL, command, "-h"]).stdout, r.stdout)
                self.assertGreater(len(help_options(command)), 0)
                for line in r.stdout.splitlines():
                    self.assertLessEqual(len(line), 80, line)
        r = run([TOOL, "--help"])
        self.assertEqual(r.returncode, 0)
        for command in COMMANDS:
            self.assertRegex(r.stdout, rf"\n  {command} +\w")
        self.assertIn("exit status: 0 done, 1 failed", r.stdout)

    def test_every_option_in_the_help_is_accepted_and_no_other(self):
        files = {"fill": 2, "preview": 2, "coarse": 2, "info": 1, "images": 2, "inpaint": 3,
                 "batch": 2, "punch": 2}
        for command in COMMANDS:
            paths = [self.path(f"absent{k}.ply") for k in range(files[command])]
            for option, valued in help_options(command):
                with self.subTest(command=command, option=option):
                    r = run([TOOL, command, *paths, option, *(["1"] if valued else [])], timeout=60)
                    self.assertNotIn("unknown option", r.stderr)
                    self.assertNotEqual(r.returncode, 0)  # the files are absent
            r = run([TOOL, command, *paths, "--no-such-option"])
            self.assertEqual(r.returncode, 2)
            self.assertEqual(r.stderr.splitlines(),
                             [f"curvature-inpaint: {command}: unknown option --no-such-option",
                              f"see 'curvature-inpaint {command} --help'"])

    def test_version_names_the_meshlab_release(self):
        r = run([TOOL, "--version"])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertRegex(r.stdout, r"^curvature-inpaint \d+\.\d+\.\d+ \(built for MeshLab \d{4}\.\d{2}\)\n$")

    def test_the_manual_page_has_every_command_and_option_the_help_has(self):
        r = run([TOOL, "--man"])
        self.assertEqual(r.returncode, 0, r.stderr)
        page = r.stdout
        self.assertTrue(page.startswith(".TH CURVATURE-INPAINT 1 "), page[:80])
        sections = re.split(r"(?m)^\.SS ", page)
        for command in COMMANDS:
            with self.subTest(command=command):
                section = next(s for s in sections if s.startswith(f'"{command} '))
                for option, valued in help_options(command):
                    roff = option.replace("-", "\\-")
                    self.assertRegex(section, rf"(?m)^\.BI? \"?{re.escape(roff)}[\" \n]")
        # man renders it without a warning.
        page_file = self.path("curvature-inpaint.1")
        with open(page_file, "w") as f:
            f.write(page)
        shown = subprocess.run(["man", "--warnings", "-l", page_file], capture_output=True, text=True,
                               env=dict(os.environ, MANWIDTH="80"), timeout=60)
        self.assertEqual(shown.returncode, 0, shown.stderr)
        self.assertEqual(shown.stderr, "")
        self.assertIn("fill IN OUT", shown.stdout)

    def test_an_option_takes_its_value_after_an_equals_sign(self):
        out = self.path("out.ply")
        r = run([TOOL, "coarse", SAMPLE, out, "--max-hole-edges=40"])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(sorted(info(out)["hole_edges"]), [45, 61])


class NeverOverwrite(TempDirTest):
    """No command writes over its input unless --in-place is given, and then atomically."""

    def scan(self, name="scan.ply"):
        path = self.path(name)
        with open(SAMPLE, "rb") as f, open(path, "wb") as g:
            g.write(f.read())
        return path

    def folder(self, name):
        os.makedirs(self.path(name))
        return self.path(name)

    def test_the_output_may_not_be_the_input(self):
        scan = self.scan()
        before = sha256(scan)
        os.symlink(scan, self.path("link.ply"))
        os.link(scan, self.path("hard.ply"))
        punch = ["--seed-vertex", "10", "--radius-frac", "0.05"]
        for command, extra in (("fill", ["--fake-holes", "0"]), ("coarse", []), ("punch", punch)):
            for out in (scan, self.path("link.ply"), self.path("hard.ply")):
                with self.subTest(command=command, out=os.path.basename(out)):
                    r = run([TOOL, command, scan, out, *extra])
                    self.assertEqual(r.returncode, 1)
                    self.assertEqual(r.stderr, f"curvature-inpaint: {out}: is the input scan; give "
                                               "another output file, or --in-place to replace the "
                                               "scan\n")
                    self.assertEqual(sha256(scan), before)
        r = run([TOOL, "fill", scan, self.path("out.ply"), "--report", scan])
        self.assertEqual(r.returncode, 1)
        self.assertIn("is the input scan", r.stderr)
        self.assertEqual(sha256(scan), before)
        self.assertEqual(sorted(os.listdir(self.tmp)), ["hard.ply", "link.ply", "scan.ply"])

    def test_in_place_replaces_the_scan_whole_or_not_at_all(self):
        # A process killed between writing the new scan and renaming it into place leaves the
        # old scan as it was.
        shim_c, shim = self.path("kill_at_rename.c"), self.path("kill_at_rename.so")
        with open(shim_c, "w") as f:
            f.write("#include <signal.h>\n#include <unistd.h>\n"
                    "int rename(const char* a, const char* b) {\n"
                    "  (void)a; (void)b; kill(getpid(), SIGKILL); return -1;\n}\n")
        subprocess.run(["cc", "-shared", "-fPIC", "-o", shim, shim_c], check=True)
        scan = self.scan()
        before = sha256(scan)
        for command, extra in (("coarse", []), ("fill", ["--fake-holes", "0", "--size", "64"])):
            with self.subTest(command=command):
                r = subprocess.run([TOOL, command, scan, scan, "--in-place", *extra],
                                   capture_output=True, text=True, timeout=300,
                                   env=dict(os.environ, LD_PRELOAD=shim))
                self.assertEqual(r.returncode, -signal.SIGKILL, r.stderr)
                self.assertIn("hole 3", r.stderr)  # the work was done
                self.assertEqual(sha256(scan), before)
        r = run([TOOL, "fill", scan, scan, "--in-place", "--fake-holes", "0", "--size", "64"])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(info(scan)["holes"], 0)
        # Through a link, the linked scan is replaced and the link stays a link.
        other = self.scan("other.ply")
        os.symlink(other, self.path("other_link.ply"))
        link = self.path("other_link.ply")
        r = run([TOOL, "coarse", link, link, "--in-place"])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertTrue(os.path.islink(link))
        self.assertEqual(info(other)["holes"], 0)

    def test_a_bad_output_fails_before_any_work(self):
        scan = self.scan()
        missing = self.path("missing/dir")
        for args, words in (
                ([os.path.join(missing, "out.ply")], f"the folder {missing} does not exist"),
                ([self.path("out.xyz")], 'unsupported format "xyz"'),
                ([self.folder("dir.ply")], "is a folder"),
                ([self.path("out.ply"), "--report", os.path.join(missing, "r.json")],
                 f"the folder {missing} does not exist"),
                ([self.path("out.obj"), "--mark-new"], "--mark-new needs a .ply output")):
            with self.subTest(args=args):
                r = run([TOOL, "fill", scan, *args])
                self.assertNotEqual(r.returncode, 0)
                self.assertIn(words, r.stderr)
                self.assertNotIn("hole 1", r.stderr)
                self.assertNotIn("Coarse fill", r.stderr)
        self.assertEqual(sorted(os.listdir(self.tmp)), ["dir.ply", "scan.ply"])

    def test_an_unknown_backend_is_one_line_naming_the_known_ones(self):
        scan = self.scan()
        r = run([TOOL, "fill", scan, self.path("out.ply"), "--backend", "dalle"])
        self.assertNotEqual(r.returncode, 0)
        self.assertEqual(r.stderr.splitlines(),
                         ['curvature-inpaint: unknown backend "dalle" '
                          '(embedded, openai, sd-webui, stability, comfyui)'])
        self.assertEqual(sorted(os.listdir(self.tmp)), ["scan.ply"])


class HoleNumbering(TempDirTest):
    def five_holes(self):
        """The sample (holes of 29, 45 and 61 edges) with two more of other sizes."""
        once, twice = self.path("once.ply"), self.path("five.ply")
        for src, out, seed, radius in ((SAMPLE, once, 1000, 0.04), (once, twice, 5000, 0.07)):
            r = run([TOOL, "punch", src, out, "--seed-vertex", str(seed), "--radius-frac", str(radius)])
            self.assertEqual(r.returncode, 0, r.stderr)
        edges = info(twice)["hole_edges"]
        self.assertEqual(len(set(edges)), 5, edges)
        return twice

    def test_info_the_log_the_report_and_the_images_number_holes_alike(self):
        scan = self.five_holes()
        for options in ([], ["--max-hole-edges", "50"]):
            with self.subTest(options=options):
                numbered = info(scan, *options)["numbered"]
                self.assertEqual(sorted(numbered), list(range(1, len(numbered) + 1)))
                report, images = self.path("report.json"), self.path("images")
                shutil.rmtree(images, ignore_errors=True)
                r = run([TOOL, "fill", scan, self.path("out.ply"), "--fake-holes", "0", "--size",
                         "64", "--report", report, "--images", images, *options])
                self.assertEqual(r.returncode, 0, r.stderr)
                with open(report) as f:
                    holes = json.load(f)["holes"]
                self.assertEqual({k + 1: h["boundary_edges"] for k, h in enumerate(holes)}, numbered)
                for k, edges in numbered.items():
                    self.assertIn(f"\nhole {k} ({edges} edges): ", r.stderr)
                self.assertEqual(montage_holes(images), numbered)
                shutil.rmtree(images)
                r = run([TOOL, "images", scan, images, "--size", "32", *options])
                self.assertEqual(r.returncode, 0, r.stderr)
                for k, edges in numbered.items():
                    with open(os.path.join(images, f"hole_{k}.json")) as f:
                        self.assertEqual(json.load(f)["boundary_edges"], edges)
                self.assertEqual(montage_holes(images), numbered)

    def test_info_gives_each_holes_size_and_place(self):
        r = run([TOOL, "info", SAMPLE])
        self.assertEqual(r.returncode, 0, r.stderr)
        lines = [l for l in r.stdout.splitlines() if l.startswith("hole ")]
        self.assertEqual(len(lines), 3)
        for line in lines:
            self.assertRegex(line, r"^hole \d: \d+ edges, diameter [0-9.e-]+ \([0-9.]+ % of the "
                                   r"diagonal\), centre \S+ \S+ \S+$")
        r = run([TOOL, "info", SAMPLE, "--max-hole-edges", "50"])
        self.assertEqual(len([l for l in r.stdout.splitlines() if l.startswith("left open: 61 edges")]), 1)


class Pick(TempDirTest):
    """--pick as the help describes it, and an error where a hole cannot follow it."""

    def fill(self, *options):
        out = self.path("out.ply")
        return run([TOOL, "fill", SAMPLE, out, "--fake-holes", "0", "--size", "64", *options]), out

    def test_the_help_lists_exactly_the_kinds_the_tool_takes(self):
        help_text = " ".join(run([TOOL, "fill", "--help"]).stdout.split())
        listed = re.search(r"a kind \(([^)]*)\)", help_text)
        self.assertIsNotNone(listed, help_text)
        r, _ = self.fill("--pick", "no-such-kind")
        self.assertEqual(r.returncode, 2, r.stderr)
        taken = re.search(r"or a kind \(([^)]*)\)", r.stderr)
        self.assertIsNotNone(taken, r.stderr)
        self.assertEqual(listed.group(1), taken.group(1))
        for kind in taken.group(1).split(", "):
            r, _ = self.fill("--pick", kind)
            self.assertEqual(r.returncode, 0, f"--pick {kind}: {r.stderr}")

    def test_a_variation_a_hole_lacks_is_an_error_naming_the_hole(self):
        for pick in ("6", "99"):
            r, out = self.fill("--pick", pick)
            self.assertEqual(r.returncode, 1, r.stderr)
            self.assertRegex(r.stderr, rf"hole \d has no variation {pick}; it has 1-4 continuation")
            self.assertFalse(os.path.exists(out))

    def test_a_list_of_the_wrong_length_is_an_error(self):
        r, out = self.fill("--pick", "1,2")
        self.assertEqual(r.returncode, 1, r.stderr)
        self.assertIn("a pick is given for 2 holes, and the mesh has 3 to fill", r.stderr)
        self.assertFalse(os.path.exists(out))

    def test_a_kind_a_hole_lacks_is_said_in_the_log(self):
        r, _ = self.fill("--pick", "symmetry")
        self.assertEqual(r.returncode, 0, r.stderr)
        lacking = [l for l in r.stderr.splitlines()
                   if re.match(r"hole \d \(\d+ edges\): .*\(it has no symmetry variation\)$", l)]
        having = [l for l in r.stderr.splitlines()
                  if re.match(r"hole \d \(\d+ edges\): the curvature of the mirror image "
                              r"\(variation \d\), as asked$", l)]
        self.assertGreater(len(lacking), 0, r.stderr)
        self.assertGreater(len(having), 0, r.stderr)
        self.assertEqual(len(lacking) + len(having), 3)


class LogAndMontage(TempDirTest):
    """A line per hole in words, the numbers with --verbose, and a montage that explains itself."""

    def test_the_log_says_in_words_what_each_hole_got(self):
        out, images = self.path("out.ply"), self.path("images")
        r = run([TOOL, "fill", SAMPLE, out, "--images", images])
        self.assertEqual(r.returncode, 0, r.stderr)
        lines = [l for l in r.stderr.splitlines() if l.startswith("hole ")]
        self.assertEqual(len(lines), 3, r.stderr)
        for k, line in enumerate(lines, 1):
            self.assertRegex(line, rf"^hole {k} \(\d+ edges\): [a-z ,']+, (better than the smooth fill|"
                                   r"best) on \d of \d test cuts(, \d+ % closer)?$")
        self.assertNotIn("validation 1:", r.stderr)  # the numbers only with --verbose
        self.assertNotIn("ms", r.stderr)
        self.assertEqual(r.stderr.splitlines()[-1], f"wrote {out}: 3 holes filled, 0 left open")
        # The montage frames what the log names, with the same words beneath it.
        with open(os.path.join(images, "montage.json")) as f:
            rows = json.load(f)["rows"]
        for line, row in zip(lines, rows):
            self.assertEqual(line.split(": ", 1)[1], row["reason"])
        verbose = run([TOOL, "fill", SAMPLE, out, "--verbose"])
        self.assertIn("validation 1: on ", verbose.stderr)
        self.assertRegex(verbose.stderr, r"inpaint 1: \d+ edges, .*deform \d+ ms")

    def test_the_montage_labels_its_rows_and_tiles_and_frames_the_choice(self):
        pictures = self.path("preview")
        r = run([TOOL, "preview", SAMPLE, pictures, "--size", "64", "--fake-holes", "0"])
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(pictures, "montage.json")) as f:
            rows = json.load(f)["rows"]
        with open(os.path.join(pictures, "montage.png"), "rb") as f:
            width, height, channels, pixels = pngs.decode(f.read())
        self.assertEqual([row["hole"] for row in rows], [1, 2, 3])
        for row in rows:
            captions = [t["caption"] for t in row["tiles"]]
            self.assertEqual(captions[:2], ["smooth fill", "hole"])
            # The embedded inpainter's continuations at detail 0 are identical: one tile.
            self.assertEqual(captions[2], "1-4 continuation")
            self.assertEqual(row["tiles"][2]["variations"], [1, 4])
            self.assertRegex(" ".join(captions[3:]), r"^5 tri-laplacian")
            framed = row["tiles"][row["framed_tile"]]
            self.assertEqual(framed["variations"], [1, 4])  # the best-scored continuation
            self.assertEqual(row["reason"], "the inpainted curvature, the best-scored of its variations")
            # A white frame around the framed tile, none around the others.
            for tile in row["tiles"]:
                x, y = tile["x"] - 2, tile["y"] + tile["size"] // 2
                pixel = tuple(pixels[y][x * channels:x * channels + 3])
                self.assertEqual(pixel == (255, 255, 255), tile is framed, tile)


class MarkNew(TempDirTest):
    def test_the_new_faces_are_written_selected(self):
        out = self.path("out.ply")
        r = run([TOOL, "coarse", SAMPLE, out, "--mark-new"])
        self.assertEqual(r.returncode, 0, r.stderr)
        added = int(re.search(r"with \d+ vertices and (\d+) faces", r.stderr).group(1))
        flags = read_binary_ply_face_flags(out)
        selected = [bool(f & 0x20) for f in flags]  # vcglib's (and MeshLab's) selection bit
        self.assertEqual(selected, [False] * (len(flags) - added) + [True] * added)
        self.assertIn(f"wrote {out}: 3 holes filled, 0 left open, the new faces selected", r.stderr)

    def test_the_last_line_says_what_was_written(self):
        out, report = self.path("out.ply"), self.path("r.json")
        r = run([TOOL, "fill", SAMPLE, out, "--fake-holes", "0", "--size", "64", "--report", report])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(r.stderr.splitlines()[-1],
                         f"wrote {out}: 3 holes filled, 0 left open (report: {report})")


if __name__ == "__main__":
    unittest.main()
