#!/usr/bin/env python3
"""The choice's development benchmark: the 300 corpus holes of bench/corpus_holes.tsv (meshes
no parameter was ever tuned on before), each filled by the whole method, the plain coarse
fill, CGAL's filler and MeshLab's Close Holes, and by each candidate the validation weighed.

    python3 bench/run_corpus_bench.py [--part tuning|check] [--only MESH[,MESH...]]
                                      [--jobs N] [--plot] [--from-json FILE] [--no-build]
                                      [--save FILE] [--weigh SHARE]... [-- FILL ARGS...]

Per hole: hole-region RMS and Hausdorff distance as ratios to CGAL's (below 1: closer to the
ground truth than CGAL's smooth cap), the detail ratio, watertight and manifold, every input
vertex kept. What the tables show is the distribution, since one bad hole is what a user
remembers: median, 90th percentile and worst ratio, and the count of holes worse than 1.25x
CGAL's RMS (1.5x its Hausdorff distance). Each candidate of the hole's validation is also run
alone (`fill --pick KIND --fake-holes 0`, the continuation as `--detail A --fake-holes 0`,
which is what the fill makes when it picks it), so that a rule of choice can be weighed
against the truth from the saved results without filling again (build-bench/corpus_PART.json).
--plot writes docs/corpus_rms_ratio_sorted.png: the sorted RMS ratios of fill, coarse and
Close Holes. Tune on the tuning part, report the check part. --jobs runs holes side by side
(default 2; each fill with --threads 1: the choice is the same for any thread count).
--no-build runs the tools as they are in build-bench/ (to measure an earlier build against a
newer); --save names the results file instead of build-bench/corpus_PART.json. --weigh adds
a row for the rule of ValidationParams::min_win_share at another value, from the saved
candidates, without filling again: the validated choice replaces the smooth fill only where it
is closer on the fake holes that hold SHARE of the smooth fill's error (0: the validated
choice alone), and a hole without fake holes keeps the smooth fill.
"""
import concurrent.futures
import json
import os
import shutil
import statistics
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_coarse_bench import (BIN, CLOSE_HOLES, ROOT, SHARED, build, check_args, hole_edges,  # noqa: E402
                              meshlab_prefix, sh)
from run_holdout_bench import measure, ratio, run_gnuplot  # noqa: E402

TOOL = os.path.join(BIN, "curvature-inpaint")
TABLE = os.path.join(ROOT, "bench", "corpus_holes.tsv")
DOCS = os.path.join(ROOT, "docs")
WORSE_RMS = 1.25  # the bound: a fill this much farther than CGAL's is visibly worse
WORSE_HAUSDORFF = 1.5


def holes(part):
    """(mesh, seed, radius, centre vertex) of each row of one part of the table."""
    with open(TABLE) as f:
        for line in f:
            if line.startswith("#") or line.startswith("mesh\t") or not line.strip():
                continue
            mesh, seed, radius, vertex, row_part = line.rstrip("\n").split("\t")
            if row_part == part:
                yield mesh, int(seed), radius, int(vertex)


def candidate_args(name):
    """The fill arguments that make what the validated fill makes when it picks `name`."""
    if name.startswith("detail "):
        return ["--detail", name.split(" ", 1)[1], "--fake-holes", "0"]
    return ["--pick", name, "--fake-holes", "0"]


def timed(args):
    start = time.perf_counter()
    sh(args)
    return time.perf_counter() - start


