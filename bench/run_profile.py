#!/usr/bin/env python3
"""Where the time of a fill goes: `perf` samples of one whole `fill` on a scan with many small
holes, each sample counted once, under the first stage or candidate named on its call stack
(innermost first), as a table of shares.

    python3 bench/run_profile.py [--holes N] [--threads T] [--no-build] [--tool PATH]

The scan: Igea subdivided once (760k faces) with N holes (default 40) punched at random
vertices, radii 2-6 mean edge lengths (bench_tools punch-many, seeded). One thread by default,
so that a share is a share of one core's time. --tool profiles another build of the tool (a
copy made before a change, say) on the same scan.
"""
import collections
import os
import re
import shutil
import subprocess
import tempfile

from run_coarse_bench import BIN, SHARED, build, check_args, sh

# (row, names on the stack that put a sample there, outermost first): the first row whose
# names all appear on a sample's stack, each called from within the one before it, takes it,
# so the test cuts' rows come before the hole's own.
ROWS = [
    ("validation: a test cut's coarse fill and curvature image", ["ValidateHole", "ComputeCurvatureImages"]),
    ("validation: a test cut's priors (mirror image, creases, tri-Laplacian fill)", ["ValidateHole", "MakePatchWork"]),
    ("validation: a test cut's continuation (one solve, every amplitude)", ["ValidateHole", "InpaintEmbeddedAmplitudes"]),
    ("validation: continuation candidates' fills (deformations)", ["ValidateHole", "ContinuationCandidate::FillFakeHole"]),
    ("validation: mirrored curvature candidate's fills (deformations)", ["ValidateHole", "SymmetryCandidate::FillFakeHole"]),
    ("validation: the fills' errors against the surface cut out", ["ValidateHole", "FakeHoleScorer::Error"]),
    ("validation: cutting the test cuts", ["ValidateHole", "CutFakeHoles"]),
    ("validation: the rest (detail ratios of tied candidates, the other candidates)", ["ValidateHole"]),
    ("variations: the continuations of the hole", ["ContinuationCandidate::Variations"]),
    ("variations: the tri-Laplacian fill's curvature image", ["TriLaplacianCandidate::Variations"]),
    ("variations: the mirror image's curvature images", ["SymmetryCandidate::Variations"]),
    ("variations: the mirror image's curvature images", ["SymmetrySurfaceCandidate::Variations"]),
    ("variations: the creases' curvature image", ["CreaseCandidate::Variations"]),
    ("the hole's priors (mirror image, creases, tri-Laplacian fill)", ["MakePatchWork"]),
    ("scoring the variations", ["PickVariation"]),
    ("the deformation of the hole", ["DeformPatch"]),
    ("symmetry planes (once per scan)", ["DetectSymmetry"]),
    ("coarse fill (stage 1)", ["CoarseFill"]),
    ("the holes' curvature images", ["ComputeCurvatureImages"]),
    ("reading the scan", ["LoadMesh"]),
    ("writing the scan", ["SaveMesh"]),
]


def frames(sample):
    """The function names of one `perf script` sample, innermost first, without namespaces
    and arguments."""
    names = []
    for line in sample.strip().split("\n")[1:]:
        parts = line.strip().split(" ", 1)
        if len(parts) < 2:
            continue
        name = re.sub(r"\+0x[0-9a-f]+ .*", "", parts[1])
        name = re.sub(r"\(.*", "", name)
        names.append(name.replace("curvature_inpaint::", "").replace("(anonymous namespace)::", ""))
    return names


def within(names, needed):
    """Whether every name of `needed` is on the stack `names` (innermost first), each called
    from within the one before it."""
    at = len(names)
    for name in needed:
        if name not in names[:at]:
            return False
        at = names[:at].index(name)
    return True


def shares(script):
    counts, total = collections.Counter(), 0
    for sample in script.split("\n\n"):
        names = frames(sample)
        if not names:
            continue
        total += 1
        row = next((r for r, needed in ROWS if within(names, needed)), "other")
        counts[row] += 1
    return counts, total


def main():
    options, _ = check_args(__doc__, flags=("--no-build",), valued=("--holes", "--threads", "--tool"))
    if not options.get("--no-build"):
        build()
    if not shutil.which("perf"):
        raise SystemExit("perf is needed (Debian: linux-perf)")
    tool = options.get("--tool", os.path.join(BIN, "curvature-inpaint"))
    tools = os.path.join(BIN, "bench_tools")
    tmp = tempfile.mkdtemp(prefix="profile-")
    try:
        scan = os.path.join(tmp, "igea_x4.ply")
        sh([tools, "subdivide", os.path.join(SHARED, "meshes", "igea_190k.ply"), scan])
        holed = os.path.join(tmp, "holed.ply")
        sh([tools, "punch-many", scan, holed, options.get("--holes", "40"), "2", "6"])
        data = os.path.join(tmp, "perf.data")
        sh(["perf", "record", "-q", "-F", "150", "--call-graph", "dwarf,16384", "-o", data, tool,
            "fill", holed, os.path.join(tmp, "out.ply"), "--threads", options.get("--threads", "1")])
        script = subprocess.run(["perf", "script", "-i", data], capture_output=True, text=True).stdout
        counts, total = shares(script)
        print(f"{total} samples at 150 Hz ({total / 150:.1f} s of CPU)\n")
        print("| part | share of the samples |\n|---|---|")
        for row in dict.fromkeys(r for r, _ in ROWS + [("other", [])]):
            if counts[row]:
                print(f"| {row} | {100 * counts[row] / total:.1f} % |")
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
