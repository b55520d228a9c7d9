#!/usr/bin/env python3
"""Fingerprints of everything the tool writes, to show that a change (a refactor, a speed-up that
must not change a choice) leaves every output byte for byte as it was.

For the sample mesh, each hole of bench/holes.tsv (both halves) and the development holes, it runs
`fill` with the default settings (its mesh, report, images and montage), `fill --pick` with every
kind the help lists (and `coarse` and the exemplar), `coarse` and `preview`, and records a SHA-256
of each output file and of the log. Reports are hashed without their times ("seconds"); the log
without its times and its progress lines, whose order depends on the threads.

usage: bench/fingerprint_outputs.py record FILE [--holes sample,table,dev] [--keep DIR]
       bench/fingerprint_outputs.py compare FILE [--holes ...] [--keep DIR]
  record   writes the fingerprints into FILE (JSON), after each mesh: a record cut short keeps
           the meshes it did
  compare  fingerprints the current build the same way, on the meshes FILE holds, and lists
           every output that differs from FILE; exit status 1 if any does
--holes picks the sets (default: all three). --keep DIR keeps the outputs to look at.
Run it before a change (record) and after it (compare), on the same machine, with the tool
built by scripts/build.sh (CURVATURE_INPAINT_TOOL names another)."""
import argparse
import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import run_holdout_bench  # noqa: E402
from run_holdout_bench import ROOT, holes, punch  # noqa: E402

# The product's own build (CURVATURE_INPAINT_TOOL: another), which also punches the holes.
TOOL = os.environ.get("CURVATURE_INPAINT_TOOL", os.path.join(ROOT, "build", "bin", "curvature-inpaint"))
run_holdout_bench.TOOL = TOOL
SAMPLE = os.path.join(ROOT, "meshes", "sample_holes.ply")
PROGRESS = re.compile(r"^[A-Z][\w ]*: [\w ]*hole \d+ of \d+$")
TIME = re.compile(r"\b\d+(?:\.\d+)? ?(?:ms|s)\b")


def pick_kinds():
    """The kinds `fill --pick` accepts, as its help lists them."""
    text = subprocess.run([TOOL, "fill", "--help"], capture_output=True, text=True, check=True).stdout
    listed = re.search(r"a kind \(([^)]*)\)", " ".join(text.split()))
    if not listed:
        raise SystemExit("fingerprint: `fill --help` no longer lists the kinds --pick takes")
    return [k.strip() for k in listed.group(1).split(",")]


def cases():
    """(name, command, extra arguments, whether it writes images) for one mesh."""
    found = [("fill", "fill", [], True), ("fill --pick coarse", "fill", ["--pick", "coarse"], False)]
    for kind in pick_kinds():
        extra = ["--exemplar"] if kind == "exemplar" else []
        found.append((f"fill --pick {kind}", "fill", extra + ["--pick", kind], False))
    found += [("coarse", "coarse", [], False), ("preview", "preview", [], False)]
    return found


def without_times(value):
    if isinstance(value, dict):
        return {k: without_times(v) for k, v in value.items() if k != "seconds"}
    if isinstance(value, list):
        return [without_times(v) for v in value]
    return value


def digest(path):
    with open(path, "rb") as f:
        data = f.read()
    if path.endswith(".json"):
        data = json.dumps(without_times(json.loads(data)), sort_keys=True).encode()
    return hashlib.sha256(data).hexdigest()


