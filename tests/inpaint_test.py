"""Every inpainting backend through `curvature-inpaint inpaint`: the remote ones against local
stand-ins of their services (inpaint_server.py) in success and in every failure a service
shows, the embedded one on synthetic curvature fields."""
import math
import os
import unittest

import pngs
from inpaint_server import OPENAI_KEY, SD_AUTH, STABILITY_KEY, Server
from support import SOURCE, TOOL, TempDirTest, read_binary_ply_xyz, run

REMOTE = ("openai", "sd-webui", "stability", "comfyui")
KNOTS = [(0, 0, 255), (0, 255, 255), (0, 255, 0), (255, 255, 0), (255, 0, 0)]


def colour(t):
    t = min(1.0, max(0.0, t))
    s = t * 4
    i = min(int(s), 3)
    f = s - i
    return tuple(round(a + f * (b - a)) for a, b in zip(KNOTS[i], KNOTS[i + 1]))


def value(rgb):
    best = (1e9, 0.5)
    for i in range(4):
        a, b = KNOTS[i], KNOTS[i + 1]
        d = [y - x for x, y in zip(a, b)]
        u = sum((c - x) * e for c, x, e in zip(rgb, a, d)) / sum(e * e for e in d)
        u = min(1.0, max(0.0, u))
        dist = sum((c - x - u * e) ** 2 for c, x, e in zip(rgb, a, d))
        best = min(best, (dist, (i + u) / 4))
    return best[1]


