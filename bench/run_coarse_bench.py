#!/usr/bin/env python3
"""Benchmark of the coarse fill (stages 0-2) against CGAL's triangulate_refine_and_fair_hole and
MeshLab's Close Holes on the public cases of ../shared/bench/cases.tsv.

    python3 bench/run_coarse_bench.py            # prints Markdown tables

Distances are measured on the hole only, in percent of the ground truth's bounding-box
diagonal: ground-truth region -> result, and filled region -> ground truth (max / RMS), from
20,000 area-weighted samples each (bench_tools metrics). Times: the filling calls alone (ours:
the per-hole times the tool reports; CGAL: the calls to triangulate_refine_and_fair_hole),
median of 3 runs, and the whole process (read, fill, write).
"""
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SHARED = os.path.join(ROOT, "..", "shared")
BUILD = os.path.join(ROOT, "build-bench")
BIN = os.path.join(BUILD, "bin")
RUNS = 3


def check_args(usage, flags=(), valued=(), repeated=()):
    """The benchmark's command line, checked before any work: its usage (the module's
    docstring) on -h or --help, status 2 on an option it does not know, rather than a run of
    many minutes with the option ignored. `flags` take no value, `valued` one, `repeated` one
    each time they are given. Returns the options given (a flag: True; a valued option: its
    last value; a repeated one: the list of its values, empty when not given) and the
    arguments after "--", for the caller to pass on."""
    argv = sys.argv[1:]
    rest = argv[argv.index("--") + 1:] if "--" in argv else []
    argv = argv[:argv.index("--")] if "--" in argv else argv
    given = {name: [] for name in repeated}
    i = 0
    while i < len(argv):
        a = argv[i]
        if a in ("-h", "--help"):
            print(usage.strip())
            sys.exit(0)
        if (a in valued or a in repeated) and i + 1 < len(argv):
            if a in repeated:
                given[a].append(argv[i + 1])
            else:
                given[a] = argv[i + 1]
            i += 2
            continue
        if a not in flags:
            why = ("needs a value" if a in valued or a in repeated
                   else "is not an option of this benchmark")
            print(f"{os.path.basename(sys.argv[0])}: {a} {why} (--help lists them)",
                  file=sys.stderr)
            sys.exit(2)
        given[a] = True
        i += 1
    return given, rest


def sh(args, **kw):
    r = subprocess.run(args, capture_output=True, text=True, **kw)
    if r.returncode != 0:
        raise RuntimeError(f"{' '.join(args)} failed:\n{r.stdout}\n{r.stderr}")
    return r


def hole_edges(info):
    """The boundary edges of each hole, from `curvature-inpaint info`'s `hole_edges` line."""
    return [int(e) for e in re.search(r"^hole_edges(.*)$", info, re.M).group(1).split()]


def build():
    sh(["bash", os.path.join(ROOT, "scripts", "setup-debian.sh")])
    if subprocess.run(["dpkg-query", "-W", "libcgal-dev"], capture_output=True).returncode != 0:
        prefix = [] if os.geteuid() == 0 else ["sudo"]
        sh(prefix + ["apt-get", "install", "-y", "-qq", "--no-install-recommends", "libcgal-dev"],
           env=dict(os.environ, DEBIAN_FRONTEND="noninteractive"))
    sh(["cmake", "-S", ROOT, "-B", BUILD, "-DCMAKE_BUILD_TYPE=Release", "-DCURVATURE_INPAINT_BENCH=ON"])
    sh(["cmake", "--build", BUILD, "-j2", "--target", "curvature-inpaint", "bench_tools", "cgal_fill",
        "filter_curvature_inpaint"])


def meshlab_prefix(root):
    sys.path.insert(0, os.path.join(ROOT, "tests"))
    os.environ.setdefault("CI_BUILD_DIR", BUILD)
    os.environ.setdefault("CI_SOURCE_DIR", ROOT)
    import support  # noqa: E402
    return support.make_meshlab_prefix(root)