def run_hole(hole, server, script, fill_args):
    """One row: every method and every validated candidate on one corpus hole."""
    mesh, seed, radius, vertex = hole
    tmp = tempfile.mkdtemp(prefix="corpus-hole-")
    try:
        gt = os.path.join(SHARED, "corpus", mesh)
        inp, out = os.path.join(tmp, "in.ply"), os.path.join(tmp, "out.ply")
        sh([TOOL, "punch", gt, inp, "--seed-vertex", str(vertex), "--radius-frac", radius])
        row = {"name": f"{os.path.splitext(mesh)[0]}_{seed}", "radius": radius,
               "edges": hole_edges(sh([TOOL, "info", inp]).stdout)[0]}
        report = os.path.join(tmp, "report.json")
        s = timed([TOOL, "fill", inp, out, "--threads", "1", "--report", report, *fill_args])
        row["fill"] = measure(gt, inp, out, s)
        row["fill_report"] = json.load(open(report))["holes"][0]
        s = timed([TOOL, "coarse", inp, out])
        row["coarse"] = measure(gt, inp, out, s)
        s = timed([os.path.join(BIN, "cgal_fill"), inp, out])
        row["cgal"] = measure(gt, inp, out, s)
        s = timed(["xvfb-run", "-a", server, "-i", inp, "-o", out, "-s", script])
        row["close"] = measure(gt, inp, out, s)
        row["candidates"] = {}
        # The smooth fill too where nothing was validated: what a hole with no evidence keeps.
        names = [c["name"] for c in (row["fill_report"].get("validation") or {})
                 .get("candidates", [])] or ["coarse"]
        for name in names:
            s = timed([TOOL, "fill", inp, out, "--threads", "1", *candidate_args(name),
                       *fill_args])
            row["candidates"][name] = measure(gt, inp, out, s)
        return row
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def percentile(values, q):
    """The q-quantile (0-1) by the nearest rank: a value that some hole really has."""
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, max(0, int(round(q * len(ordered) + 0.5)) - 1))]


def distribution_line(label, rows, key):
    rms = [ratio(r[key]["rms"], r["cgal"]["rms"]) for r in rows]
    haus = [ratio(r[key]["hausdorff"], r["cgal"]["hausdorff"]) for r in rows]
    differ = [x for x, r in zip(rms, rows) if r["cgal"]["rms"] > 1e-9 or r[key]["rms"] > 1e-9]
    details = [r[key]["detail"] for r in rows if r[key]["detail"] is not None]
    return (f"| {label} | {sum(x < 1 for x in differ)} of {len(differ)} | "
            f"{statistics.median(rms):.3f} | {percentile(rms, 0.9):.2f} | {max(rms):.2f} | "
            f"{sum(x > WORSE_RMS for x in rms)} | {max(haus):.2f} | "
            f"{sum(x > WORSE_HAUSDORFF for x in haus)} | "
            f"{statistics.mean(details) if details else float('nan'):.2f} | "
            f"{all(r[key]['watertight'] for r in rows)} | {all(r[key]['kept'] for r in rows)} |")


def weighed_choice(r, share):
    """The candidate a hole gets when its validated choice must be clearly better than the
    smooth fill (validation/hole_choice.h, ClearlyBetter), from its saved fake-hole errors."""
    v = r["fill_report"].get("validation") or {}
    if "choice" not in v:
        return "coarse"
    names = [c["name"] for c in v["candidates"]]
    choice = v.get("not_clearly_better", v["choice"])
    if choice == "coarse" or "coarse" not in names:
        return choice
    c, s = names.index(choice), names.index("coarse")
    telling = [e for e in v["per_fake_hole"] if max(e[c], e[s]) > 1e-3]
    total = sum(e[s] for e in telling)
    won = sum(e[s] for e in telling if e[c] < e[s])
    return choice if total > 0 and won >= share * total else "coarse"


def weigh(rows, share):
    """`rows` with the fill replaced by the candidate the rule at `share` chooses."""
    out = []
    for r in rows:
        w = dict(r)
        w["fill"] = r["candidates"][weighed_choice(r, share)]
        out.append(w)
    return out


def choice_words(r):
    v = r["fill_report"].get("validation") or {}
    if "choice" in v:
        return f"{v['choice']} on {v['fake_holes']} fake holes"
    return v.get("note", "not validated")[:60]


def print_report(rows, part, weighed=()):
    print(f"\nCorpus holes, {part} part ({len(rows)} holes): RMS and Hausdorff ratios to CGAL's "
          "on the same hole (below 1: closer to the ground truth)\n")
    print(f"| method | RMS < CGAL | median | 90th pct | worst | > {WORSE_RMS}x | worst Hausdorff | "
          f"Hausdorff > {WORSE_HAUSDORFF}x | mean detail | watertight | kept |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for key, label in (("fill", "fill"), ("coarse", "coarse"), ("close", "Close Holes"),
                       ("cgal", "CGAL")):
        print(distribution_line(label, rows, key))
    for share in weighed:
        print(distribution_line(f"fill, rule {share:g}", weigh(rows, share), "fill"))
    worst = sorted(rows, key=lambda r: -ratio(r["fill"]["rms"], r["cgal"]["rms"]))[:12]
    print("\nThe fill's worst holes: RMS ratio to CGAL's, the coarse fill's, what was chosen\n")
    print("| hole | edges | fill | coarse | chosen |")
    print("|---|---|---|---|---|")
    for r in worst:
        print(f"| {r['name']} | {r['edges']} | {ratio(r['fill']['rms'], r['cgal']['rms']):.2f} | "
              f"{ratio(r['coarse']['rms'], r['cgal']['rms']):.2f} | {choice_words(r)} |")


