#!/usr/bin/env python3
"""Trains the learned inpainter's network on the pairs of train/make_pairs.py (CPU, seeded).

The network answers how far the truth's curvature lies from the embedded continuation; the
loss is on the hole's cells only: the absolute error, plus the absolute error of the
curvature's differences between neighbouring cells (so ridges stay sharp). Every batch takes
each pair in one of the square's eight symmetries. Runs for at most --minutes, saving a
checkpoint as it goes; run it again to go on (the same seed, the same weights, piece by piece).
At the end it exports the weights (train/unet.py's format) and reports the validation errors.

    /usr/bin/python3 train/train_unet.py [--pairs build/learned-pairs] [--minutes 25]
"""
import argparse
import glob
import json
import os
import random
import sys
import time

import numpy as np
import torch

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import unet  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def load(folder):
    files = sorted(glob.glob(os.path.join(folder, "*.f32")))
    planes = [np.fromfile(f, dtype=np.float32).reshape(-1, 128, 128) for f in files]
    return files, np.stack([p[:4] for p in planes]), planes


def symmetry(batch, k):
    """The k-th of the square's eight symmetries of (N, C, H, W)."""
    if k & 4:
        batch = batch.flip(3)
    return torch.rot90(batch, k & 3, (2, 3))


def predict(model, planes):
    """The network's curvature: the continuation plus its correction."""
    return planes[:, 2:3] + model(planes[:, :3])


def loss_of(model, batch, gradient_weight):
    truth = batch[:, 3:4]
    hole = (batch[:, 1:2] > 0.5).float()
    pred = predict(model, batch)
    err = (pred - truth) * hole
    value = err.abs().sum() / hole.sum().clamp(min=1)
    both_x = hole[..., :, 1:] * hole[..., :, :-1]
    both_y = hole[..., 1:, :] * hole[..., :-1, :]
    dx = ((pred[..., :, 1:] - pred[..., :, :-1]) - (truth[..., :, 1:] - truth[..., :, :-1])) * both_x
    dy = ((pred[..., 1:, :] - pred[..., :-1, :]) - (truth[..., 1:, :] - truth[..., :-1, :])) * both_y
    grad = (dx.abs().sum() + dy.abs().sum()) / (both_x.sum() + both_y.sum()).clamp(min=1)
    return value + gradient_weight * grad


def hole_errors(estimate, truth, hole):
    """Per pair: the mean absolute curvature error over the hole's cells."""
    m = hole > 0.5
    return np.array([np.abs(e - t)[h].mean() for e, t, h in zip(estimate, truth, m)])