class Backends(TempDirTest):
    @classmethod
    def setUpClass(cls):
        cls.server = Server()
        import tempfile
        cls.dir = tempfile.mkdtemp(prefix="inpaint-test-")
        r = run([TOOL, "images", os.path.join(SOURCE, "meshes", "sample_holes.ply"), cls.dir, "--size", "128"])
        assert r.returncode == 0, r.stderr
        cls.image = os.path.join(cls.dir, "hole_1_curvature.png")
        cls.mask = os.path.join(cls.dir, "hole_1_mask.png")

    @classmethod
    def tearDownClass(cls):
        cls.server.stop()
        import shutil
        shutil.rmtree(cls.dir, ignore_errors=True)

    def inpaint(self, backend, scenario, *extra, timeout=2, url=None):
        env = dict(os.environ, OPENAI_API_KEY=OPENAI_KEY, STABILITY_API_KEY=STABILITY_KEY, SD_WEBUI_AUTH=SD_AUTH,
                   OPENAI_BASE_URL=self.server.url(scenario) + "/v1")
        out = self.path(f"{backend}-{scenario}")
        args = [TOOL, "inpaint", self.image, self.mask, out, "--backend", backend, "-n", "2",
                "--timeout", str(timeout), "--retries", "1", "--max-response-mb", "1", *extra]
        if backend != "openai":
            args += ["--url", url or self.server.url(scenario)]
        import subprocess
        r = subprocess.run(args, capture_output=True, text=True, timeout=120, env=env)
        for secret in (OPENAI_KEY, STABILITY_KEY, SD_AUTH, SD_AUTH.split(":")[1]):
            self.assertNotIn(secret, r.stdout + r.stderr)
        return r, out

    def assert_fails(self, backend, scenario, *words):
        r, out = self.inpaint(backend, scenario)
        self.assertNotEqual(r.returncode, 0, f"{backend} {scenario} succeeded")
        last = r.stderr.strip().splitlines()[-1]
        self.assertTrue(last.startswith(f"curvature-inpaint: {backend}: "), last)
        for w in words:
            self.assertIn(w, last)
        self.assertFalse(os.path.exists(os.path.join(out, "variation_1.png")))
        return last

    def test_success_keeps_every_known_pixel(self):
        _, _, _, src = pngs.decode(open(self.image, "rb").read())
        _, _, _, mask = pngs.decode(open(self.mask, "rb").read())
        for backend in REMOTE:
            with self.subTest(backend=backend):
                r, out = self.inpaint(backend, "ok")
                self.assertEqual(r.returncode, 0, r.stderr)
                self.assertEqual(self.server.violations, [])
                for i in (1, 2):
                    w, h, ch, rows = pngs.decode(open(os.path.join(out, f"variation_{i}.png"), "rb").read())
                    self.assertEqual((w, h), (128, 128))
                    for y in range(h):
                        for x in range(w):
                            if mask[y][x] == 0:
                                self.assertEqual(rows[y][x * ch:x * ch + 3], src[y][x * 3:x * 3 + 3])

    def test_gpt_image_1(self):
        # The stand-in decodes the 1024 x 1024 PNG in pure Python: give it time.
        r, out = self.inpaint("openai", "ok", "--model", "gpt-image-1", timeout=60)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(self.server.violations, [])

    def test_unauthorized(self):
        self.assertIn("Incorrect API key provided", self.assert_fails("openai", "unauthorized", "HTTP 401"))
        self.assert_fails("sd-webui", "unauthorized", "HTTP 401", "Not authenticated")
        self.assert_fails("stability", "unauthorized", "HTTP 401", "authentication failed")

    def test_rate_limit_is_retried_after_the_wait_asked(self):
        for backend in REMOTE:
            with self.subTest(backend=backend):
                before = len(self.server.httpd.requests)
                r, out = self.inpaint(backend, "rate-limited")
                self.assertEqual(r.returncode, 0, r.stderr)
                self.assertTrue(os.path.exists(os.path.join(out, "variation_2.png")))
                self.assertGreater(len(self.server.httpd.requests) - before, 1)

    def test_server_error_is_retried_then_reported(self):
        for backend in REMOTE:
            with self.subTest(backend=backend):
                before = len(self.server.httpd.requests)
                self.assert_fails(backend, "server-error", "HTTP 500", "error processing your request")
                self.assertEqual(len(self.server.httpd.requests) - before, 2)  # one retry

    def test_timeout(self):
        for backend in REMOTE:
            with self.subTest(backend=backend):
                self.assert_fails(backend, "slow", "no complete answer within 2 s")

    def test_garbage_body(self):
        for backend in REMOTE:
            with self.subTest(backend=backend):
                self.assert_fails(backend, "garbage", "not the JSON")

    def test_wrong_image_size(self):
        for backend in REMOTE:
            with self.subTest(backend=backend):
                self.assert_fails(backend, "wrong-size", "image where")

    def test_oversized_body(self):
        for backend in REMOTE:
            with self.subTest(backend=backend):
                self.assert_fails(backend, "oversized", "larger than 1 MB")

    def test_decompression_bomb(self):
        for backend in REMOTE:
            with self.subTest(backend=backend):
                self.assert_fails(backend, "bomb", "refused")

    def test_slow_drip_is_cut_by_the_total_timeout(self):
        for backend in REMOTE:
            with self.subTest(backend=backend):
                self.assert_fails(backend, "drip", "no complete answer within 2 s")

    def test_endless_body_is_cut_by_the_size_cap(self):
        for backend in REMOTE:
            with self.subTest(backend=backend):
                self.assert_fails(backend, "endless", "larger than 1 MB")

    def test_redirect_is_not_followed(self):
        for backend in REMOTE:
            with self.subTest(backend=backend):
                last = self.assert_fails(backend, "redirect", "HTTP 302", "redirects are not followed")
                self.assertNotIn("example.invalid", last)

    def test_deeply_nested_json(self):
        for backend in REMOTE:
            with self.subTest(backend=backend):
                self.assert_fails(backend, "deep-json", "not the JSON")

    def test_invalid_base64(self):
        for backend in ("openai", "sd-webui", "stability"):
            with self.subTest(backend=backend):
                self.assert_fails(backend, "bad-base64", "invalid base64")

    def test_content_that_is_not_an_image(self):
        for backend in REMOTE:
            with self.subTest(backend=backend):
                self.assert_fails(backend, "not-image", "not a valid PNG")

    def test_missing_key_is_one_clear_sentence(self):
        env = {k: v for k, v in os.environ.items() if k != "OPENAI_API_KEY"}
        import subprocess
        r = subprocess.run([TOOL, "inpaint", self.image, self.mask, self.path("o"), "--backend", "openai"],
                           capture_output=True, text=True, env=env)
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("set OPENAI_API_KEY", r.stderr)

    def test_unreachable_server(self):
        r, _ = self.inpaint("sd-webui", "ok", url="http://127.0.0.1:9")
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("curvature-inpaint: sd-webui: ", r.stderr)


