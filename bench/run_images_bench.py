#!/usr/bin/env python3
"""Time of stages 3-7 (patch, APSS curvature, parameterization, 1024^2 image) for one hole, on
Igea (190k faces) and on the same hole beside Igea subdivided twice (3.2M faces in all).

    python3 bench/run_images_bench.py     # prints a Markdown table

Per-hole times are those `curvature-inpaint images` reports, median of 3 runs; the one pass
over the mesh that all holes share (vertex-face incidence) is reported on its own.
"""
import os
import re
import shutil
import statistics
import tempfile
import time

from run_coarse_bench import BIN, SHARED, build, check_args, sh, table

RUNS = 3


def images(inp, out):
    per_hole, process = [], []
    for _ in range(RUNS):
        shutil.rmtree(out, ignore_errors=True)
        start = time.perf_counter()
        r = sh([os.path.join(BIN, "curvature-inpaint"), "images", inp, out, "--size", "1024"])
        process.append(time.perf_counter() - start)
        m = re.search(r"image 1: patch of (\d+) vertices.*, (\d+) ms", r.stderr)
        per_hole.append(int(m.group(2)))
    return int(m.group(1)), statistics.median(per_hole), statistics.median(process)


def main():
    check_args(__doc__)
    build()
    tmp = tempfile.mkdtemp(prefix="images-bench-")
    try:
        tool = os.path.join(BIN, "curvature-inpaint")
        bench = os.path.join(BIN, "bench_tools")
        igea = os.path.join(SHARED, "meshes", "igea_190k.ply")
        small = os.path.join(tmp, "igea_nose.ply")
        sh([tool, "punch", igea, small, "--seed-vertex", "21537", "--radius-frac", "0.05"])
        mid, big, large = (os.path.join(tmp, n) for n in ("mid.ply", "big.ply", "large.ply"))
        sh([bench, "subdivide", igea, mid])
        sh([bench, "subdivide", mid, big])
        sh([bench, "append", small, big, large])
        rows = []
        for label, inp in (("Igea with the nose hole", small), ("the same beside Igea subdivided twice", large)):
            faces = int(re.search(r"faces (\d+)", sh([tool, "info", inp]).stdout).group(1))
            vertices, ms, process = images(inp, os.path.join(tmp, "out"))
            rows.append(f"| {label} | {faces:,} | {vertices} | {ms:.0f} | {process:.2f} |")
        table("Stages 3-7 for one hole at 1024 x 1024",
              ["mesh", "faces", "patch vertices", "stages 3-7 for the hole: ms", "whole process: s"], rows)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
