"""The real MeshLab GUI under Xvfb, driven with xdotool: open a shared mesh with a punched hole,
find "Curvature Inpaint Hole Fill" with MeshLab's filter search (Ctrl+F), inpaint in the
product's dialog, apply, and check MeshLab's log. Screenshots go to <build>/screenshots/."""
import os
import re
import struct
import subprocess
import time

import pngs
from support import BUILD, TempDirTest, make_meshlab_prefix

SCREENSHOTS = os.path.join(BUILD, "screenshots")


def xwd_to_png(data):
    """A PNG of an `xwd -root` dump (TrueColor, 24 or 32 bits per pixel)."""
    (header_size, _, _, depth, width, height, _, byte_order, _, _, _, bits_per_pixel,
     bytes_per_line, _, red_mask, green_mask, blue_mask, _, _, ncolors) = struct.unpack(">20I", data[:80])
    offset = header_size + 12 * ncolors
    step = bits_per_pixel // 8
    order = "<" if byte_order == 0 else ">"
    fmt = order + "I"

    def shift(mask):
        return (mask & -mask).bit_length() - 1

    rs, gs, bs = shift(red_mask), shift(green_mask), shift(blue_mask)
    rows = []
    for y in range(height):
        line = data[offset + y * bytes_per_line:offset + y * bytes_per_line + width * step]
        row = bytearray()
        for x in range(width):
            chunk = line[x * step:x * step + step]
            (p,) = struct.unpack(fmt, chunk if step == 4 else chunk + b"\0")
            row += bytes(((p & red_mask) >> rs, (p & green_mask) >> gs, (p & blue_mask) >> bs))
        rows.append(bytes(row))
    return pngs.encode(width, height, rows=rows)


class MeshLabGui(TempDirTest):
    def setUp(self):
        super().setUp()
        os.makedirs(SCREENSHOTS, exist_ok=True)
        # Xvfb picks a free display and writes its number once it is ready.
        read, write = os.pipe()
        self.xvfb = subprocess.Popen(["Xvfb", "-displayfd", str(write), "-screen", "0", "1280x1000x24",
                                      "-nolisten", "tcp"], pass_fds=(write,), stderr=subprocess.DEVNULL)
        os.close(write)
        with os.fdopen(read) as f:
            self.display = ":" + f.readline().strip()
        self.addCleanup(self.xvfb.kill)
        self.env = dict(os.environ, DISPLAY=self.display, HOME=self.tmp,
                        XDG_CONFIG_HOME=self.path("config"), LIBGL_ALWAYS_SOFTWARE="1")
        self.env.pop("CURVATURE_INPAINT_NO_DIALOG", None)

    def x(self, *args):
        return subprocess.run(["xdotool", *args], env=self.env, capture_output=True, text=True)

    def wait_window(self, pattern, seconds):
        """The id of the first window whose name matches `pattern`, or None after `seconds`."""
        end = time.monotonic() + seconds
        while time.monotonic() < end:
            r = self.x("search", "--name", pattern)
            if r.returncode == 0 and r.stdout.split():
                return r.stdout.split()[0]
            time.sleep(0.5)
        return None

    def wait_log(self, log, text, seconds):
        end = time.monotonic() + seconds
        while time.monotonic() < end:
            with open(log, errors="replace") as f:
                if text in f.read():
                    return True
            time.sleep(0.5)
        return False

    def screenshot(self, name):
        data = subprocess.run(["xwd", "-root", "-silent"], env=self.env, capture_output=True, check=True).stdout
        with open(os.path.join(SCREENSHOTS, name), "wb") as f:
            f.write(xwd_to_png(data))

    def test_dialog_previews_the_variations_and_apply_fills_the_hole(self):
        mesh = self.punched("igea_190k.ply", 21537, 0.05)
        meshlab = os.path.join(make_meshlab_prefix(self.path("prefix")), "meshlab")
        log = self.path("meshlab.log")
        with open(log, "w") as out:
            gui = subprocess.Popen([meshlab, mesh], env=self.env, stdout=out, stderr=subprocess.STDOUT,
                                   cwd=self.tmp)
        self.addCleanup(gui.kill)
        main = self.wait_window("^MeshLab 20", 120)
        self.assertIsNotNone(main, "MeshLab's window did not appear")
        self.assertTrue(self.wait_log(log, "All files opened", 120), open(log).read())
        time.sleep(1)
        # No window manager on Xvfb: give MeshLab the keyboard focus by hand.
        self.x("windowfocus", "--sync", main)

        # MeshLab's filter search: the first match is the filter; Enter starts it.
        self.x("key", "ctrl+f")
        time.sleep(1)
        self.x("type", "--delay", "30", "Curvature Inpaint Hole Fill")
        time.sleep(1)
        self.x("key", "Down")
        self.x("key", "Return")
        dialog = self.wait_window("^Curvature Inpaint Hole Fill", 60)
        if dialog is None:
            self.screenshot("no_dialog.png")
        self.assertIsNotNone(dialog, "the Curvature Inpaint Hole Fill dialog did not appear:\n" + open(log).read())
        time.sleep(1)

        self.x("key", "alt+i")  # Inpaint
        ready = self.wait_window("holes ready", 180)
        self.assertIsNotNone(ready, "no variations were shown:\n" + open(log).read())
        title = self.x("getwindowname", ready).stdout
        self.assertIn("1 of 1 holes ready", title)
        time.sleep(1)
        self.screenshot("dialog_variations.png")
        with open(log) as f:
            self.assertNotIn("Applied filter Curvature Inpaint Hole Fill", f.read(),
                             "the mesh changed before Apply")

        self.x("key", "alt+a")  # Apply
        self.assertTrue(self.wait_log(log, "Applied filter Curvature Inpaint Hole Fill", 120), open(log).read())
        time.sleep(2)
        self.screenshot("mesh_after_apply.png")
        text = open(log).read()
        self.assertIn("filled 1 of 1 holes", text)
        # The dialog's automatic pick is the fake-hole validation's choice: a variation, or the
        # coarse fill (Skip) where that came closest.
        chosen = re.search(r"validation 1: on \d fake holes, .*; chose ([a-z0-9. ]+)", text)
        self.assertIsNotNone(chosen, text)
        if chosen.group(1) == "coarse":
            self.assertIn("detail 1: none: skipped; it keeps its coarse fill", text)
        else:
            self.assertRegex(text, r"detail 1: \d+ edges, variation \d of 4")
