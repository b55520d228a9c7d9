"""Drives the real `meshlab` of 2021.05 or later (FilterPlugin) under Xvfb, inside the Debian root
of its release: installs the plugin in MeshLab's per-user plugin folder, opens a mesh, runs one
of the product's filters through its dialog, exports the mesh and prints MeshLab's log. Exits 1
with the reason (and a screenshot) when MeshLab refuses the plugin or a dialog never appears.

usage: meshlab_gui_driver.py coarse-hole-fill|hole-fill|hole-fill-cancelled RELEASE PLUGIN MESH OUT SCREENSHOTS
PLUGIN "installed": the plugin a package installed where MeshLab loads its own."""
import os
import shutil
import subprocess
import sys
import tempfile
import time

from xsession import XSession, wait_text


class Failure(Exception):
    pass


def install_plugin(home, release, plugin):
    """MeshLab's per-user plugin folder: <AppDataLocation>/MeshLabExtraPlugins/<release>/, where
    AppDataLocation is $XDG_DATA_HOME/VCG/MeshLab_64bit_fp for the float builds Debian ships."""
    data = os.path.join(home, "data")
    folder = os.path.join(data, "VCG", "MeshLab_64bit_fp", "MeshLabExtraPlugins", release)
    os.makedirs(folder)
    if plugin != "installed":
        shutil.copy(plugin, folder)
    return data


def applied(log, name, seconds):
    """Whether MeshLab logs that it applied the filter ("Applied filter: NAME" in 2025.07,
    "Applied filter NAME" in 2022.02) within `seconds`."""
    return wait_text(log, ("Applied filter: " + name, "Applied filter " + name), seconds)


def coarse_hole_fill(session, main, log, shots):
    name = "Curvature Inpaint: Coarse Hole Fill"
    # Since 2021.05 a filter's parameters are in a floating dock, a window of its own.
    dock = session.open_filter(main, "Curvature Inpaint Coarse Hole Fill Liepa", "^" + name + "$")
    if dock is None:
        raise Failure("the dialog of " + name + " did not appear")
    time.sleep(2)
    session.screenshot(os.path.join(shots, "coarse_hole_fill_dialog.png"), dock)
    width, height = session.size(dock)
    session.click(dock, width - 100, height - 22)  # Apply, at the dock's bottom right
    if not applied(log, name, 120):
        raise Failure(name + " was not applied")


HOLE_FILL = "Curvature Inpaint Hole Fill"


def open_product_dialog(session, main):
    """The product's own dialog, focused; MeshLab shows none of its own for this filter."""
    dialog = session.open_filter(main, HOLE_FILL + " variations", "^" + HOLE_FILL)
    if dialog is None:
        raise Failure("the product's dialog did not appear")
    time.sleep(1)
    session.focus(dialog)
    return dialog


def hole_fill(session, main, log, shots):
    dialog = open_product_dialog(session, main)
    session.x("key", "alt+i")  # Inpaint
    ready = session.wait_window("holes ready", 180)
    if ready is None:
        session.screenshot(os.path.join(shots, "hole_fill_dialog_failure.png"), dialog)
        raise Failure("the dialog showed no variations")
    time.sleep(1)
    session.screenshot(os.path.join(shots, "hole_fill_dialog.png"), ready)
    if applied(log, HOLE_FILL, 0):
        raise Failure("the mesh changed before Apply")
    session.focus(ready)
    session.x("key", "alt+a")  # Apply
    if not applied(log, HOLE_FILL, 120):
        raise Failure(HOLE_FILL + " was not applied")


def hole_fill_cancelled(session, main, log, shots):
    open_product_dialog(session, main)
    session.x("key", "Escape")  # Cancel
    if not wait_text(log, "cancelled; the mesh was not changed", 60):
        raise Failure("the dialog was not cancelled")


def export_mesh(session, main, log, out):
    session.focus(main)
    session.x("key", "ctrl+shift+e")  # File > Export Mesh As...
    if session.wait_window('^Save "', 30) is None:
        raise Failure("the export dialog did not appear")
    time.sleep(1)
    session.x("type", "--delay", "10", out)
    session.x("key", "Return")
    if session.wait_window("^Choose Saving Options", 30) is None:
        raise Failure("the saving options did not appear")
    time.sleep(1)
    session.x("key", "Return")
    if not wait_text(log, "Saved Mesh " + out, 60):
        raise Failure("the mesh was not saved")


def main():
    action, release, plugin, mesh, out, shots = sys.argv[1:7]
    home = tempfile.mkdtemp(prefix="meshlab-home-")
    session = XSession(home)
    session.env["XDG_DATA_HOME"] = install_plugin(home, release, plugin)
    log = os.path.join(home, "meshlab.log")
    gui = None
    try:
        with open(log, "w") as f:
            gui = subprocess.Popen(["meshlab", mesh], env=session.env, stdout=f,
                                   stderr=subprocess.STDOUT, cwd=home)
        main_window = session.wait_window("^MeshLab 20", 120)
        if main_window is None:
            raise Failure("MeshLab's window did not appear")
        # MeshLab says why it refuses a plugin only in a message box, which blocks it.
        end = time.monotonic() + 120
        while not wait_text(log, "All files opened", 0):
            refused = session.wait_window("^Error while loading plugins", 0)
            if refused is not None:
                time.sleep(1)
                picture = os.path.join(shots, "plugins_refused.png")
                session.screenshot(picture, refused)
                raise Failure("MeshLab refused plugins; its message is in " + picture)
            if time.monotonic() > end:
                raise Failure("MeshLab did not open " + mesh)
            time.sleep(0.5)
        time.sleep(1)
        actions = {"coarse-hole-fill": coarse_hole_fill, "hole-fill": hole_fill,
                   "hole-fill-cancelled": hole_fill_cancelled}
        actions[action](session, main_window, log, shots)
        export_mesh(session, main_window, log, out)
        status = 0
    except Failure as e:
        session.screenshot(os.path.join(shots, action + "_failure.png"))
        print("FAIL:", e)
        status = 1
    finally:
        if gui is not None:
            gui.kill()
            gui.wait()
        session.close()
    with open(log, errors="replace") as f:
        print(f.read())
    shutil.rmtree(home, ignore_errors=True)
    return status


if __name__ == "__main__":
    sys.exit(main())
