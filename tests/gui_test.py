"""The real MeshLab GUI under Xvfb, driven with xdotool: open a shared mesh with a punched hole,
find "Curvature Inpaint Hole Fill" with MeshLab's filter search (Ctrl+F), inpaint in the
product's dialog, apply, and check MeshLab's log. Screenshots go to <build>/screenshots/."""
import os
import re
import subprocess
import time

from support import BUILD, TempDirTest, make_meshlab_prefix
from xsession import XSession, wait_text

SCREENSHOTS = os.path.join(BUILD, "screenshots")


class MeshLabGui(TempDirTest):
    def setUp(self):
        super().setUp()
        os.makedirs(SCREENSHOTS, exist_ok=True)
        self.session = XSession(self.tmp)
        self.addCleanup(self.session.close)
        self.env = self.session.env
        self.x = self.session.x
        self.wait_window = self.session.wait_window
        self.wait_log = wait_text

    def screenshot(self, name):
        self.session.screenshot(os.path.join(SCREENSHOTS, name))

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
        # MeshLab's filter search (no window manager on Xvfb: the session gives MeshLab the
        # keyboard focus by hand). The coarse fill's help names this filter too: "variations"
        # is in this filter's help alone.
        dialog = self.session.open_filter(main, "Curvature Inpaint Hole Fill variations",
                                          "^Curvature Inpaint Hole Fill")
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
        chosen = re.search(r"validation 1: on \d fake holes, .*; chose ([a-z0-9.-]+(?: [a-z0-9.-]+)*)", text)
        self.assertIsNotNone(chosen, text)
        if chosen.group(1) == "coarse":
            self.assertIn("inpaint 1: none: skipped; it keeps its coarse fill", text)
        elif chosen.group(1).startswith("detail"):
            self.assertRegex(text, r"inpaint 1: \d+ edges, variation \d+ of \d+")
        else:  # a prior's variation, named by its kind
            self.assertRegex(text, r"inpaint 1: \d+ edges, variation \d+ " + re.escape(chosen.group(1)) + " of")
