#!/usr/bin/env python3
"""The whole method against its own coarse fill on the public cases (embedded backend, both
deformation modes). Distances as in run_coarse_bench.py; detail ratio: the spread (standard
deviation) of the APSS mean curvature over the fill's vertices divided by the ground truth's
over the same region (1: as much detail as the truth; smooth fills sit below).

    python3 bench/run_fill_bench.py
"""
import os
import re
import shutil
import tempfile
import time

from run_coarse_bench import BIN, SHARED, build, case_input, cases, dist, metrics, sh, table


def main():
    build()
    tool = os.path.join(BIN, "curvature-inpaint")
    tmp = tempfile.mkdtemp(prefix="fill-bench-")
    rows = []
    try:
        for name, gt, seed, frac, given in cases():
            inp = case_input(tmp, name, gt, seed, frac, given)
            for label, args in (("coarse fill", ["coarse"]), ("fill, direct", ["fill", "--mode", "direct"]),
                                ("fill, paper", ["fill", "--mode", "paper"])):
                out = os.path.join(tmp, f"{name}_{label[-6:].strip()}.ply")
                start = time.perf_counter()
                r = sh([tool, args[0], inp, out] + args[1:])
                seconds = time.perf_counter() - start
                steps = re.findall(r"(\d+) deformation steps", r.stderr)
                m = metrics(gt, inp, out)
                rows.append(f"| {name} | {label} | {dist(m)} | {m['detail_ratio']:.2f} | "
                            f"{m['normal_deviation_deg']:.1f} | {m['holes_left']} | "
                            f"{seconds:.2f} | {'+'.join(steps) or '-'} |")
        table("The whole method (embedded backend) against its coarse fill",
              ["case", "method", "ground truth → fill", "fill → ground truth", "detail ratio", "normal deviation (°)",
               "holes left", "process s", "deformation steps"], rows)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