class Embedded(TempDirTest):
    def field_image(self, f, size, hole, prior=None):
        """A curvature image of the field f(x, y) and a mask of the pixels `hole` selects. The
        hole's pixels are black (off the colour map: nothing known there) or, given `prior`,
        painted with prior(x, y), as a coarse fill's curvature would be."""
        def pixel(x, y):
            if not hole(x, y):
                return colour(f(x, y))
            return colour(prior(x, y)) if prior else (0, 0, 0)
        rows = [bytes(c for x in range(size) for c in pixel(x, y)) for y in range(size)]
        img, mask = self.path("field.png"), self.path("mask.png")
        with open(img, "wb") as out:
            out.write(pngs.encode(size, size, rows=rows))
        mrows = [bytes(c for x in range(size) for c in ((255,) * 3 if hole(x, y) else (0,) * 3)) for y in range(size)]
        with open(mask, "wb") as out:
            out.write(pngs.encode(size, size, rows=mrows))
        return img, mask

    def inpainted_errors(self, f, size, hole, *extra, prior=None):
        img, mask = self.field_image(f, size, hole, prior)
        out = self.path("out")
        r = run([TOOL, "inpaint", img, mask, out, "-n", "1", *extra])
        self.assertEqual(r.returncode, 0, r.stderr)
        _, _, ch, rows = pngs.decode(open(os.path.join(out, "variation_1.png"), "rb").read())
        return [value(rows[y][x * ch:x * ch + 3]) - min(1, max(0, f(x, y)))
                for y in range(size) for x in range(size) if hole(x, y)]

    def test_exact_on_a_harmonic_field(self):
        size = 96
        f = lambda x, y: 0.5 + 0.4 * ((x - 48) ** 2 - (y - 48) ** 2) / 48 ** 2 + 0.1 * (x - y) / 96  # noqa: E731
        hole = lambda x, y: (x - 50) ** 2 + (y - 44) ** 2 < 22 ** 2  # noqa: E731
        errors = self.inpainted_errors(f, size, hole, "--detail", "0")
        self.assertLess(max(abs(e) for e in errors), 3.5 / 255)  # 8-bit colours, both ways

    def test_smooth_field_rms_below_telea_and_navier_stokes(self):
        # The design notes' case: a 256-pixel rainbow field with a radius-40 hole, where OpenCV's
        # Telea leaves an RMS scalar error of 0.101 and Navier-Stokes 0.091.
        size = 256
        f = lambda x, y: 0.5 + 0.35 * math.sin(2 * math.pi * x / 180) * math.cos(2 * math.pi * y / 150)  # noqa: E731
        hole = lambda x, y: (x - 128) ** 2 + (y - 120) ** 2 < 40 ** 2  # noqa: E731
        errors = self.inpainted_errors(f, size, hole, "--detail", "0")  # the continuation
        rms = math.sqrt(sum(e * e for e in errors) / len(errors))
        self.assertLess(rms, 0.091)

    def test_follows_the_coarse_curvature_the_hole_still_shows(self):
        # A bump inside the hole that no continuation from the border can guess: painted in the
        # hole (as the coarse fill's curvature is), it comes back; left black, it does not.
        size = 128
        bump = lambda x, y: 0.5 + 0.3 * math.exp(-((x - 64) ** 2 + (y - 64) ** 2) / 12 ** 2)  # noqa: E731
        hole = lambda x, y: (x - 64) ** 2 + (y - 64) ** 2 < 36 ** 2  # noqa: E731
        rms = lambda e: math.sqrt(sum(x * x for x in e) / len(e))  # noqa: E731
        with_prior = rms(self.inpainted_errors(bump, size, hole, "--detail", "0", prior=bump))
        without = rms(self.inpainted_errors(bump, size, hole, "--detail", "0"))
        self.assertLess(with_prior, 0.02)
        self.assertGreater(without, 0.05)

    def test_variations_differ_by_seed_and_repeat_for_the_same_seed(self):
        size = 64
        f = lambda x, y: 0.5 + 0.3 * math.sin(x / 3.0) * math.sin(y / 4.0)  # noqa: E731
        img, mask = self.field_image(f, size, lambda x, y: 20 < x < 44 and 20 < y < 44)
        a, b = self.path("a"), self.path("b")
        self.assertEqual(run([TOOL, "inpaint", img, mask, a, "-n", "2", "--seed", "5"]).returncode, 0)
        self.assertEqual(run([TOOL, "inpaint", img, mask, b, "-n", "2", "--seed", "5"]).returncode, 0)
        va1, va2, vb1 = (open(os.path.join(d, n), "rb").read() for d, n in
                         ((a, "variation_1.png"), (a, "variation_2.png"), (b, "variation_1.png")))
        self.assertEqual(va1, vb1)
        self.assertNotEqual(va1, va2)


