#!/usr/bin/env python3
"""Inpainting accuracy on real curvature: for every public case of ../shared/bench/cases.tsv,
the hole's curvature image is completed by each offline method and compared, on the hole's
pixels, with the ideal image (the ground truth's own curvature painted over the same patch and
UV, as `fill --oracle` paints it; bench_tools ideal).

    python3 bench/run_inpaint_bench.py      # prints Markdown tables

Methods: embedded (the default backend, seed 1), the same without detail (--detail 0),
OpenCV's Telea and Navier-Stokes (python3-opencv, installed by this script only). Measures:
RMS of the curvature value (colour map inverted, range 0-1) and SSIM of the value field over
the hole's bounding box. Images are 256 x 256 (the Python SSIM is slow beyond); the embedded
backend's time is also measured on the 1024 x 1024 image of the Igea nose.
"""
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

from run_coarse_bench import BIN, SHARED, build, case_input, cases, check_args, sh, table

SIZE = 256


def ensure_opencv():
    """Debian's python3-opencv, for the two reference methods; it lives in Debian's Python, so
    the script re-runs itself there when started from another one."""
    try:
        import cv2  # noqa: F401
        return
    except ImportError:
        pass
    if subprocess.run(["dpkg-query", "-W", "python3-opencv"], capture_output=True).returncode != 0:
        prefix = [] if os.geteuid() == 0 else ["sudo"]
        sh(prefix + ["apt-get", "install", "-y", "-qq", "--no-install-recommends", "python3-opencv"],
           env=dict(os.environ, DEBIAN_FRONTEND="noninteractive"))
    if sys.executable != "/usr/bin/python3":
        os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)


KNOTS = None


def values(img_bgr):
    """The colour map's inverse on every pixel (nearest point of the rainbow polyline)."""
    import numpy as np
    rgb = img_bgr[..., ::-1].astype(np.float64)
    knots = np.array([[0, 0, 255], [0, 255, 255], [0, 255, 0], [255, 255, 0], [255, 0, 0]], float)
    best_d = np.full(rgb.shape[:2], np.inf)
    best_t = np.zeros(rgb.shape[:2])
    for i in range(4):
        a, d = knots[i], knots[i + 1] - knots[i]
        u = np.clip(((rgb - a) @ d) / (d @ d), 0, 1)
        dist = np.linalg.norm(rgb - (a + u[..., None] * d), axis=2)
        better = dist < best_d
        best_d[better] = dist[better]
        best_t[better] = (i + u[better]) / 4
    return best_t


def ssim(a, b):
    import cv2
    import numpy as np
    c1, c2 = 0.01 ** 2, 0.03 ** 2
    blur = lambda x: cv2.GaussianBlur(x, (7, 7), 1.5)  # noqa: E731
    ma, mb = blur(a), blur(b)
    va, vb, cov = blur(a * a) - ma * ma, blur(b * b) - mb * mb, blur(a * b) - ma * mb
    s = ((2 * ma * mb + c1) * (2 * cov + c2)) / ((ma * ma + mb * mb + c1) * (va + vb + c2))
    return float(np.mean(s))


def main():
    check_args(__doc__)
    ensure_opencv()
    build()
    import cv2
    import numpy as np
    tool, bench = os.path.join(BIN, "curvature-inpaint"), os.path.join(BIN, "bench_tools")
    tmp = tempfile.mkdtemp(prefix="inpaint-bench-")
    rows, times = [], []
    try:
        for name, gt, seed, frac, given in cases():
            inp = case_input(tmp, name, gt, seed, frac, given)
            d = os.path.join(tmp, name)
            sh([bench, "ideal", gt, inp, d, str(SIZE)])
            for k in range(1, 10):
                image = os.path.join(d, f"hole_{k}_curvature.png")
                if not os.path.exists(image):
                    continue
                mask_path = os.path.join(d, f"hole_{k}_mask.png")
                img = cv2.imread(image)
                mask = cv2.imread(mask_path, cv2.IMREAD_GRAYSCALE)
                hole = mask > 127
                if hole.sum() < 50:
                    continue
                ideal_path = os.path.join(d, f"hole_{k}_ideal.png")
                if not os.path.exists(ideal_path):  # the ground truth does not close this one alone
                    continue
                ideal = values(cv2.imread(ideal_path))
                ys, xs = np.nonzero(hole)
                box = (slice(ys.min(), ys.max() + 1), slice(xs.min(), xs.max() + 1))
                results = {}
                for label, extra in (("embedded", []), ("smooth", ["--detail", "0"])):
                    out = os.path.join(d, f"{label}_{k}")
                    sh([tool, "inpaint", image, mask_path, out, "-n", "1"] + extra)
                    results[label] = values(cv2.imread(os.path.join(out, "variation_1.png")))
                results["coarse"] = values(img)  # the coarse fill's own curvature, not inpainted
                results["Telea"] = values(cv2.inpaint(img, mask, 3, cv2.INPAINT_TELEA))
                results["Navier-Stokes"] = values(cv2.inpaint(img, mask, 3, cv2.INPAINT_NS))
                cells = []
                for label in ("embedded", "smooth", "Telea", "Navier-Stokes", "coarse"):
                    v = results[label]
                    rms = float(np.sqrt(np.mean((v[hole] - ideal[hole]) ** 2)))
                    cells.append(f"{rms:.3f} / {ssim(v[box], ideal[box]):.2f}")
                rows.append(f"| {name} (hole {k}) | {int(hole.sum())} | " + " | ".join(cells) + " |")
        # Speed at the default size on the Igea nose.
        igea = os.path.join(tmp, "igea_nose.ply")
        d = os.path.join(tmp, "speed")
        sh([tool, "images", igea, d, "--size", "1024"])
        image, mask = os.path.join(d, "hole_1_curvature.png"), os.path.join(d, "hole_1_mask.png")
        for n in (1, 4):
            runs = []
            for _ in range(3):
                start = time.perf_counter()
                sh([tool, "inpaint", image, mask, os.path.join(d, "out"), "-n", str(n)])
                runs.append(time.perf_counter() - start)
            times.append(f"| Igea nose, 1024 x 1024 | {n} | {statistics.median(runs):.2f} |")
        table(f"Scalar RMS / SSIM on the hole against the ideal image ({SIZE} x {SIZE}; lower RMS, higher SSIM is better)",
              ["case", "hole pixels", "embedded", "embedded without detail", "OpenCV Telea", "OpenCV Navier-Stokes",
               "the coarse fill's own curvature"], rows)
        table("Embedded backend, whole `curvature-inpaint inpaint` process (median of 3)",
              ["image", "variations", "seconds"], times)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
