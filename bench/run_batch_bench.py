#!/usr/bin/env python3
"""Whole collections: scans per minute of `curvature-inpaint batch` against a shell loop of
single `fill` runs, and of the shipped Slurm job array on a one-node Slurm of this machine.

    python3 bench/run_batch_bench.py [--scans N]

The collection: N scans (default 100) made from the fandisk and the rocker arm of
../shared/meshes, each with one hole of 3 % of the diagonal punched at its own vertex; every
run fills all of them with the default settings (embedded backend, fake-hole validation, the
priors). Slurm (needs root and Debian's slurm-wlm, which scripts/setup-debian.sh installs):
an array of as many one-core tasks as the machine has cores.

A second table: the pool of inpainting servers, `fill --backend sd-webui` on a scan with 12
holes against 1, 2 and 3 of the tests' AUTOMATIC1111 stand-ins, each answering a request
after a fixed 4 s (a GPU's time for one inpainting).
"""
import os
import shutil
import subprocess
import sys
import tempfile
import time

from run_coarse_bench import BIN, ROOT, SHARED, build, check_args, sh, table

sys.path.insert(0, os.path.join(ROOT, "tests"))
os.environ.setdefault("CI_BUILD_DIR", os.path.dirname(BIN))
os.environ.setdefault("CI_SOURCE_DIR", ROOT)
from slurm_test import SBATCH, OneNodeSlurm  # noqa: E402

TOOL = os.path.join(BIN, "curvature-inpaint")


def pool_table(tmp):
    import inpaint_server
    holed = os.path.join(tmp, "twelve.ply")
    sh([os.path.join(BIN, "bench_tools"), "punch-many", os.path.join(SHARED, "meshes", "koala.ply"),
        holed, "12", "3", "6"])
    rows = []
    servers = [inpaint_server.Server() for _ in range(3)]
    try:
        for n in (1, 2, 3):
            args = [TOOL, "fill", holed, os.path.join(tmp, f"pool{n}.ply"), "--backend", "sd-webui",
                    "--size", "256"]
            for s in servers[:n]:
                args += ["--url", s.url("slow")]
            start = time.perf_counter()
            subprocess.run(args, check=True, capture_output=True,
                           env=dict(os.environ, SD_WEBUI_AUTH=inpaint_server.SD_AUTH))
            seconds = time.perf_counter() - start
            rows.append(f"| {n} | {seconds:.1f} | {60 * 12 / seconds:.1f} |")
    finally:
        for s in servers:
            s.stop()
    table("The pool: a scan with 12 holes, each server 4 s a request",
          ["servers", "seconds", "holes per minute"], rows)


def main():
    options, _ = check_args(__doc__, valued=("--scans",))
    count = int(options.get("--scans", 100))
    build()
    tmp = tempfile.mkdtemp(prefix="batch-bench-")
    try:
        scans = os.path.join(tmp, "scans")
        os.makedirs(scans)
        for i in range(count):
            mesh = ("fandisk.ply", "rocker_arm.ply")[i % 2]
            sh([TOOL, "punch", os.path.join(SHARED, "meshes", mesh),
                os.path.join(scans, f"scan{i:03d}_{mesh}"), "--seed-vertex", str((97 * i + 11) % 6000),
                "--radius-frac", "0.03"])
        rows = []

        def row(label, seconds):
            rows.append(f"| {label} | {seconds:.1f} | {60 * count / seconds:.1f} |")

        out = os.path.join(tmp, "loop")
        os.makedirs(out)
        start = time.perf_counter()
        for name in sorted(os.listdir(scans)):
            sh([TOOL, "fill", os.path.join(scans, name), os.path.join(out, name)])
        row("shell loop of `fill`, one scan after the other", time.perf_counter() - start)
        for jobs in (1, 2):
            out = os.path.join(tmp, f"batch{jobs}")
            start = time.perf_counter()
            sh([TOOL, "batch", scans, out, "--jobs", str(jobs)])
            row(f"`batch --jobs {jobs}`", time.perf_counter() - start)
        out = os.path.join(tmp, "resumed")
        shutil.copytree(os.path.join(tmp, "batch2"), out)
        start = time.perf_counter()
        sh([TOOL, "batch", scans, out, "--jobs", "2"])
        row("`batch --jobs 2` again on its finished folder (every scan skipped)",
            time.perf_counter() - start)
        if os.geteuid() == 0 and shutil.which("slurmctld"):
            slurm = OneNodeSlurm(os.path.join(tmp, "slurm"))
            try:
                slurm.start()
                cores = os.cpu_count()
                out = os.path.join(tmp, "slurm-out")
                start = time.perf_counter()
                job = slurm.sbatch(f"--array=0-{cores - 1}", "--cpus-per-task=1", "--mem=2G",
                                   f"--output={tmp}/task-%a.log",
                                   f"--export=ALL,CURVATURE_INPAINT={TOOL}", SBATCH, scans, out)
                slurm.wait(job, timeout=3600)
                row(f"Slurm array of {cores} one-core tasks (submit to last task done)",
                    time.perf_counter() - start)
            finally:
                slurm.stop()
        table(f"{count} scans (fandisk and rocker arm, one hole each), default settings",
              ["process", "seconds", "scans per minute"], rows)
        pool_table(tmp)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
