#!/usr/bin/env python3
"""Makes the learned inpainter's training pairs with the product's own stages.

For each hole: a round hole is punched into a corpus mesh (`curvature-inpaint punch`; centre
and radius drawn from the hole's seed, radius 2-6 % of the diagonal), filled with the ground
truth as the oracle (`fill --oracle`, which writes the hole's curvature image with the coarse
fill inside, its mask and the ground truth's image on the same UV), continued by the embedded
inpainter at detail 0 (`inpaint`), and read into float32 planes of 128² by `bench_tools
learned-planes`: the network's three input planes, then the truth's curvature (and for the
validation meshes the tri-Laplacian fill's, rendered the same way). Deterministic for a seed.

Meshes (../shared/corpus/MANIFEST.md): only those whose licence lets weights ship ("ship"),
only from the corpus benchmark's tuning part (bench/corpus_holes.tsv), so its check part stays
unseen; split by mesh into training and validation.

    /usr/bin/python3 train/make_pairs.py [--out build/learned-pairs] [--holes 110]
"""
import argparse
import json
import os
import random
import shutil
import subprocess
import sys
import tempfile
from multiprocessing import Pool

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CORPUS = os.path.join(ROOT, "..", "shared", "corpus")
TRAINING = ["od_boat.ply", "od_cat-low-resolution.ply", "od_fish.ply", "od_hammer.ply",
            "od_skull.ply", "od_wingnut.ply"]
VALIDATION = ["od_human_man.ply", "od_plane.ply"]
SEED = 57000


def vertex_count(path):
    with open(path, "rb") as f:
        for line in f:
            if line.startswith(b"element vertex"):
                return int(line.split()[2])
            if line.startswith(b"end_header"):
                break
    raise ValueError(path + ": no vertex count")


def run(args):
    r = subprocess.run(args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if r.returncode != 0:
        raise RuntimeError(" ".join(args) + ": " + r.stderr.strip())


def one_hole(job):
    tool, bench_tools, mesh, seed, out_dir, validation = job
    target = os.path.join(out_dir, "%s_%d.f32" % (os.path.splitext(mesh)[0], seed))
    if os.path.exists(target):
        return target
    gt = os.path.join(CORPUS, mesh)
    rng = random.Random(seed)
    vertex = rng.randrange(vertex_count(gt))
    radius = 0.02 + 0.04 * rng.random()
    with tempfile.TemporaryDirectory() as tmp:
        holed = os.path.join(tmp, "holed.ply")
        images = os.path.join(tmp, "images")
        run([tool, "punch", gt, holed, "--seed-vertex", str(vertex), "--radius-frac", str(radius)])
        report = os.path.join(tmp, "report.json")
        run([tool, "fill", holed, os.path.join(tmp, "out.ply"), "--oracle", gt, "--images", images,
             "--fake-holes", "0", "--threads", "1", "--variations", "1", "--report", report])
        holes = json.load(open(report))["holes"]
        # The largest hole the punch made (a ball across a thin part makes two) with a truth.
        holes = [h for h in holes if "truth" in h.get("curvature_spread", {}) and
                 os.path.exists(os.path.join(images, "hole_%d_coarse.png" % h["hole"]))]
        if not holes:
            return None
        hole = max(holes, key=lambda h: h["boundary_edges"])["hole"]
        stem = os.path.join(images, "hole_%d_" % hole)
        run([tool, "inpaint", stem + "coarse.png", stem + "mask.png", os.path.join(tmp, "cont"),
             "--detail", "0", "-n", "1"])
        extra = [stem + "variation_1.png"]
        if validation:
            plain = os.path.join(tmp, "plain")
            run([tool, "fill", holed, os.path.join(tmp, "plain.ply"), "--images", plain,
                 "--fake-holes", "0", "--threads", "1", "--variations", "1"])
            row = json.load(open(os.path.join(plain, "montage.json")))["rows"]
            row = [r for r in row if r["hole"] == hole][0]
            captions = [t["caption"] for t in row["tiles"]]
            kind = [c for c in captions if c.endswith(" tri-laplacian")]
            if not kind:
                return None
            extra.append(os.path.join(plain, "hole_%d_variation_%s.png" % (hole, kind[0].split()[0])))
        run([bench_tools, "learned-planes", stem + "coarse.png", stem + "mask.png",
             os.path.join(tmp, "cont", "variation_1.png"), target + ".part"] + extra)
        os.replace(target + ".part", target)
    return target


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", default=os.path.join(ROOT, "build", "learned-pairs"))
    ap.add_argument("--holes", type=int, default=110, help="holes per training mesh")
    ap.add_argument("--validation-holes", type=int, default=40)
    ap.add_argument("--tool", default=os.path.join(ROOT, "build-bench", "bin", "curvature-inpaint"))
    ap.add_argument("--bench-tools", default=os.path.join(ROOT, "build-bench", "bin", "bench_tools"))
    ap.add_argument("--jobs", type=int, default=os.cpu_count())
    a = ap.parse_args()
    jobs = []
    for part, meshes, count in (("train", TRAINING, a.holes),
                                ("validation", VALIDATION, a.validation_holes)):
        os.makedirs(os.path.join(a.out, part), exist_ok=True)
        for mesh in meshes:
            index = sorted(os.listdir(CORPUS)).index(mesh)
            for k in range(count):
                jobs.append((a.tool, a.bench_tools, mesh, SEED + 1000 * index + k,
                             os.path.join(a.out, part), part == "validation"))
    made = 0
    with Pool(a.jobs) as pool:
        for i, target in enumerate(pool.imap_unordered(one_hole, jobs)):
            made += target is not None
            if (i + 1) % 50 == 0:
                print("%d of %d holes, %d pairs" % (i + 1, len(jobs), made), flush=True)
    print("%d pairs in %s" % (made, a.out))


if __name__ == "__main__":
    sys.exit(main())
