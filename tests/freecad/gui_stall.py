# Runs inside the FreeCAD GUI (`freecad gui_stall.py`, under Xvfb): measures how long the GUI stops
# answering while a user works the Medial Axis task panel. A 10 ms QTimer ("heartbeat") records
# the longest gap between its ticks in each phase; a gap of G ms means the event loop was blocked
# for about G - 10 ms. Writes $CADMEDIAL_GUI_OUT/stall.json:
#   {"typing": ms, "compute": ms, "stop": ms, "samples": N, "source": path}
# Phases: typing the sample count key by key; computing and adding the result (until the panel
# closes); a second compute stopped after 1 s (until the panel is idle again).
#   CADMEDIAL_STALL_SOURCE  STEP file (default: the bundled NIST FTC 11)
#   CADMEDIAL_STALL_SAMPLES sample count typed (default 300000)
import os
import time

import FreeCAD as App
import FreeCADGui as Gui
import Import
from PySide2 import QtCore, QtGui, QtWidgets
import sys  # noqa: E402
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # gui_heartbeat beside this script
from gui_heartbeat import Heartbeat, run_and_report  # noqa: E402

OUT = os.environ["CADMEDIAL_GUI_OUT"]
SOURCE = os.environ.get("CADMEDIAL_STALL_SOURCE")
SAMPLES = os.environ.get("CADMEDIAL_STALL_SAMPLES", "300000")
report = {"samples": int(SAMPLES), "source": SOURCE}


def spin(condition, seconds):
    # Lets the event loop run as FreeCAD's own would: control returns to it between short waits.
    end = time.monotonic() + seconds
    while not condition():
        if time.monotonic() > end:
            raise TimeoutError("waited %.0f s" % seconds)
        loop = QtCore.QEventLoop()
        QtCore.QTimer.singleShot(20, loop.quit)
        loop.exec_()


def type_key(widget, char):
    # PySide2 on Debian has no QtTest: send the key press and release as the window system would.
    code = QtCore.Qt.Key_0 + int(char)
    for kind in (QtCore.QEvent.KeyPress, QtCore.QEvent.KeyRelease):
        QtWidgets.QApplication.sendEvent(
            widget, QtGui.QKeyEvent(kind, code, QtCore.Qt.NoModifier, char))


def run():
    from cadmedial.gui import task_panel
    Gui.activateWorkbench("MedialAxisWorkbench")
    doc = App.newDocument("Stall")
    Import.insert(SOURCE, doc.Name)
    doc.recompute()
    source = [o for o in doc.Objects if o.isDerivedFrom("Part::Feature") and o.Shape.Solids][0]
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(source)
    beat = Heartbeat()
    Gui.runCommand("MedialAxis_Create")
    spin(lambda: task_panel.active_panel is not None, 10)
    panel = task_panel.active_panel
    if hasattr(panel, "choose_mode"):
        panel.choose_mode("samples")
    else:
        panel.by_samples.setChecked(True)
    end = time.monotonic() + 0.5
    spin(lambda: time.monotonic() > end, 2)

    beat.reset()
    panel.samples.selectAll()
    for key in SAMPLES:  # a user typing, ~8 keys a second
        type_key(panel.samples, key)
        end = time.monotonic() + 0.12
        spin(lambda: time.monotonic() > end, 5)
    end = time.monotonic() + 1.0  # the debounced estimate, if any, lands here
    spin(lambda: time.monotonic() > end, 60)
    idle = getattr(panel, "estimate_idle", lambda: True)
    spin(idle, 120)
    report["typing"] = beat.gap()
    report["preview"] = panel.preview.text()

    beat.reset()
    started = time.monotonic()
    panel.accept()
    spin(lambda: task_panel.active_panel is None, 900)
    end = time.monotonic() + 2.0  # what runs after the panel closed (view updates, legend)
    spin(lambda: time.monotonic() > end, 10)
    report["compute"] = beat.gap()
    report["compute_seconds"] = round(time.monotonic() - started, 1)
    feature = [o for o in doc.Objects if getattr(getattr(o, "Proxy", None), "Type", None) == "MedialAxis"][0]
    report["status"] = feature.Status
    report["vertices"] = feature.VertexCount

    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(source)
    Gui.runCommand("MedialAxis_Create")
    spin(lambda: task_panel.active_panel is not None, 10)
    panel = task_panel.active_panel
    if hasattr(panel, "choose_mode"):
        panel.choose_mode("samples")
    else:
        panel.by_samples.setChecked(True)
    panel.samples.setValue(int(SAMPLES))
    spin(getattr(panel, "estimate_idle", lambda: True), 120)
    beat.reset()
    panel.accept()
    end = time.monotonic() + 1.0
    spin(lambda: time.monotonic() > end, 10)
    panel.stop.click()
    spin(lambda: panel.job is None, 300)
    report["stop"] = beat.gap()


def main():
    run_and_report(run, report, os.path.join(OUT, "stall.json"))


QtCore.QTimer.singleShot(1500, main)
