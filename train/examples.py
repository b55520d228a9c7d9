#!/usr/bin/env python3
"""Ten validation holes side by side: input (the hole grey), truth, continuation, learned.

Reads the pairs and the learned curvature train_unet.py saved for the validation meshes; the
ten are spread evenly over the holes sorted by how much the network changed the continuation's
error, the worst and the best among them. Colours are the product's colour map.

    /usr/bin/python3 train/examples.py [--out docs/learned_examples.png]
"""
import argparse
import glob
import os

import numpy as np
from PIL import Image, ImageDraw

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
KNOTS = np.array([[0, 0, 255], [0, 255, 255], [0, 255, 0], [255, 255, 0], [255, 0, 0]], float)


def colour(t):
    """vcg_ext::CurvatureColormap::Color8 of every value."""
    s = np.clip(t, 0, 1) * 4
    i = np.minimum(s.astype(int), 3)
    f = (s - i)[..., None]
    return np.rint(KNOTS[i] + f * (KNOTS[i + 1] - KNOTS[i])).astype(np.uint8)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--pairs", default=os.path.join(ROOT, "build", "learned-pairs"))
    ap.add_argument("--work", default=os.path.join(ROOT, "build", "learned-training"))
    ap.add_argument("--out", default=os.path.join(ROOT, "docs", "learned_examples.png"))
    a = ap.parse_args()
    files = sorted(glob.glob(os.path.join(a.pairs, "validation", "*.f32")))
    val = np.stack([np.fromfile(f, dtype=np.float32).reshape(-1, 128, 128)[:4] for f in files])
    learned = np.load(os.path.join(a.work, "validation_learned.npy"))
    hole = val[:, 1] > 0.5
    err = lambda e: np.array([np.abs(x - t)[h].mean() for x, t, h in zip(e, val[:, 3], hole)])
    change = err(learned) / np.maximum(err(val[:, 2]), 1e-9)
    order = np.argsort(change)
    picks = order[np.linspace(0, len(order) - 1, 10).round().astype(int)]
    cell, pad, top = 128, 4, 18
    sheet = Image.new("RGB", (4 * (cell + pad) + pad + 150, top + 10 * (cell + pad)), (40, 40, 46))
    draw = ImageDraw.Draw(sheet)
    for c, name in enumerate(["input", "truth", "continuation", "learned"]):
        draw.text((pad + c * (cell + pad) + 4, 3), name, fill=(230, 230, 230))
    for r, k in enumerate(picks):
        shown = colour(val[k, 0])
        shown[hole[k]] = 128
        # As the product pastes it: the network's curvature on the hole, the known pixels kept.
        pasted = np.where(hole[k], learned[k], val[k, 0])
        panels = [shown, colour(val[k, 3]), colour(val[k, 2]), colour(pasted)]
        for c, p in enumerate(panels):
            sheet.paste(Image.fromarray(p), (pad + c * (cell + pad), top + r * (cell + pad)))
        label = "%s\nerror %.2fx the\ncontinuation's" % (os.path.basename(files[k])[:-4], change[k])
        draw.text((pad + 4 * (cell + pad) + 4, top + r * (cell + pad) + 4), label,
                  fill=(230, 230, 230))
    sheet.save(a.out)
    print("wrote", a.out)


if __name__ == "__main__":
    main()