class FillPipeline(TempDirTest):
    def test_fill_is_watertight_and_leaves_the_rest_bit_for_bit(self):
        src = os.path.join(SOURCE, "meshes", "sample_holes.ply")
        out, report = self.path("filled.ply"), self.path("report.json")
        r = run([TOOL, "fill", src, out, "--size", "128", "--report", report, "--images", self.path("img")])
        self.assertEqual(r.returncode, 0, r.stderr)
        from support import info
        self.assertEqual(info(out)["holes"], 0)
        before, after = read_binary_ply_xyz(src), read_binary_ply_xyz(out)
        self.assertGreater(len(after), len(before))
        self.assertEqual(after[:len(before)], before)
        import json
        holes = json.load(open(report))["holes"]
        self.assertEqual(len(holes), 3)
        for h in holes:
            # Four continuations, then the priors' variations (the tri-Laplacian's on every hole).
            self.assertEqual(h["kinds"][:4], ["continuation"] * 4)
            self.assertEqual(len(h["scores"]), len(h["kinds"]))
            # The best-scored continuation, unless the fake holes found the coarse fill (then
            # none) or a prior's variation closer (then that one).
            choice = h["validation"]["choice"]
            best = 1 + max(range(4), key=lambda i: h["scores"][i])
            self.assertIn("tri-laplacian", h["kinds"][4:])
            if choice == "coarse":
                self.assertEqual(h["pick"], 0)
            elif choice.startswith("detail"):
                self.assertEqual(h["pick"], best)
            else:
                self.assertEqual(h["kinds"][h["pick"] - 1], choice)
        self.assertTrue(os.path.exists(self.path("img/montage.png")))

    def test_failing_backend_changes_nothing_and_says_why(self):
        server = Server()
        self.addCleanup(server.stop)
        src = os.path.join(SOURCE, "meshes", "sample_holes.ply")
        digest = open(src, "rb").read()
        out = self.path("filled.ply")
        r = run([TOOL, "fill", src, out, "--size", "128", "--backend", "sd-webui", "--url",
                 server.url("server-error"), "--retries", "0"])
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("sd-webui: HTTP 500", r.stderr.strip().splitlines()[-1])
        self.assertFalse(os.path.exists(out))
        self.assertEqual(open(src, "rb").read(), digest)


class ServerPool(TempDirTest):
    """`fill` with three AUTOMATIC1111 stand-ins: the holes spread over them, one server lost
    half-way, all of them down."""

    SAMPLE = os.path.join(SOURCE, "meshes", "sample_holes.ply")

    def fill(self, urls, out, *extra):
        args = [TOOL, "fill", self.SAMPLE, out, "--size", "128", "--backend", "sd-webui",
                "--fake-holes", "0", "--retries", "0", "--timeout", "20", *extra]
        for u in urls:
            args += ["--url", u]
        import subprocess
        return subprocess.run(args, capture_output=True, text=True, timeout=300,
                              env=dict(os.environ, SD_WEBUI_AUTH=SD_AUTH))

    def sd_requests(self, server):
        return [r for r in server.httpd.requests if r[2] == "/sdapi/v1/img2img"]

    def test_the_holes_spread_over_every_server(self):
        servers = [Server() for _ in range(3)]
        for s in servers:
            self.addCleanup(s.stop)
        out = self.path("pooled.ply")
        r = self.fill([s.url("ok") for s in servers], out)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual([len(self.sd_requests(s)) for s in servers], [1, 1, 1])
        for s in servers:
            self.assertEqual(s.violations, [])
        # The same variations as from one server: a hole's are one server's answer to its seed.
        single = Server()
        self.addCleanup(single.stop)
        r = self.fill([single.url("ok")], self.path("single.ply"))
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(read_binary_ply_xyz(out), read_binary_ply_xyz(self.path("single.ply")))

    def test_a_server_killed_half_way_loses_no_hole(self):
        import subprocess
        import sys
        import threading
        here = os.path.dirname(os.path.abspath(__file__))
        # The third server in a process of its own, answering slowly, killed while it works.
        doomed = subprocess.Popen(
            [sys.executable, "-c", "import time, inpaint_server as s; srv = s.Server(); "
             "print(srv.url('slow'), flush=True); time.sleep(600)"],
            cwd=here, stdout=subprocess.PIPE, text=True)
        self.addCleanup(doomed.kill)
        slow_url = doomed.stdout.readline().strip()
        servers = [Server() for _ in range(2)]
        for s in servers:
            self.addCleanup(s.stop)
        threading.Timer(1.5, doomed.kill).start()
        out = self.path("filled.ply")
        r = self.fill([slow_url] + [s.url("ok") for s in servers], out)
        self.assertEqual(r.returncode, 0, r.stderr)
        # Every hole done, on the two left: one request each, and the killed one's again.
        self.assertEqual(sum(len(self.sd_requests(s)) for s in servers), 3)
        from support import info
        self.assertEqual(info(out)["holes"], 0)

    def test_every_server_down_is_one_error_and_no_output(self):
        import socket
        ports = []
        for _ in range(3):
            with socket.socket() as sock:  # a port nobody listens on
                sock.bind(("127.0.0.1", 0))
                ports.append(sock.getsockname()[1])
        out = self.path("filled.ply")
        r = self.fill([f"http://127.0.0.1:{p}" for p in ports], out)
        self.assertNotEqual(r.returncode, 0)
        last = r.stderr.strip().splitlines()[-1]
        self.assertIn("every one of the 3 servers failed", last)
        self.assertFalse(os.path.exists(out))


if __name__ == "__main__":
    unittest.main()
