#!/usr/bin/env python3
"""Writes bench/corpus_holes.tsv, the development set of the choice among fills: 300 holes
punched into the closed meshes of ../shared/corpus (never in a benchmark's test part), by the
rule written at the head of the table (RULE below). Deterministic: the same corpus, the same
table.

    python3 bench/make_corpus_holes.py      # about a minute
"""
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_coarse_bench import ROOT, SHARED, sh  # noqa: E402

CORPUS = os.path.join(SHARED, "corpus")
TABLE = os.path.join(ROOT, "bench", "corpus_holes.tsv")
TOOL = os.path.join(ROOT, "build", "bin", "curvature-inpaint")
HOLES_PER_MESH = 12
DRAWS = 50

RULE = """\
# The development set of the choice among fills: holes punched into the public meshes of
# ../shared/corpus (MANIFEST.md: origin and licence), none of which is in ../shared/meshes or
# in Debian's libcgal-demo data. Made by bench/make_corpus_holes.py; the ground truth of a hole
# is the corpus mesh before it was punched.
#
# Meshes: the corpus's closed, two-manifold meshes (`curvature-inpaint info`: no hole, no
# non-manifold edge), in file-name order. The open ones (their own borders would be filled too
# and measured as part of the hole) and aj_beast (edges shared by three faces) are left out.
#
# Holes: per mesh, 12 holes k = 1..12 of radius 0.02 + 0.04 (k - 1) / 11 of the bounding-box
# diagonal (every face with a vertex that close to the centre is removed), with seed
# 20000 + 100 i + k (i: the mesh's place among all corpus files, from 0). The centre is the
# first draw of Python's random.Random(seed).randrange(vertex count) whose hole is one loop in
# an otherwise closed mesh (a ball that cuts a thin part in two is drawn again from the same
# generator; a hole with no such draw in 50 is left out).
#
# Parts (fixed before any run, never two parts of one mesh): the meshes in the order below
# alternate tuning, check, tuning, ... Every parameter and rule of the choice is chosen on the
# tuning part; results are reported on the check part (and the test half of holes.tsv).
"""


def info(path):
    out = sh([TOOL, "info", path]).stdout
    return dict(line.split(" ", 1) for line in out.splitlines() if " " in line)


def closed_meshes():
    """(place among all corpus files, file name) of each closed two-manifold corpus mesh."""
    names = sorted(n for n in os.listdir(CORPUS) if n.endswith(".ply"))
    for i, name in enumerate(names):
        facts = info(os.path.join(CORPUS, name))
        if facts["holes"] == "0" and facts["non_manifold_edges"] == "0":
            yield i, name


def centre(path, seed, radius, tmp):
    """The hole's centre vertex by the rule, or None."""
    vertices = int(info(path)["vertices"])
    rng = random.Random(seed)
    for _ in range(DRAWS):
        v = rng.randrange(vertices)
        sh([TOOL, "punch", path, tmp, "--seed-vertex", str(v), "--radius-frac", radius])
        facts = info(tmp)
        if facts["holes"] == "1" and facts["non_manifold_edges"] == "0":
            return v
    return None


def main():
    tmp = os.path.join(ROOT, "build", "corpus-hole.ply")
    rows = []
    for place, (i, name) in enumerate(closed_meshes()):
        part = "tuning" if place % 2 == 0 else "check"
        for k in range(1, HOLES_PER_MESH + 1):
            seed = 20000 + 100 * i + k
            radius = f"{0.02 + 0.04 * (k - 1) / (HOLES_PER_MESH - 1):.4f}"
            v = centre(os.path.join(CORPUS, name), seed, radius, tmp)
            if v is not None:
                rows.append(f"{name}\t{seed}\t{radius}\t{v}\t{part}")
        print(f"{name}: {part}", file=sys.stderr, flush=True)
    os.remove(tmp)
    with open(TABLE, "w") as f:
        f.write(RULE + "mesh\tseed\tradius_frac\tcentre_vertex\tpart\n" + "\n".join(rows) + "\n")
    print(f"{TABLE}: {len(rows)} holes", file=sys.stderr)


if __name__ == "__main__":
    main()