CLOSE_HOLES = """<!DOCTYPE FilterScript>
<FilterScript>
 <filter name="Close Holes">
  <Param type="RichInt" name="MaxHoleSize" value="100000"/>
  <Param type="RichBool" name="Selected" value="false"/>
  <Param type="RichBool" name="NewFaceSelected" value="true"/>
  <Param type="RichBool" name="SelfIntersection" value="true"/>
 </filter>
</FilterScript>
"""


def timed(args):
    start = time.perf_counter()
    r = sh(args)
    return r, time.perf_counter() - start


def ours(inp, out, extra=()):
    fills, walls = [], []
    for _ in range(RUNS):
        r, wall = timed([os.path.join(BIN, "curvature-inpaint"), "coarse", inp, out, *extra])
        fills.append(sum(float(m) for m in re.findall(r", ([0-9.]+) ms", r.stderr)))
        walls.append(wall)
    methods = sorted(set(re.findall(r"edges(?: \(pinched\))?, ([a-z-]+),", r.stderr)))
    return statistics.median(fills), statistics.median(walls), ",".join(methods)


def cgal(inp, out):
    fills, walls = [], []
    for _ in range(RUNS):
        r, wall = timed([os.path.join(BIN, "cgal_fill"), inp, out])
        fills.append(json.loads(r.stdout)["fill_ms"])
        walls.append(wall)
    return statistics.median(fills), statistics.median(walls)


def meshlab(server, script, inp, out):
    walls = []
    for _ in range(RUNS):
        _, wall = timed(["xvfb-run", "-a", server, "-i", inp, "-o", out, "-s", script])
        walls.append(wall)
    return statistics.median(walls)


def metrics(gt, inp, result):
    return json.loads(sh([os.path.join(BIN, "bench_tools"), "metrics", gt, inp, result]).stdout)


def cases():
    with open(os.path.join(SHARED, "bench", "cases.tsv")) as f:
        for line in f:
            if line.startswith("#") or line.startswith("name\t") or not line.strip():
                continue
            name, gt, seed, frac, given = line.rstrip("\n").split("\t")
            yield name, os.path.join(SHARED, gt), seed, frac, given


def case_input(tmp, name, gt, seed, frac, given):
    """The case's mesh with its hole: the given open mesh, or the ground truth punched."""
    inp = os.path.join(tmp, name + ".ply")
    if given != "-":
        shutil.copy(os.path.join(SHARED, given), inp)
    else:
        sh([os.path.join(BIN, "curvature-inpaint"), "punch", gt, inp, "--seed-vertex", seed,
            "--radius-frac", frac])
    return inp


def dist(m):
    a, b = m["gt_to_result"], m["result_to_gt"]
    return f"{a['max']:.2f} / {a['rms']:.3f} | {b['max']:.2f} / {b['rms']:.3f}"


def table(title, header, rows):
    print(f"\n{title}\n")
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    print("\n".join(rows))


