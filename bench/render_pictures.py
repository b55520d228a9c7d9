#!/usr/bin/env python3
"""Pictures of holes a person would look at: ground truth | CGAL | coarse fill | fill, each in
the mean-curvature colours of the curvature images (blue convex, green flat, red concave, one
scale per picture), shaded, seen along the ground truth's mean normal at the hole.

    python3 bench/render_pictures.py      # writes docs/holes_<name>.png

Holes: the Igea nose and the armadillo belly of ../shared/bench/cases.tsv; of bench/holes.tsv,
an armadillo hole of the test half (the posed body's mirror image holds near the hole, not in
it), a koala hole of the test half (its mirror image holds the missing shape) and the tuning
half's larger fandisk hole (its CAD creases).
"""
import json
import os
import sys
import tempfile
import shutil

from run_coarse_bench import BIN, BUILD, ROOT, SHARED, build, check_args, sh
from run_holdout_bench import punch

sys.path.insert(0, os.path.join(ROOT, "tests"))
os.environ.setdefault("CI_BUILD_DIR", BUILD)
os.environ.setdefault("CI_SOURCE_DIR", ROOT)
from support import read_binary_ply_xyz  # noqa: E402

TOOL = os.path.join(BIN, "curvature-inpaint")
BENCH = os.path.join(BIN, "bench_tools")
# (name, mesh, seed vertex or None for the holes.tsv row's draw, radius fraction, row seed)
CASES = [("igea_nose", "igea_190k.ply", 21537, "0.05", None),
         ("armadillo_belly", "armadillo.ply", 35206, "0.04", None),
         ("armadillo_304", "armadillo.ply", None, "0.05", 304),
         ("koala_504", "koala.ply", None, "0.05", 504),
         ("fandisk_703", "fandisk.ply", None, "0.05", 703)]


def main():
    check_args(__doc__)
    build()
    tmp = tempfile.mkdtemp(prefix="pictures-")
    try:
        for name, mesh, vertex, frac, row in CASES:
            gt = os.path.join(SHARED, "meshes", mesh)
            if vertex is None:
                _, inp, vertex = punch(tmp, mesh, row, frac)
            else:
                inp = os.path.join(tmp, name + ".ply")
                sh([TOOL, "punch", gt, inp, "--seed-vertex", str(vertex), "--radius-frac", frac])
            xyz = read_binary_ply_xyz(gt)
            lo = [min(p[k] for p in xyz) for k in range(3)]
            hi = [max(p[k] for p in xyz) for k in range(3)]
            diag = sum((b - a) ** 2 for a, b in zip(lo, hi)) ** 0.5
            centre = [str(c) for c in xyz[vertex]]
            radius = str(2.2 * float(frac) * diag)
            results = {"cgal": os.path.join(tmp, "cgal.ply"), "coarse": os.path.join(tmp, "coarse.ply"),
                       "fill": os.path.join(tmp, "fill.ply")}
            sh([os.path.join(BIN, "cgal_fill"), inp, results["cgal"]])
            sh([TOOL, "coarse", inp, results["coarse"]])
            sh([TOOL, "fill", inp, results["fill"]])
            first = json.loads(sh([BENCH, "render", gt, os.path.join(tmp, "gt.png"), *centre, radius,
                                   "0", "0", "0", "-1"]).stdout)
            view = [str(v) for v in first["view"]]
            panels = [os.path.join(tmp, "gt.png")]
            for key in ("cgal", "coarse", "fill"):
                png = os.path.join(tmp, key + ".png")
                sh([BENCH, "render", results[key], png, *centre, radius, *view, str(first["curvature_scale"])])
                panels.append(png)
            out = os.path.join(ROOT, "docs", f"holes_{name}.png")
            sh([BENCH, "side-by-side", out, *panels])
            print(f"wrote {os.path.relpath(out, ROOT)}", file=sys.stderr)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
