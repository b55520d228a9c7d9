"""The command-line tool on real scans and on bad input."""
import json
import math
import os
import re
import unittest

from support import (SHARED_MESHES, SOURCE, TOOL, TempDirTest, grid, info, png_size,
                     read_binary_ply_xyz, run, sha256, write_ascii_ply, write_binary_ply,
                     write_non_manifold_ply)


class CoarseFill(TempDirTest):
    def test_punched_scan_comes_back_watertight(self):
        src = self.punched("igea_190k.ply", 21537, 0.05)
        before = info(src)
        self.assertEqual(before["holes"], 1)
        out = self.path("filled.ply")
        r = run([TOOL, "coarse", src, out])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("hole 1:", r.stderr)  # a progress line per hole
        after = info(out)
        self.assertEqual(after["holes"], 0)
        self.assertEqual(after["non_manifold_edges"], 0)
        self.assertGreater(after["vertices"], before["vertices"])

    def test_pinched_falcon_bottom_is_closed(self):
        out = self.path("falcon.ply")
        r = run([TOOL, "coarse", os.path.join(SHARED_MESHES, "falconstatue_boundary.ply"), out])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("(pinched)", r.stderr)
        self.assertEqual(info(out)["holes"], 0)

    def test_large_real_hole_is_closed_by_the_ears(self):
        out = self.path("lion.ply")
        r = run([TOOL, "coarse", os.path.join(SHARED_MESHES, "lionstatue.ply"), out])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("322 edges, vcg-ears", r.stderr)
        self.assertIn("opposite orientation", r.stderr)  # the scan's own flipped faces, reported
        self.assertEqual(info(out)["holes"], 0)

    def test_windows_over_the_size_limit_stay_open(self):
        src = os.path.join(SHARED_MESHES, "tower_holes.ply")
        sizes = info(src)["hole_edges"]
        limit = 30
        out = self.path("tower.ply")
        r = run([TOOL, "coarse", src, out, "--max-hole-edges", str(limit)])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(sorted(info(out)["hole_edges"]), sorted(e for e in sizes if e > limit))

    def test_outer_border_of_an_open_scan_stays_open(self):
        # A grid with a hole in the middle: its outer border is the longest loop.
        v, f = grid(12)
        f = [t for k, t in enumerate(f) if k not in (130, 131, 132, 133)]
        src = self.path("relief.ply")
        write_ascii_ply(src, v, f)
        self.assertEqual(len(info(src)["hole_edges"]), 2)
        out = self.path("relief_filled.ply")
        r = run([TOOL, "coarse", src, out, "--keep-longest-open"])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("the longest loop as the scan's outer border", r.stderr)
        self.assertEqual(info(out)["hole_edges"], [48])  # the border, 4 x 12 edges

    def test_holes_wider_than_the_diameter_limit_stay_open(self):
        src = os.path.join(SHARED_MESHES, "tower_holes.ply")
        out = self.path("tower.ply")
        r = run([TOOL, "coarse", src, out, "--max-hole-diameter", "0.05"])
        self.assertEqual(r.returncode, 0, r.stderr)
        left = info(out)["hole_edges"]
        self.assertIn(401, left)  # the widest window
        self.assertLess(len(left), len(info(src)["hole_edges"]))
        self.assertRegex(r.stderr, r"left open: %d over the size limit" % len(left))

    def test_very_large_hole_takes_the_ears_in_bounded_time(self):
        # A 400 x 400 grid, gently curved, with a round hole of over a thousand edges: the log
        # says which triangulation it took (vcglib's ears; Liepa's DP would be cubic).
        n, radius = 400, 150
        v, f = grid(n)
        v = [(x, y, 0.2 * (x - 0.5) ** 2) for x, y, _ in v]
        inside = {i * (n + 1) + j for i in range(n + 1) for j in range(n + 1)
                  if (i - n / 2) ** 2 + (j - n / 2) ** 2 < radius ** 2}
        f = [t for t in f if not any(k in inside for k in t)]
        src = self.path("big_hole.ply")
        write_binary_ply(src, v, f)
        edges = sorted(info(src)["hole_edges"])
        self.assertGreater(edges[0], 1000)  # the hole; the longer loop is the border
        out = self.path("big_hole_filled.ply")
        r = run([TOOL, "coarse", src, out, "--keep-longest-open"])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertRegex(r.stderr, r"hole 1: %d edges, vcg-ears" % edges[0])
        self.assertEqual(info(out)["hole_edges"], [edges[1]])

    def test_genus_one_part_with_a_hole(self):
        src = self.punched("rocker_arm.ply", 100, 0.04)
        out = self.path("rocker.ply")
        r = run([TOOL, "coarse", src, out])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(info(out)["holes"], 0)
        self.assertEqual(info(out)["non_manifold_edges"], 0)

    def test_inconsistent_orientation_is_filled_and_reported(self):
        v, f = grid(10)
        f = [(t if k % 2 else (t[0], t[2], t[1])) for k, t in enumerate(f) if k not in (88, 89, 90, 91)]
        src = self.path("flipped.ply")
        write_ascii_ply(src, v, f)
        out = self.path("flipped_filled.ply")
        r = run([TOOL, "coarse", src, out, "--keep-longest-open"])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("opposite orientation", r.stderr)
        self.assertEqual(len(info(out)["hole_edges"]), 1)  # only the border
        self.assertEqual(info(out)["non_manifold_edges"], 0)

    def test_island_inside_a_hole(self):
        # Two triangles floating inside a hole: the hole and the island's own border are
        # separate loops, each closed on its own; the result is manifold.
        v, f = grid(10)
        cell = lambda k: divmod(k // 2, 10)  # noqa: E731  (row, column) of face k
        hole = [k for k in range(len(f)) if 2 <= cell(k)[0] <= 7 and 2 <= cell(k)[1] <= 7]
        island = [k for k in hole if 4 <= cell(k)[0] <= 5 and 4 <= cell(k)[1] <= 5]
        src = self.path("island.ply")
        write_ascii_ply(src, v, [t for k, t in enumerate(f) if k not in hole or k in island])
        self.assertEqual(len(info(src)["hole_edges"]), 3)
        out = self.path("island_filled.ply")
        r = run([TOOL, "coarse", src, out, "--keep-longest-open"])
        self.assertEqual(r.returncode, 0, r.stderr)
        after = info(out)
        self.assertEqual(after["hole_edges"], [40])  # the grid's border
        self.assertEqual(after["non_manifold_edges"], 0)

    def test_every_format_round_trips(self):
        v, f = grid(12)
        f = [t for k, t in enumerate(f) if k not in (60, 61, 62, 63)]  # a small hole
        src = self.path("grid.ply")
        write_ascii_ply(src, v, f)
        for ext in ("ply", "off", "obj", "stl"):
            out = self.path("out." + ext)
            r = run([TOOL, "coarse", src, out, "--max-hole-edges", "20"])
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(info(out)["holes"], 1, ext)  # only the outer border is left

    def test_obj_as_exporters_write_it(self):
        # Polygons, v/vt/vn corners, negative indices, a continued line, per-vertex colours,
        # groups and materials: the geometry and the colours come through.
        src = self.path("quad.obj")
        with open(src, "w") as f:
            f.write("# exported\nmtllib scan.mtl\no scan\n"
                    "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 1 1 0 0 0 1\nv 0 1 0 \\\n 1 1 0\n"
                    "v 0.5 2 0 0 1 1\nvt 0 0\nvn 0 0 1\ng part\nusemtl skin\ns 1\n"
                    "f 1/1/1 2/1/1 3/1/1 4/1/1\r\nf -2//1 -3//1 -1//1\nl 1 2\n")
        before = info(src)
        self.assertEqual((before["vertices"], before["faces"], before["hole_edges"]), (5, 3, [5]))
        out = self.path("quad_filled.obj")
        r = run([TOOL, "coarse", src, out])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(info(out)["holes"], 0)
        with open(out) as f:
            colours = [line.split()[4:7] for line in f if line.startswith("v ")]
        self.assertEqual(colours[3], ["1.000000", "1.000000", "0.000000"])

def relief(n):
    """grid(n) bent into gentle waves, so curvature images show something."""
    v, f = grid(n)
    return [(x, y, 0.08 * math.sin(5 * x) * math.cos(4 * y)) for x, y, _ in v], f


def box(size, cell):
    """The closed surface of the box [0, sx] x [0, sy] x [0, sz], triangles facing out, edges
    about `cell` long (at least one per side)."""
    vertices, index, faces = [], {}, []

    def vertex(p):
        key = tuple(round(c, 9) for c in p)
        if key not in index:
            index[key] = len(vertices)
            vertices.append(key)
        return index[key]

    for axis in range(3):
        a, b = (axis + 1) % 3, (axis + 2) % 3
        na, nb = max(1, round(size[a] / cell)), max(1, round(size[b] / cell))
        for side in (0, 1):
            def corner(i, j):
                p = [0.0, 0.0, 0.0]
                p[axis], p[a], p[b] = size[axis] * side, size[a] * i / na, size[b] * j / nb
                return vertex(p)
            for i in range(na):
                for j in range(nb):
                    q = (corner(i, j), corner(i + 1, j), corner(i + 1, j + 1), corner(i, j + 1))
                    if side:
                        faces += [(q[0], q[1], q[2]), (q[0], q[2], q[3])]
                    else:
                        faces += [(q[0], q[2], q[1]), (q[0], q[3], q[2])]
    return vertices, faces


def read_off_vertices(path):
    with open(path) as f:
        words = f.read().split()
    assert words[0] == "OFF", words[0]
    nv = int(words[1])
    return [tuple(float(c) for c in words[4 + 3 * i: 7 + 3 * i]) for i in range(nv)]


class HoleShapes(TempDirTest):
    """The whole method (`fill`) on the hole shapes scans bring: each has a defined outcome."""

    def fill(self, src, *options):
        """Runs fill to OFF and checks what holds for every shape: exit 0, manifold, no vertex
        of the input moved (only the fill's own vertices are deformed). Returns (info, report)."""
        out, report = self.path("out.off"), self.path("report.json")
        # Detail on every hole (no fake holes choosing): the deformation runs on each shape.
        r = run([TOOL, "fill", src, out, "--size", "256", "--report", report, "--detail", "1",
                 "--verbose", *options])
        self.assertEqual(r.returncode, 0, r.stderr)
        after = info(out)
        self.assertEqual(after["non_manifold_edges"], 0)
        self.assertEqual(after["inconsistent_edges"], 0)
        before = read_off_vertices(self.to_off(src))
        for p, q in zip(before, read_off_vertices(out)):
            self.assertLess(max(abs(a - b) for a, b in zip(p, q)), 1e-5)
        with open(report) as f:
            return after, json.load(f)

    def to_off(self, src):
        off = self.path("in.off")
        self.assertEqual(run([TOOL, "coarse", src, off, "--max-hole-edges", "1"]).returncode, 0)
        return off

    def assert_detailed(self, report, holes):
        self.assertEqual(len(report["holes"]), holes)
        for h in report["holes"]:
            self.assertGreaterEqual(h["pick"], 1, h)
            self.assertNotIn("problem", h)

    def test_holes_sharing_a_vertex(self):
        # Two square holes touching at one corner: the vertex where they meet is on both
        # loops. Each loop is filled on its own (the log marks them pinched) and gets detail.
        n = 30
        v, f = relief(n)
        cell = lambda k: divmod(k // 2, n)  # noqa: E731
        hole = lambda r, c: 8 <= r < 12 and 8 <= c < 12 or 12 <= r < 16 and 12 <= c < 16  # noqa: E731
        src = self.path("touching.ply")
        write_ascii_ply(src, v, [t for k, t in enumerate(f) if not hole(*cell(k))])
        self.assertEqual(sorted(info(src)["hole_edges"]), [16, 16, 120])
        after, report = self.fill(src, "--keep-longest-open")
        self.assertEqual(after["hole_edges"], [120])  # the border alone
        self.assert_detailed(report, 2)

    def test_holes_facing_each_other_across_a_thin_plate(self):
        # A plate 0.03 thick with a hole of radius 0.1 on each side, 0.02 from the rim: a patch
        # of one hole's radius around either would wrap over the rim into the other. The
        # patches grow in step and stop where they meet: they share no vertex, both get detail.
        v, f = box((1.0, 1.0, 0.03), 1 / 48)

        def in_hole(t):
            c = [sum(v[i][k] for i in t) / 3 for k in range(3)]
            on_face = abs(c[2]) < 1e-9 or abs(c[2] - 0.03) < 1e-9
            return on_face and (c[0] - 0.88) ** 2 + (c[1] - 0.5) ** 2 < 0.1 ** 2
        src = self.path("plate.ply")
        write_ascii_ply(src, v, [t for t in f if not in_hole(t)])
        self.assertEqual(info(src)["hole_edges"], [38, 38])
        images = self.path("images")
        r = run([TOOL, "images", src, images, "--size", "256"])
        self.assertEqual(r.returncode, 0, r.stderr)
        patches = []
        for k in (1, 2):
            with open(os.path.join(images, f"hole_{k}.json")) as f:
                patches.append({p["index"] for p in json.load(f)["vertices"]})
        self.assertEqual(patches[0] & patches[1], set())
        # Both holes lie in a face of the plate: left to itself the fill keeps their flat caps
        # (what the log says); a variation asked for by number is deformed on each.
        after, report = self.fill(src)
        self.assertEqual([h["problem"] for h in report["holes"]],
                         ["a flat cap in its plane; it keeps its coarse fill"] * 2)
        after, report = self.fill(src, "--pick", "1")
        self.assertEqual(after["holes"], 0)
        self.assert_detailed(report, 2)

    def test_island_inside_a_hole(self):
        # The island's border and the hole's are separate loops; both are closed, the island
        # ends up part of the surface.
        v, f = relief(20)
        cell = lambda k: divmod(k // 2, 20)  # noqa: E731
        hole = [k for k in range(len(f)) if 5 <= cell(k)[0] <= 14 and 5 <= cell(k)[1] <= 14]
        island = [k for k in hole if 9 <= cell(k)[0] <= 10 and 9 <= cell(k)[1] <= 10]
        src = self.path("island.ply")
        write_ascii_ply(src, v, [t for k, t in enumerate(f) if k not in hole or k in island])
        self.assertEqual(sorted(info(src)["hole_edges"]), [8, 40, 80])
        after, report = self.fill(src, "--keep-longest-open")
        self.assertEqual(after["hole_edges"], [80])
        self.assertEqual(len(report["holes"]), 2)

    def test_hole_beside_a_handle(self):
        # The rocker arm has genus one; a hole punched by its bore is filled with detail and
        # the handle survives (Euler characteristic 0 before and after).
        src = self.path("rocker_holed.ply")
        r = run([TOOL, "punch", os.path.join(SHARED_MESHES, "rocker_arm.ply"), src,
                 "--seed-vertex", "100", "--radius-frac", "0.04"])
        self.assertEqual(r.returncode, 0, r.stderr)
        after, report = self.fill(src)
        self.assertEqual(after["holes"], 0)
        self.assertEqual(after["vertices"] - after["faces"] // 2, 0)  # V - E + F = V - F / 2
        self.assert_detailed(report, 1)


class DetailAndValidation(TempDirTest):
    """The detail amplitude changes the fill; without one, fake holes choose per hole."""

    SAMPLE = os.path.join(SOURCE, "meshes", "sample_holes.ply")

    def fill(self, *options):
        out, report = self.path("out.ply"), self.path("report.json")
        r = run([TOOL, "fill", self.SAMPLE, out, "--size", "256", "--report", report, "--verbose",
                 *options])
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(report) as f:
            return read_binary_ply_xyz(out), json.load(f)["holes"], r.stderr

    def test_the_detail_amplitude_changes_the_filled_vertices(self):
        n = len(read_binary_ply_xyz(self.SAMPLE))
        smooth, holes0, _ = self.fill("--detail", "0")
        detailed, holes2, _ = self.fill("--detail", "2")
        self.assertEqual(smooth[:n], detailed[:n])  # the scan as it was, both times
        self.assertEqual(len(smooth), len(detailed))
        moved = max(max(abs(a - b) for a, b in zip(p, q)) for p, q in zip(smooth[n:], detailed[n:]))
        self.assertGreater(moved, 1e-4)
        for h in holes0 + holes2:
            self.assertNotIn("validation", h)  # an amplitude given: no fake holes
            self.assertEqual(h["seconds"]["validation"], 0)
        # Detail 0 is the smooth continuation: every continuation the same (the symmetry
        # prior's variations, where a hole has them, come after the continuations).
        def continuations(h):
            return [s for s, kind in zip(h["scores"], h["kinds"]) if kind == "continuation"]
        self.assertTrue(all(len(continuations(h)) == 4 for h in holes0 + holes2))
        self.assertTrue(all(len(set(continuations(h))) == 1 for h in holes0), holes0)
        self.assertTrue(any(len(set(continuations(h))) > 1 for h in holes2), holes2)

    def test_curvature_passes_change_the_deformation(self):
        n = len(read_binary_ply_xyz(self.SAMPLE))
        once, _, _ = self.fill("--detail", "2")
        passes, holes, _ = self.fill("--detail", "2", "--curvature-passes", "3")
        self.assertEqual(once[:n], passes[:n])  # the scan as it was, both times
        moved = max(max(abs(a - b) for a, b in zip(p, q)) for p, q in zip(once[n:], passes[n:]))
        self.assertGreater(moved, 1e-5)
        self.assertTrue(all(not h.get("problem") for h in holes), holes)
        r = run([TOOL, "fill", self.SAMPLE, self.path("x.ply"), "--curvature-passes", "21"])
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("curvature passes", r.stderr)
        self.assertFalse(os.path.exists(self.path("x.ply")))

    def test_fake_holes_choose_and_the_log_says_how(self):
        _, holes, log = self.fill()
        self.assertEqual(len(holes), 3)
        for k, h in enumerate(holes, 1):
            v = h["validation"]
            names = [c["name"] for c in v["candidates"]]
            self.assertEqual(names[:5], ["coarse", "detail 0", "detail 0.5", "detail 1", "detail 2"])
            # The tri-Laplacian fill on every hole; where the hole's mirror image is known
            # surface, the symmetry prior's two more; the exemplar only when asked for.
            self.assertEqual(names[5], "tri-laplacian")
            self.assertIn(names[6:], [[], ["symmetry", "symmetry surface"], ["creases"], ["face"],
                                      ["symmetry", "symmetry surface", "creases"],
                                      ["symmetry", "symmetry surface", "face"]])
            self.assertEqual(h["kinds"][4:], names[5:])
            self.assertGreaterEqual(v["fake_holes"], 1)
            errors = {c["name"]: c["error"] for c in v["candidates"]}
            best = min(errors.values())
            self.assertEqual(v["tie"], 0.1)
            # The best, or tied with it, then of a detail ratio like the cut surface's.
            self.assertLessEqual(errors[v["choice"]], (1 + v["tie"]) * best + 1e-9)
            if errors[v["choice"]] > best:
                ratio = {c["name"]: c["detail_ratio"] for c in v["candidates"]}[v["choice"]]
                self.assertTrue(0.7 <= ratio <= 1.3, v)
            self.assertEqual(h["pick"] == 0, v["choice"] == "coarse", h)
            self.assertIn(f"validation {k}: on {v['fake_holes']} fake hole", log)
            self.assertIn(f"chose {v['choice']}", log)
            # The fake holes' time is their own, not counted in the inpainting's.
            self.assertGreater(h["seconds"]["validation"], 0)
            self.assertRegex(log, rf"inpaint {k}: \d+ edges, .*images \d+ ms, validation \d+ ms, "
                                  r"inpaint \d+ ms, deform \d+ ms")
        # The same seed: the same choices and the same mesh.
        again, holes_again, _ = self.fill()
        self.assertEqual([h["validation"]["choice"] for h in holes],
                         [h["validation"]["choice"] for h in holes_again])

    def test_pick_a_kind_where_a_hole_has_it(self):
        _, holes, _ = self.fill("--exemplar", "--pick", "exemplar", "--fake-holes", "0")
        for h in holes:
            self.assertEqual(h["kind"], "exemplar" if "exemplar" in h["kinds"] else "continuation")
            self.assertEqual(h["kinds"][h["pick"] - 1], h["kind"])
        r = run([TOOL, "fill", self.SAMPLE, self.path("x.ply"), "--pick", "mirror"])
        self.assertEqual(r.returncode, 2)
        self.assertIn('--pick: "mirror" is not auto, coarse, a variation number (1 to 1000) or a '
                      'kind', r.stderr)

    def test_pick_coarse_keeps_every_holes_coarse_fill(self):
        every, holes, _ = self.fill("--pick", "coarse")
        listed, _, _ = self.fill("--pick", "coarse,coarse,coarse")
        self.assertEqual(len(holes), 3)
        for h in holes:
            self.assertEqual(h["pick"], 0)
            self.assertEqual(h["problem"], "asked to keep its coarse fill")
        self.assertEqual(every, listed)
        auto, _, _ = self.fill()
        self.assertNotEqual(every, auto)

    def test_preview_shows_the_fills_variations_and_a_list_picks_per_hole(self):
        before = sha256(self.SAMPLE)
        pictures = self.path("preview")
        r = run([TOOL, "preview", self.SAMPLE, pictures, "--size", "256"])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(sha256(self.SAMPLE), before)  # the mesh is only read
        auto, holes, log = self.fill()
        self.assertEqual(len(holes), 3)
        lines = r.stdout.splitlines()
        for k, h in enumerate(holes, 1):
            # The validation as the fill logs it, and the fill's variations and pick.
            self.assertIn(f"hole {k}: validation " + log.split(f"validation {k}: ")[1].split("\n")[0],
                          lines)
            line = next(l for l in lines if l.startswith(f"hole {k}: variations "))
            shown = re.findall(r"(\d+) ([a-z -]+) \(score ", line)
            self.assertEqual([int(j) for j, _ in shown], list(range(1, len(h["kinds"]) + 1)))
            self.assertEqual([kind for _, kind in shown], h["kinds"])
            self.assertTrue(line.endswith(f"; fill picks {h['pick']}"), line)
            for j in range(1, len(h["kinds"]) + 1):
                self.assertEqual(png_size(os.path.join(pictures, f"hole_{k}_variation_{j}.png")),
                                 (256, 256))
            self.assertFalse(os.path.exists(os.path.join(pictures, f"hole_{k}_final.png")))
        self.assertTrue(os.path.exists(os.path.join(pictures, "montage.png")))
        # One entry per hole: the last variation of hole 1 (not what fill picks by itself),
        # hole 2's coarse fill, hole 3 as fill picks it.
        last = len(holes[0]["kinds"])
        self.assertNotEqual(holes[0]["pick"], last)
        picked, listed, _ = self.fill("--pick", f"{last},coarse,auto")
        self.assertEqual(listed[0]["pick"], last)
        self.assertEqual(listed[0]["kind"], holes[0]["kinds"][last - 1])
        self.assertEqual(listed[1]["pick"], 0)
        self.assertEqual(listed[1]["problem"], "asked to keep its coarse fill")
        self.assertNotIn("validation", listed[1])  # neither validated nor inpainted
        self.assertEqual(listed[2]["pick"], holes[2]["pick"])
        self.assertNotEqual(picked, auto)
        r = run([TOOL, "fill", self.SAMPLE, self.path("x.ply"), "--pick", "1,99,auto"])
        self.assertEqual(r.returncode, 1)
        self.assertRegex(r.stderr, r"hole 2 has no variation 99; it has 1-\d continuation")
        self.assertFalse(os.path.exists(self.path("x.ply")))
        r = run([TOOL, "fill", self.SAMPLE, self.path("x.ply"), "--pick", "1,first,auto"])
        self.assertEqual(r.returncode, 2)
        self.assertIn('"first" is not auto, coarse, a variation number', r.stderr)
        r = run([TOOL, "preview", self.SAMPLE, pictures, "--report", self.path("r.json")])
        self.assertEqual(r.returncode, 2)

    def test_a_fill_makes_only_the_variations_its_pick_can_take(self):
        # Asked for pictures, a fill makes and shows every variation; without, only those its
        # automatic pick can take, the others listed unmade (no score): the same mesh, bytes
        # and all, the same choices, and the same numbers for the variations.
        lazy, holes, log = self.fill()
        every, holes_every, _ = self.fill("--images", self.path("pictures"))
        self.assertEqual(lazy, every)
        unmade = 0
        for h, e in zip(holes, holes_every):
            self.assertEqual((h["kinds"], h["pick"], h["validation"]),
                             (e["kinds"], e["pick"], e["validation"]))
            self.assertNotIn(None, e["scores"])
            for s, t in zip(h["scores"], e["scores"]):
                unmade += s is None
                self.assertIn(s, (None, t))
            if h["pick"] > 0:
                self.assertIsNotNone(h["scores"][h["pick"] - 1])
        self.assertGreater(unmade, 0)

    def test_no_fake_holes_is_the_variation_score(self):
        _, holes, log = self.fill("--fake-holes", "0")
        for h in holes:
            self.assertNotIn("validation", h)
            # The best-scored continuation: no prior's variation is picked unvalidated.
            continuations = [i for i, kind in enumerate(h["kinds"]) if kind == "continuation"]
            self.assertEqual(h["pick"], 1 + max(continuations, key=lambda i: h["scores"][i]))
        self.assertNotIn("validation 1:", log)


class Oracle(TempDirTest):
    """`fill --oracle`: the ground truth's own curvature image, on a finer fill."""

    def test_the_oracle_fills_finer_unless_a_density_is_given(self):
        src = self.punched("fandisk.ply", 1000, 0.04)
        truth = os.path.join(SHARED_MESHES, "fandisk.ply")

        def fill(*options):
            out, report = self.path("out.ply"), self.path("report.json")
            r = run([TOOL, "fill", src, out, "--report", report, "--verbose", *options])
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(info(out)["holes"], 0)
            with open(report) as f:
                return json.load(f)["holes"][0]

        oracle = fill("--oracle", truth)
        at_two = fill("--oracle", truth, "--density", "2")
        inpainted = fill("--detail", "1")
        self.assertEqual(at_two["new_vertices"], inpainted["new_vertices"])
        self.assertGreater(oracle["new_vertices"], at_two["new_vertices"])
        for h in (oracle, at_two):
            self.assertGreater(h["curvature_spread"]["truth"], 0)
            self.assertGreater(h["curvature_spread"]["result"], 0)


class CurvatureImages(TempDirTest):
    def test_images_of_every_hole_and_a_montage(self):
        out = self.path("images")
        r = run([TOOL, "images", os.path.join(SOURCE, "meshes", "sample_holes.ply"), out, "--size", "256"])
        self.assertEqual(r.returncode, 0, r.stderr)
        for k in (1, 2, 3):
            for kind in ("curvature", "rgba", "mask"):
                self.assertEqual(png_size(os.path.join(out, f"hole_{k}_{kind}.png")), (256, 256))
            with open(os.path.join(out, f"hole_{k}.json")) as f:
                meta = json.load(f)
            self.assertEqual(meta["image_size"], 256)
            self.assertGreater(meta["rings"], 0)
        w, h = png_size(os.path.join(out, "montage.png"))
        self.assertGreater(h, 3 * 256)  # a row per hole

    def test_refused_mesh_writes_no_images(self):
        src = write_non_manifold_ply(self.path("nonmanifold.ply"))
        out = self.path("images")
        r = run([TOOL, "images", src, out])
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("more than two faces", r.stderr)
        self.assertFalse(os.path.exists(out))


class BadInput(TempDirTest):
    def assert_refused(self, src, expected_words):
        digest = sha256(src)
        out = self.path("out.ply")
        r = run([TOOL, "coarse", src, out])
        self.assertNotEqual(r.returncode, 0)
        lines = r.stderr.strip().splitlines()
        self.assertEqual(len(lines), 1, r.stderr)  # one clear line
        self.assertTrue(lines[0].startswith("curvature-inpaint: "), lines[0])
        for w in expected_words:
            self.assertIn(w, lines[0])
        self.assertEqual(sha256(src), digest)  # input untouched
        self.assertFalse(os.path.exists(out))  # nothing half-written
        self.assertEqual([n for n in os.listdir(self.tmp) if ".part" in n], [])

    def test_not_a_mesh(self):
        src = self.path("notes.ply")
        with open(src, "w") as f:
            f.write("these are my notes, not a mesh\n")
        self.assert_refused(src, ["not a readable mesh"])

    def test_malformed_obj(self):
        for name, text, words in (
                ("short_vertex", "v 0 0 0\nv 1 0\n", ["line 2", "three coordinates"]),
                ("missing_vertex", "v 0 0 0\nv 1 0 0\nf 1 2 3\n", ["line 3", "vertex \"3\" of 2"]),
                ("zero_index", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", ["vertex \"0\""]),
                ("two_corners", "v 0 0 0\nv 1 0 0\nf 1 2\n", ["fewer than three corners"]),
                ("not_a_number", "v 0 0 zero\n", ["\"zero\" is not a number"])):
            with self.subTest(name=name):
                src = self.path(name + ".obj")
                with open(src, "w") as f:
                    f.write(text)
                self.assert_refused(src, ["not a readable mesh"] + words)


    def test_truncated_file(self):
        src = self.path("truncated.ply")
        with open(os.path.join(SHARED_MESHES, "fandisk.ply"), "rb") as f:
            data = f.read()
        with open(src, "wb") as f:
            f.write(data[: len(data) // 2])
        self.assert_refused(src, ["not a readable mesh"])

    def test_empty_mesh(self):
        src = self.path("empty.ply")
        write_ascii_ply(src, [], [])
        self.assert_refused(src, ["empty"])

    def test_nan_coordinates(self):
        v, f = grid(4)
        v[7] = (math.nan, 0.5, 0.0)
        src = self.path("nan.ply")
        write_ascii_ply(src, v, f)
        self.assert_refused(src, ["non-finite"])

    def test_infinite_coordinates(self):
        v, f = grid(4)
        v[3] = (math.inf, 0.0, 0.0)
        src = self.path("inf.ply")
        write_ascii_ply(src, v, f)
        self.assert_refused(src, ["non-finite"])

    def test_vertex_index_out_of_range(self):
        v, f = grid(4)
        f[5] = (0, 1, 9999)
        src = self.path("oob.ply")
        write_ascii_ply(src, v, f)
        self.assert_refused(src, ["not a readable mesh", "face 5 names a vertex that does not exist"])

    def test_ply_as_exporters_write_it(self):
        # Binary big-endian, double coordinates, a quad, colours as floats, MeshLab's face
        # flags (selection), an element no reader knows: read, filled, colours kept.
        import struct
        src = self.path("big_endian.ply")
        with open(src, "wb") as f:
            f.write(b"ply\nformat binary_big_endian 1.0\ncomment from a scanner\n"
                    b"element vertex 5\nproperty double x\nproperty double y\nproperty double z\n"
                    b"property float red\nproperty float green\nproperty float blue\n"
                    b"element face 2\nproperty list uchar uint vertex_indices\nproperty int flags\n"
                    b"element camera 1\nproperty list ushort float view\n"
                    b"end_header\n")
            for p in ((0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0.5, 2, 0)):
                f.write(struct.pack(">3d3f", *p, 0.0, 1.0, 0.5))
            f.write(struct.pack(">B4Ii", 4, 0, 1, 2, 3, 0x20))
            f.write(struct.pack(">B3Ii", 3, 3, 2, 4, 0))
            f.write(struct.pack(">H2f", 2, 1.0, 2.0))
        before = info(src)
        self.assertEqual((before["vertices"], before["faces"], before["hole_edges"]), (5, 3, [5]))
        out = self.path("filled.ply")
        r = run([TOOL, "coarse", src, out, "--selected-only"])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(info(out)["holes"], 0)  # the hole borders the selected quad
        r = run([TOOL, "coarse", src, self.path("filled.off")])
        self.assertEqual(r.returncode, 0, r.stderr)

    def test_malformed_ply(self):
        head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n" \
               "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
        body = "0 0 0\n1 0 0\n0 1 0\n"
        for name, text, words in (
                ("polygon_past_the_end", head + body + "4 0 1 2 7\n", ["face 0 names a vertex"]),
                ("two_corners", head + body + "2 0 1\n", ["fewer than three corners"]),
                ("cut_short", head + body + "3 0 1\n", ["face 0 is cut short"]),
                ("word", head + "0 0 zero\n1 0 0\n0 1 0\n3 0 1 2\n", ["vertex 0 is cut short or not a number"]),
                ("no_count", "ply\nformat ascii 1.0\nelement vertex\nend_header\n", ["without a valid count"]),
                ("unknown_type", head.replace("float z", "quad z") + body, ["malformed PLY property"])):
            with self.subTest(name=name):
                src = self.path(name + ".ply")
                with open(src, "w") as f:
                    f.write(text)
                self.assert_refused(src, ["not a readable mesh"] + words)

    def test_unwelded_triangle_soup(self):
        # Each triangle with its own corners: every edge looks like a hole. Refused, not doubled.
        v, f = grid(6)
        soup_v, soup_f = [], []
        for t in f:
            soup_f.append((len(soup_v), len(soup_v) + 1, len(soup_v) + 2))
            soup_v += [v[i] for i in t]
        src = self.path("soup.ply")
        write_ascii_ply(src, soup_v, soup_f)
        self.assert_refused(src, ["not welded", "Merge Close Vertices"])

    def test_non_manifold_edge(self):
        src = write_non_manifold_ply(self.path("nonmanifold.ply"))
        self.assert_refused(src, ["more than two faces"])

    def test_files_that_broke_vcglibs_readers(self):
        # The inputs fuzzing found (fuzz/corpus/fuzz_mesh_file/regression_*; first byte: the
        # format): each is refused with one line or read, never a crash or a hang.
        corpus = os.path.join(SOURCE, "fuzz", "corpus", "fuzz_mesh_file")
        for name in sorted(n for n in os.listdir(corpus) if n.startswith("regression_")):
            with self.subTest(name=name):
                with open(os.path.join(corpus, name), "rb") as f:
                    data = f.read()
                src = self.path(name + "." + ("ply", "off", "obj", "stl")[data[0] % 4])
                with open(src, "wb") as f:
                    f.write(data[1:])
                r = run([TOOL, "info", src], timeout=60)
                self.assertIn(r.returncode, (0, 1), r.stderr)  # not killed by a signal
                if r.returncode:
                    self.assertRegex(r.stderr, r"^curvature-inpaint: .*not a readable mesh")

    def test_missing_file_and_unknown_format(self):
        r = run([TOOL, "coarse", self.path("absent.ply"), self.path("out.ply")])
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("cannot open", r.stderr)
        src = self.path("mesh.xyz")
        with open(src, "w") as f:
            f.write("0 0 0\n")
        r = run([TOOL, "coarse", src, self.path("out.ply")])
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("unsupported format", r.stderr)

    def test_usage_errors(self):
        # One line that says what is wrong, one that says where the help is; exit status 2.
        r = run([TOOL, "coarse", "only-one-file.ply"])
        self.assertEqual(r.returncode, 2)
        self.assertEqual(r.stderr.splitlines(),
                         ["curvature-inpaint: coarse: expected IN OUT, got 1 file",
                          "see 'curvature-inpaint coarse --help'"])
        r = run([TOOL, "coarse", "a.ply", "b.ply", "--max-hole-edges", "-3"])
        self.assertEqual(r.returncode, 2)
        self.assertEqual(len(r.stderr.splitlines()), 2)
        self.assertIn("--max-hole-edges needs an integer >= 0", r.stderr)
        r = run([TOOL, "punch", "a.ply", "b.ply", "--radius-frac", "0.1"])
        self.assertEqual(r.returncode, 2)
        self.assertIn("--seed-vertex is required", r.stderr)
        r = run([TOOL, "fly", "a.ply"])
        self.assertEqual(r.returncode, 2)
        self.assertEqual(r.stderr.splitlines(), ['curvature-inpaint: unknown command "fly"',
                                                 "see 'curvature-inpaint --help'"])


if __name__ == "__main__":
    unittest.main()


class Batch(TempDirTest):
    """`batch`: a collection filled, recorded, resumed, sharded and summarized."""

    def scans(self, count=3, broken=True):
        folder = self.collection(count)
        if broken:
            with open(os.path.join(folder, "broken.ply"), "w") as f:
                f.write("ply\nformat ascii 1.0\nelement vertex 3\nend_header\n1 2\n")
        return folder

    def results(self, outdir, name="results.jsonl"):
        with open(os.path.join(outdir, name)) as f:
            return [json.loads(line) for line in f if line.strip()]

    def test_a_folder_is_filled_recorded_and_resumed(self):
        folder, out = self.scans(), self.path("out")
        r = run([TOOL, "batch", folder, out, "--fake-holes", "0", "--size", "128"])
        self.assertEqual(r.returncode, 1, r.stderr)  # one scan failed
        lines = self.results(out)
        self.assertEqual(sorted(os.path.basename(l["input"]) for l in lines),
                         ["broken.ply", "scan1.ply", "scan2.ply", "scan3.ply"])
        for l in lines:
            if l["input"].endswith("broken.ply"):
                self.assertEqual(l["status"], "failed")
                self.assertIn("the mesh is empty", l["error"])  # its vertex line cut short
                self.assertFalse(os.path.exists(os.path.join(out, "broken.ply")))
                continue
            self.assertEqual(l["status"], "ok", l)
            self.assertEqual(l["sha256"], sha256(l["input"]))
            self.assertEqual((l["holes_filled"], l["holes_left"]), (1, 0))
            self.assertEqual(l["options"], ["--fake-holes", "0", "--size", "128"])
            result = os.path.join(out, l["output"])
            self.assertEqual(info(result)["holes"], 0)
            before = read_binary_ply_xyz(l["input"])
            self.assertEqual(read_binary_ply_xyz(result)[:len(before)], before)
        self.assertIn("batch: 4 scans: 3 filled, 0 done before, 1 failed", r.stderr)
        stamps = {n: os.stat(os.path.join(out, n)).st_mtime_ns for n in os.listdir(out) if n.endswith(".ply")}
        # Again: the three are done (same bytes, same options), the broken one is tried again.
        r = run([TOOL, "batch", folder, out, "--fake-holes", "0", "--size", "128"])
        self.assertEqual(r.returncode, 1, r.stderr)
        self.assertIn("batch: 4 scans: 0 filled, 3 done before, 1 failed", r.stderr)
        self.assertEqual(len(self.results(out)), 5)
        self.assertEqual(stamps, {n: os.stat(os.path.join(out, n)).st_mtime_ns for n in stamps})
        # Other options are another job: every scan is filled again.
        r = run([TOOL, "batch", folder, out, "--fake-holes", "0", "--size", "64"])
        self.assertIn("batch: 4 scans: 3 filled, 0 done before, 1 failed", r.stderr)
        # The summary: counts, the failure's reason, a CSV row per scan.
        r = run([TOOL, "batch", "--summary", out])
        self.assertEqual(r.returncode, 1, r.stderr)
        self.assertIn("| 4 | 3 | 1 | 3 | 0 |", r.stdout)
        self.assertIn("| broken.ply |", r.stdout)
        with open(os.path.join(out, "summary.csv")) as f:
            rows = f.read().splitlines()
        self.assertEqual(rows[0], "input,status,holes_filled,holes_left,seconds,error")
        self.assertEqual(len(rows), 5)

    def test_shards_cover_the_manifest_once(self):
        folder, out = self.scans(count=4, broken=False), self.path("out")
        for k in (1, 2):
            r = run([TOOL, "batch", folder, out, "--shard", f"{k}/2", "--fake-holes", "0", "--size", "64"])
            self.assertEqual(r.returncode, 0, r.stderr)
        one, two = self.results(out, "results.1-of-2.jsonl"), self.results(out, "results.2-of-2.jsonl")
        names = [os.path.basename(l["input"]) for l in one + two]
        self.assertEqual(sorted(names), ["scan1.ply", "scan2.ply", "scan3.ply", "scan4.ply"])
        self.assertEqual([os.path.basename(l["input"]) for l in one], ["scan1.ply", "scan3.ply"])
        # A Slurm array's task 2 of 2 (ids 0-1) is shard 2/2: its scans are done already.
        env = dict(os.environ, SLURM_ARRAY_TASK_ID="1", SLURM_ARRAY_TASK_COUNT="2",
                   SLURM_ARRAY_TASK_MIN="0")
        import subprocess
        r = subprocess.run([TOOL, "batch", folder, out, "--fake-holes", "0", "--size", "64"],
                           capture_output=True, text=True, env=env, timeout=300)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("batch: 2 scans: 0 filled, 2 done before, 0 failed", r.stderr)
        r = run([TOOL, "batch", "--summary", out])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("| 4 | 4 | 0 | 4 | 0 |", r.stdout)
        r = run([TOOL, "batch", folder, out, "--shard", "3/2"])
        self.assertEqual(r.returncode, 2)
        self.assertIn("--shard needs K/N", r.stderr)

    def test_a_killed_batch_loses_no_finished_scan(self):
        import signal
        import subprocess
        import time
        folder, out = self.scans(count=4, broken=False), self.path("out")
        p = subprocess.Popen([TOOL, "batch", folder, out], stderr=subprocess.DEVNULL)
        results = os.path.join(out, "results.jsonl")
        deadline = time.time() + 300
        while time.time() < deadline and p.poll() is None:
            if os.path.exists(results) and os.path.getsize(results) > 0:
                break
            time.sleep(0.01)
        p.send_signal(signal.SIGKILL)
        p.wait()
        finished = [l["output"] for l in self.results(out)]
        self.assertGreaterEqual(len(finished), 1)
        self.assertLess(len(finished), 4, "killed half-way")
        # Whatever is in the folder is a whole mesh (a scan cut short was being written in
        # .partial/); the finished ones are not done again.
        for name in os.listdir(out):
            self.assertTrue(name.endswith(".ply") or name in ("results.jsonl", ".partial"), name)
            if name.endswith(".ply"):
                self.assertEqual(info(os.path.join(out, name))["holes"], 0, name)
        stamps = {n: os.stat(os.path.join(out, n)).st_mtime_ns for n in finished}
        r = run([TOOL, "batch", folder, out])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn(f"{len(finished)} done before", r.stderr)
        self.assertEqual(sorted(l["output"] for l in self.results(out)),
                         ["scan1.ply", "scan2.ply", "scan3.ply", "scan4.ply"])
        self.assertEqual(stamps, {n: os.stat(os.path.join(out, n)).st_mtime_ns for n in stamps})

    def test_a_text_manifest_carries_options_per_scan(self):
        folder, out = self.scans(count=2, broken=False), self.path("out")
        manifest = os.path.join(folder, "manifest.txt")
        with open(manifest, "w") as f:
            f.write("# scan and its own options\nscan1.ply --fake-holes 0\nscan2.ply --mode sideways\n")
        r = run([TOOL, "batch", manifest, out, "--size", "64"])
        self.assertEqual(r.returncode, 1, r.stderr)
        lines = {os.path.basename(l["input"]): l for l in self.results(out)}
        self.assertEqual(lines["scan1.ply"]["options"], ["--size", "64", "--fake-holes", "0"])
        self.assertEqual(lines["scan1.ply"]["status"], "ok")
        self.assertEqual(lines["scan2.ply"]["status"], "failed")
        self.assertIn("--mode is direct or paper", lines["scan2.ply"]["error"])
        r = run([TOOL, "batch", manifest, out, "--report", "r.json"])
        self.assertEqual(r.returncode, 2)
        self.assertIn("--report is not a batch option", r.stderr)