def main():
    check_args(__doc__)
    build()
    tmp = tempfile.mkdtemp(prefix="coarse-bench-")
    try:
        server = os.path.join(meshlab_prefix(os.path.join(tmp, "prefix")), "meshlabserver")
        script = os.path.join(tmp, "close_holes.mlx")
        with open(script, "w") as f:
            f.write(CLOSE_HOLES)
        quality, speed, triang = [], [], []
        for name, gt, seed, frac, given in cases():
            inp = case_input(tmp, name, gt, seed, frac, given)
            edges = [str(e) for e in hole_edges(sh([os.path.join(BIN, "curvature-inpaint"), "info", inp]).stdout)]
            o, c, m = (os.path.join(tmp, f"{name}_{k}.ply") for k in ("ours", "cgal", "meshlab"))
            o_fill, o_wall, o_method = ours(inp, o)
            c_fill, c_wall = cgal(inp, c)
            m_wall = meshlab(server, script, inp, m)
            mo, mc, mm = metrics(gt, inp, o), metrics(gt, inp, c), metrics(gt, inp, m)
            quality.append(f"| {name} | {'+'.join(edges)} | ours | {dist(mo)} | {mo['normal_deviation_deg']:.1f} | {mo['holes_left']} |")
            quality.append(f"| | | CGAL | {dist(mc)} | {mc['normal_deviation_deg']:.1f} | {mc['holes_left']} |")
            quality.append(f"| | | Close Holes | {dist(mm)} | {mm['normal_deviation_deg']:.1f} | {mm['holes_left']} |")
            speed.append(f"| {name} | {o_fill:.1f} ({o_method}) | {c_fill:.1f} | {o_wall:.2f} | {c_wall:.2f} | {m_wall:.2f} |")
            # The optimal triangulation against vcglib's ears on the same holes.
            e = os.path.join(tmp, f"{name}_ears.ply")
            e_fill, _, _ = ours(inp, e, ["--liepa-max-edges", "3"])
            me = metrics(gt, inp, e)
            triang.append(f"| {name} | {dist(mo)} | {o_fill:.1f} | {dist(me)} | {e_fill:.1f} |")

        # The same hole in a mesh 17 times larger (Igea beside Igea subdivided twice): the time
        # to fill it must not grow with the rest of the mesh.
        igea = os.path.join(SHARED, "meshes", "igea_190k.ply")
        mid, big = os.path.join(tmp, "igea_760k.ply"), os.path.join(tmp, "igea_3m.ply")
        sh([os.path.join(BIN, "bench_tools"), "subdivide", igea, mid])
        sh([os.path.join(BIN, "bench_tools"), "subdivide", mid, big])
        small = os.path.join(tmp, "scale_small.ply")
        sh([os.path.join(BIN, "curvature-inpaint"), "punch", igea, small, "--seed-vertex", "21537", "--radius-frac", "0.05"])
        large = os.path.join(tmp, "scale_large.ply")
        sh([os.path.join(BIN, "bench_tools"), "append", small, big, large])
        scale = []
        for label, inp in (("Igea with the nose hole", small), ("the same beside Igea subdivided twice", large)):
            info = sh([os.path.join(BIN, "curvature-inpaint"), "info", inp]).stdout
            faces = int(re.search(r"faces (\d+)", info).group(1))
            edges = [str(e) for e in hole_edges(info)]
            o_fill, o_wall, _ = ours(inp, os.path.join(tmp, "scale_ours.ply"))
            c_fill, c_wall = cgal(inp, os.path.join(tmp, "scale_cgal.ply"))
            m_wall = meshlab(server, script, inp, os.path.join(tmp, "scale_meshlab.ply"))
            scale.append(f"| {label} | {faces:,} | {'+'.join(edges)} | {o_fill:.1f} | {c_fill:.1f} | {o_wall:.2f} | {c_wall:.2f} | {m_wall:.2f} |")

        table("Quality: distance on the hole, % of the bounding-box diagonal, max / RMS",
              ["case", "hole edges", "filler", "ground truth → fill", "fill → ground truth",
               "normal deviation (°)", "holes left"], quality)
        table("Speed: median of 3 runs",
              ["case", "ours: fill ms (triangulation)", "CGAL: fill ms", "ours: process s",
               "CGAL: process s", "Close Holes (meshlabserver): process s"], speed)
        table("Triangulation: Liepa's dynamic programme against vcglib's ears (both refined and faired)",
              ["case", "Liepa DP: gt → fill / fill → gt", "ms", "vcglib ears: gt → fill / fill → gt", "ms"],
              triang)
        table("Scale: the same hole in a mesh 17 times larger",
              ["mesh", "faces", "hole edges", "ours: fill ms", "CGAL: fill ms", "ours: process s",
               "CGAL: process s", "Close Holes: process s"], scale)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