def fingerprint(mesh, work):
    """{case: {output: sha256}} for one holed mesh; `work` is an empty folder."""
    result = {}
    for index, (name, command, extra, images) in enumerate(cases()):
        out = os.path.join(work, f"case{index}")
        os.makedirs(out)
        if command == "preview":
            args = [TOOL, "preview", mesh, os.path.join(out, "images")]
        else:
            args = [TOOL, command, mesh, os.path.join(out, "out.ply"), *extra]
            if command == "fill":
                args += ["--report", os.path.join(out, "report.json")]
            if images:
                args += ["--images", os.path.join(out, "images")]
        r = subprocess.run(args, capture_output=True, text=True)
        log = "\n".join(line for line in (r.stdout + r.stderr).splitlines() if not PROGRESS.match(line))
        log = log.replace(out, "OUT").replace(mesh, "IN")  # the folders differ from run to run
        log = TIME.sub("TIME", log)
        files = {"exit status": str(r.returncode), "log": hashlib.sha256(log.encode()).hexdigest()}
        for folder, _, names in os.walk(out):
            for n in names:
                path = os.path.join(folder, n)
                files[os.path.relpath(path, out)] = digest(path)
        result[name] = dict(sorted(files.items()))
    return result


def meshes(sets, tmp, wanted=None):
    """(label, holed mesh) of each set asked for (of those in `wanted`, when given)."""
    if "sample" in sets and (wanted is None or "sample" in wanted):
        yield "sample", SAMPLE
    for split in ("tuning", "test", "dev"):
        if ("table" if split != "dev" else "dev") not in sets:
            continue
        for mesh, seed, frac in holes(split):
            label = f"{split} {mesh} {seed}"
            if wanted is None or label in wanted:
                _, holed, _ = punch(tmp, mesh, seed, frac)
                yield label, holed


def save(prints, path):
    with open(path + ".part", "w") as f:
        json.dump(prints, f, indent=1, sort_keys=True)
    os.replace(path + ".part", path)


def run(sets, keep, wanted=None, record=None):
    """{label: fingerprint} of each mesh of `sets` (of those in `wanted`, when given); with
    `record`, saved there after each mesh, so that a record cut short keeps what it did."""
    tmp = tempfile.mkdtemp(prefix="fingerprint-")
    try:
        prints = {}
        for label, mesh in meshes(sets, tmp, wanted):
            work = os.path.join(keep or tmp, re.sub(r"\W+", "_", label))
            shutil.rmtree(work, ignore_errors=True)
            os.makedirs(work)
            prints[label] = fingerprint(mesh, work)
            if record:
                save(prints, record)
            print(f"fingerprint: {label}", file=sys.stderr, flush=True)
        return prints
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def differences(before, after):
    for label in sorted(set(before) | set(after)):
        a, b = before.get(label), after.get(label)
        if a is None or b is None:
            yield f"{label}: only {'after' if a is None else 'before'}"
            continue
        for case in sorted(set(a) | set(b)):
            fa, fb = a.get(case, {}), b.get(case, {})
            for name in sorted(set(fa) | set(fb)):
                if fa.get(name) != fb.get(name):
                    yield f"{label}: {case}: {name} differs"


def main():
    parser = argparse.ArgumentParser(usage=__doc__)
    parser.add_argument("action", choices=["record", "compare"])
    parser.add_argument("file")
    parser.add_argument("--holes", default="sample,table,dev")
    parser.add_argument("--keep")
    args = parser.parse_args()
    sets = set(args.holes.split(","))
    if not sets <= {"sample", "table", "dev"}:
        parser.error("--holes takes sample, table and dev")
    if not os.access(TOOL, os.X_OK):
        raise SystemExit(f"fingerprint: no tool at {TOOL}; run scripts/build.sh")
    if args.action == "compare":
        with open(args.file) as f:
            before = json.load(f)
    if args.action == "record":
        prints = run(sets, args.keep, record=args.file)
        print(f"fingerprint: {sum(len(c) for p in prints.values() for c in p.values())} outputs "
              f"of {len(prints)} meshes recorded in {args.file}")
        return 0
    prints = run(sets, args.keep, wanted=set(before))
    before = {k: v for k, v in before.items() if k in prints}
    found = list(differences(before, prints))
    for line in found:
        print(line)
    print(f"fingerprint: {len(found)} of {sum(len(c) for p in prints.values() for c in p.values())} "
          f"outputs of {len(prints)} meshes differ from {args.file}")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
