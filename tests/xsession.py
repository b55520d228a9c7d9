"""An Xvfb display driven with xdotool, and screenshots of it as PNG: what the GUI tests of every
MeshLab release share. Standard library only: it also runs inside the Debian roots."""
import os
import struct
import subprocess
import time

import pngs


def xwd_to_png(data):
    """A PNG of an `xwd` dump (TrueColor, 24 or 32 bits per pixel)."""
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


class XSession:
    """Xvfb on a free display (it writes the number once it is ready), with no window manager:
    windows get the keyboard focus by hand (focus())."""

    def __init__(self, home, screen="1280x1000x24"):
        read, write = os.pipe()
        self.xvfb = subprocess.Popen(["Xvfb", "-displayfd", str(write), "-screen", "0", screen,
                                      "-nolisten", "tcp"], pass_fds=(write,), stderr=subprocess.DEVNULL)
        os.close(write)
        with os.fdopen(read) as f:
            self.display = ":" + f.readline().strip()
        self.env = dict(os.environ, DISPLAY=self.display, HOME=home,
                        XDG_CONFIG_HOME=os.path.join(home, "config"), LIBGL_ALWAYS_SOFTWARE="1")
        self.env.pop("CURVATURE_INPAINT_NO_DIALOG", None)

    def close(self):
        self.xvfb.kill()
        self.xvfb.wait()

    def x(self, *args):
        return subprocess.run(["xdotool", *args], env=self.env, capture_output=True, text=True)

    def wait_window(self, pattern, seconds):
        """The id of the first window whose name matches `pattern`, or None after `seconds`."""
        end = time.monotonic() + seconds
        while True:
            r = self.x("search", "--name", pattern)
            if r.returncode == 0 and r.stdout.split():
                return r.stdout.split()[0]
            if time.monotonic() >= end:
                return None
            time.sleep(0.5)

    def open_filter(self, main, query, title, seconds=60, attempts=3):
        """Starts a filter with MeshLab's filter search (Ctrl+F in `main`, the first match,
        Enter) and returns the id of the window whose name matches `title` that it opens, or
        None. The search ranks filters by how many of the query's words their name and help
        hold, and filters with as many in an arbitrary order: `query` carries a word of the
        filter's own help that the product's other filters lack. Keys sent while a loaded
        machine keeps MeshLab busy can be lost: where no window comes within `seconds`, Escape
        closes what the search left open and it is typed again, `attempts` times in all."""
        for _ in range(attempts):
            self.focus(main)
            self.x("key", "ctrl+f")
            time.sleep(1)
            self.x("type", "--delay", "30", query)
            time.sleep(1)
            self.x("key", "Down")
            self.x("key", "Return")
            window = self.wait_window(title, seconds)
            if window is not None:
                return window
            self.x("key", "Escape")
            time.sleep(1)
        return None

    def size(self, window):
        """(width, height) of a window."""
        geometry = self.x("getwindowgeometry", window).stdout.split("Geometry:")[1].split()[0]
        width, height = geometry.split("x")
        return int(width), int(height)

    def click(self, window, x, y):
        """A left click at (x, y) inside `window`."""
        self.x("mousemove", "--window", window, str(x), str(y))
        self.x("click", "1")

    def focus(self, window):
        self.x("windowfocus", "--sync", window)

    def screenshot(self, path, window=None):
        """The whole screen, or one window (a floating Qt dock is not in the root's picture)."""
        target = ["-id", window] if window else ["-root"]
        data = subprocess.run(["xwd", *target, "-silent"], env=self.env, capture_output=True,
                              check=True).stdout
        with open(path, "wb") as f:
            f.write(xwd_to_png(data))


def wait_text(path, text, seconds):
    """Whether `text` (or one of a tuple of texts) appears in the file at `path` within
    `seconds`."""
    texts = (text,) if isinstance(text, str) else text
    end = time.monotonic() + seconds
    while True:
        with open(path, errors="replace") as f:
            content = f.read()
        if any(t in content for t in texts):
            return True
        if time.monotonic() >= end:
            return False
        time.sleep(0.5)