def plot_sorted(path, rows, part):
    data = path + ".dat"
    keys = ("fill", "coarse", "close")
    columns = [sorted(ratio(r[k]["rms"], r["cgal"]["rms"]) for r in rows) for k in keys]
    with open(data, "w") as f:
        for i in range(len(rows)):
            f.write(f"{i + 1} " + " ".join(f"{c[i]:.4f}" for c in columns) + "\n")
    script = "\n".join([
        "set terminal pngcairo size 900,560 font 'DejaVu Sans,11'", "set termoption noenhanced",
        f"set output '{path}'",
        f"set title 'Corpus holes ({part} part): hole-region RMS relative to CGAL, sorted'",
        "set xlabel 'holes, sorted by ratio'", "set ylabel 'RMS / CGAL RMS (log)'",
        "set logscale y", "set yrange [0.05:20]", "set grid", "set key top left",
        f"set arrow from graph 0, first {WORSE_RMS} to graph 1, first {WORSE_RMS} nohead dt 3",
        f"plot '{data}' using 1:2 with lines lw 2 title 'curvature-inpaint fill', "
        "'' using 1:3 with lines lw 2 title 'coarse fill', "
        "'' using 1:4 with lines lw 2 title 'MeshLab Close Holes', "
        "1 with lines dt 2 lw 2 title 'CGAL'"])
    run_gnuplot(script)
    os.remove(data)


def main():
    options, fill_args = check_args(
        __doc__, flags=("--plot", "--no-build"),
        valued=("--part", "--only", "--jobs", "--from-json", "--save"), repeated=("--weigh",))
    weighed = [float(w) for w in options["--weigh"]]
    part = options.get("--part", "tuning")
    if part not in ("tuning", "check"):
        print(f"run_corpus_bench.py: --part is tuning or check, not {part}", file=sys.stderr)
        sys.exit(2)
    saved = options.get("--save", os.path.join(ROOT, "build-bench", f"corpus_{part}.json"))
    if "--from-json" in options:
        with open(options["--from-json"]) as f:
            rows = json.load(f)
    else:
        if "--no-build" not in options:
            build()
        only = options["--only"].split(",") if "--only" in options else None
        todo = [h for h in holes(part) if not only or os.path.splitext(h[0])[0] in only]
        if not todo:
            print(f"run_corpus_bench.py: no hole of the {part} part in those meshes",
                  file=sys.stderr)
            sys.exit(2)
        tmp = tempfile.mkdtemp(prefix="corpus-bench-")
        try:
            server = os.path.join(meshlab_prefix(os.path.join(tmp, "prefix")), "meshlabserver")
            script = os.path.join(tmp, "close_holes.mlx")
            with open(script, "w") as f:
                f.write(CLOSE_HOLES)
            jobs = int(options.get("--jobs", "2"))
            with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
                futures = [pool.submit(run_hole, h, server, script, fill_args) for h in todo]
                rows = []
                for future in futures:  # in the table's order, whatever finishes first
                    rows.append(future.result())
                    print(f"{rows[-1]['name']} done ({len(rows)} of {len(todo)})",
                          file=sys.stderr, flush=True)
                    with open(saved + ".part", "w") as f:
                        json.dump(rows, f, indent=1)
            os.replace(saved + ".part", saved)
        finally:
            shutil.rmtree(tmp, ignore_errors=True)
    print_report(rows, part, weighed)
    if "--plot" in options:
        plot_sorted(os.path.join(DOCS, "corpus_rms_ratio_sorted.png"), rows, part)


if __name__ == "__main__":
    main()
