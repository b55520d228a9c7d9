#!/usr/bin/env python3
"""Load held: a scan of over a million faces with 200 holes, filled by the whole method
(embedded backend) and by its coarse fill, against CGAL's filler and MeshLab's Close Holes on
the same input; wall time and peak memory (GNU time's maximum resident set size) of each
whole process, and the same for merely loading the mesh (`curvature-inpaint info`).

    python3 bench/run_scale_bench.py [--ten]

(--ten: only the second table, the 760k-face scan with ten holes.)

The mesh: Igea and the armadillo, each subdivided once (1-to-4), side by side (1.1M faces);
200 holes punched at random vertices with radii of 2-12 mean edge lengths, kept apart.
"""
import os
import re
import shutil
import subprocess
import tempfile

from run_coarse_bench import (BIN, CLOSE_HOLES, SHARED, build, check_args, hole_edges,
                              meshlab_prefix, sh, table)


def measured(args):
    """(seconds, peak MB, stderr) of a whole process under GNU time."""
    r = subprocess.run(["/usr/bin/time", "-f", "TIME %e %M", *args], capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError(f"{' '.join(args)} failed:\n{r.stderr[-3000:]}")
    seconds, kb = re.findall(r"TIME ([0-9.]+) (\d+)", r.stderr)[-1]
    return float(seconds), int(kb) / 1024, r.stderr


def hundreds(tmp, tool, tools, parts, out):
    """The first table: both meshes side by side with 200 holes."""
    closed = os.path.join(tmp, "closed.ply")
    sh([tools, "append", parts[0], parts[1], closed])
    holed = os.path.join(tmp, "holed.ply")
    sh([tools, "punch-many", closed, holed, "200", "2", "12"])
    info = sh([tool, "info", holed]).stdout
    faces = int(re.search(r"faces (\d+)", info).group(1))
    edges = hole_edges(info)
    server = os.path.join(meshlab_prefix(os.path.join(tmp, "prefix")), "meshlabserver")
    script = os.path.join(tmp, "close_holes.mlx")
    with open(script, "w") as f:
        f.write(CLOSE_HOLES)
    rows = []
    load_s, load_mb, _ = measured([tool, "info", holed])
    rows.append(f"| loading only (`curvature-inpaint info`) | {load_s:.1f} | {load_mb:.0f} | - |")
    for label, args in (
            ("ours: whole method (`fill`, embedded, 2 threads)", [tool, "fill", holed, out]),
            ("ours: whole method, 1 thread", [tool, "fill", holed, out, "--threads", "1"]),
            ("ours: whole method without fake holes (`--fake-holes 0`)",
             [tool, "fill", holed, out, "--fake-holes", "0"]),
            ("ours: coarse fill (`coarse`)", [tool, "coarse", holed, out]),
            ("CGAL: triangulate_refine_and_fair_hole, every hole", [os.path.join(BIN, "cgal_fill"), holed, out]),
            ("MeshLab: Close Holes (meshlabserver)", ["xvfb-run", "-a", server, "-i", holed, "-o", out, "-s", script])):
        seconds, mb, err = measured(args)
        left = len(hole_edges(sh([tool, "info", out]).stdout))
        rows.append(f"| {label} | {seconds:.1f} | {mb:.0f} | {left} |")
    table(f"{faces:,} faces, {len(edges)} holes of {min(edges)}-{max(edges)} boundary edges",
          ["process", "seconds", "peak memory (MB)", "holes left"], rows)


def main():
    options, _ = check_args(__doc__, flags=("--ten",))
    build()
    if not os.path.exists("/usr/bin/time"):
        prefix = [] if os.geteuid() == 0 else ["sudo"]
        sh(prefix + ["apt-get", "install", "-y", "-qq", "--no-install-recommends", "time"],
           env=dict(os.environ, DEBIAN_FRONTEND="noninteractive"))
    tools = os.path.join(BIN, "bench_tools")
    tool = os.path.join(BIN, "curvature-inpaint")
    tmp = tempfile.mkdtemp(prefix="scale-bench-")
    try:
        parts = []
        for name in ("igea_190k", "armadillo"):
            out = os.path.join(tmp, name + "_x4.ply")
            sh([tools, "subdivide", os.path.join(SHARED, "meshes", name + ".ply"), out])
            parts.append(out)
        out = os.path.join(tmp, "out.ply")
        if "--ten" not in options:
            hundreds(tmp, tool, tools, parts, out)

        # A scan of 760k faces with ten holes: the fake-hole validation's cost against CGAL's
        # whole process (median of 3 runs each).
        ten = os.path.join(tmp, "ten.ply")
        sh([tools, "punch-many", parts[0], ten, "10", "4", "12"])
        info = sh([tool, "info", ten]).stdout
        faces = int(re.search(r"faces (\d+)", info).group(1))
        edges = hole_edges(info)
        rows = []
        for label, args in (
                ("ours: whole method (`fill`, 4 fake holes per hole)", [tool, "fill", ten, out]),
                ("ours: whole method without the priors (`--no-symmetry --no-creases --no-tri-laplacian`)",
                 [tool, "fill", ten, out, "--no-symmetry", "--no-creases", "--no-tri-laplacian"]),
                ("ours: whole method without fake holes", [tool, "fill", ten, out, "--fake-holes", "0"]),
                ("ours: the variations alone (`preview`, what the dialog shows before applying)",
                 [tool, "preview", ten, os.path.join(tmp, "preview")]),
                ("CGAL: triangulate_refine_and_fair_hole", [os.path.join(BIN, "cgal_fill"), ten, out])):
            runs = sorted(measured(args)[:2] for _ in range(3))
            rows.append(f"| {label} | {runs[1][0]:.2f} | {runs[1][1]:.0f} |")
        table(f"{faces:,} faces, {len(edges)} holes of {min(edges)}-{max(edges)} boundary edges "
              "(Igea subdivided once)", ["process", "seconds", "peak memory (MB)"], rows)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