def write_card(a, summary, path):
    """The text beside the weights: how they were made and how well they predict."""
    import subprocess
    import make_pairs
    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "HEAD"], capture_output=True,
                            text=True).stdout.strip()
    lines = [
        "The learned inpainter's weights (curvature_unet.bin), read by inpaint/curvature_unet.h.",
        "",
        "made by:    /usr/bin/python3 train/make_pairs.py && /usr/bin/python3 train/train_unet.py"
        " --steps %d (run again until it exports)" % a.steps,
        "at commit:  %s (the scripts as they were then)" % commit,
        "seed:       pairs %d + 1000 x the mesh's place in the corpus + hole; training %d"
        % (make_pairs.SEED, a.seed),
        "training:   %s" % ", ".join(make_pairs.TRAINING),
        "validation: %s" % ", ".join(make_pairs.VALIDATION),
        "            (../shared/corpus, licences in its MANIFEST.md: all public domain or CC BY)",
        "model:      U-Net, widths %s, %d parameters, 128 x 128 input"
        % (CurvatureWidths(), sum(p.numel() for p in unet.CurvatureUNet().parameters())),
        "loss:       L1 on the hole + %g x L1 of neighbour differences; batch %d, Adam, one-cycle"
        " lr %g" % (a.gradient_weight, a.batch, a.lr),
        "",
        "validation holes (%d): mean absolute curvature error over the hole's cells, t units"
        % summary["holes"],
    ]
    for name in ("learned", "continuation", "tri-laplacian", "coarse"):
        e = summary[name]
        lines.append("  %-14s mean %.5f  90th pct %.5f  better than the continuation on %d"
                     % (name, e["mean"], e["p90"], e["better_than_continuation"]))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def CurvatureWidths():
    m = unet.CurvatureUNet()
    return "/".join(str(w) for w in m.widths)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--pairs", default=os.path.join(ROOT, "build", "learned-pairs"))
    ap.add_argument("--work", default=os.path.join(ROOT, "build", "learned-training"))
    ap.add_argument("--steps", type=int, default=6000)
    ap.add_argument("--batch", type=int, default=16)
    ap.add_argument("--lr", type=float, default=1e-3)
    ap.add_argument("--gradient-weight", type=float, default=1.0)
    ap.add_argument("--minutes", type=float, default=25, help="this piece's limit")
    ap.add_argument("--seed", type=int, default=57)
    ap.add_argument("--threads", type=int, default=os.cpu_count())
    ap.add_argument("--export", default=os.path.join(
        ROOT, "filter_curvature_inpaint", "inpaint", "learned", "curvature_unet.bin"))
    a = ap.parse_args()
    torch.set_num_threads(a.threads)
    torch.manual_seed(a.seed)
    os.makedirs(a.work, exist_ok=True)
    _, train, _ = load(os.path.join(a.pairs, "train"))
    val_files, val, val_planes = load(os.path.join(a.pairs, "validation"))
    train = torch.from_numpy(train)
    model = unet.CurvatureUNet()
    opt = torch.optim.Adam(model.parameters(), lr=a.lr)
    sched = torch.optim.lr_scheduler.OneCycleLR(opt, max_lr=a.lr, total_steps=a.steps,
                                                pct_start=0.05)
    checkpoint = os.path.join(a.work, "checkpoint.pt")
    step = 0
    if os.path.exists(checkpoint):
        state = torch.load(checkpoint)
        model.load_state_dict(state["model"])
        opt.load_state_dict(state["opt"])
        sched.load_state_dict(state["sched"])
        torch.set_rng_state(state["rng"])
        step = state["step"]
    start = time.time()
    log = open(os.path.join(a.work, "log.txt"), "a")
    running = []
    while step < a.steps and time.time() - start < a.minutes * 60:
        idx = torch.randint(0, len(train), (a.batch,))
        k = int(torch.randint(0, 8, (1,)))
        batch = symmetry(train[idx], k)
        loss = loss_of(model, batch, a.gradient_weight)
        opt.zero_grad()
        loss.backward()
        opt.step()
        sched.step()
        step += 1
        running.append(float(loss))
        if step % 100 == 0 or step == a.steps:
            line = "step %d loss %.5f (%.0f s)" % (step, np.mean(running), time.time() - start)
            print(line, flush=True)
            log.write(line + "\n")
            log.flush()
            running = []
        if step % 500 == 0 or step == a.steps:
            torch.save({"model": model.state_dict(), "opt": opt.state_dict(),
                        "sched": sched.state_dict(), "rng": torch.get_rng_state(),
                        "step": step}, checkpoint)
    if step < a.steps:
        torch.save({"model": model.state_dict(), "opt": opt.state_dict(),
                    "sched": sched.state_dict(), "rng": torch.get_rng_state(), "step": step},
                   checkpoint)
        print("stopped at step %d of %d: run it again to go on" % (step, a.steps))
        return 0
    model.eval()
    with torch.no_grad():
        learned = predict(model, torch.from_numpy(val))[:, 0].numpy()
    truth, hole = val[:, 3], val[:, 1]
    errors = {"learned": hole_errors(learned, truth, hole),
              "continuation": hole_errors(val[:, 2], truth, hole),
              "coarse": hole_errors(val[:, 0], truth, hole)}
    tri = [p[4] for p in val_planes]
    errors["tri-laplacian"] = hole_errors(np.stack(tri), truth, hole)
    summary = {name: {"mean": float(e.mean()), "p90": float(np.percentile(e, 90)),
                      "better_than_continuation": int((e < errors["continuation"]).sum())}
               for name, e in errors.items()}
    summary["holes"] = len(val_files)
    json.dump(summary, open(os.path.join(a.work, "validation.json"), "w"), indent=1)
    np.save(os.path.join(a.work, "validation_learned.npy"), learned)
    print(json.dumps(summary, indent=1))
    unet.export(model, a.export)
    unet.write_check(model, os.path.splitext(a.export)[0] + "_check.txt")
    write_card(a, summary, os.path.splitext(a.export)[0] + ".txt")
    print("wrote", a.export)
    return 0


if __name__ == "__main__":
    sys.exit(main())
