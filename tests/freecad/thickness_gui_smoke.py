# Runs inside the FreeCAD GUI under Xvfb (see test_thickness_gui.py): runs the Wall thickness
# command on a plate with a thin rib, waits for the worker thread, records the regions listed and
# saves a screenshot. Writes $CADMEDIAL_GUI_OUT/thickness.json; exits with os._exit.
import json
import os
import time
import traceback

import FreeCAD as App
import FreeCADGui as Gui
from PySide2 import QtCore, QtWidgets

OUT = os.environ["CADMEDIAL_GUI_OUT"]
report = {}


def wait_until(condition, seconds, what):
    end = time.monotonic() + seconds
    while not condition():
        if time.monotonic() > end:
            raise TimeoutError("waited %.0f s for %s" % (seconds, what))
        QtWidgets.QApplication.processEvents(QtCore.QEventLoop.AllEvents, 50)
        time.sleep(0.02)


def run():
    Gui.activateWorkbench("MedialAxisWorkbench")
    doc = App.newDocument("Ribbed")
    plate = doc.addObject("Part::Box", "Plate")
    plate.Length, plate.Width, plate.Height = 40, 40, 4
    rib = doc.addObject("Part::Box", "Rib")
    rib.Length, rib.Width, rib.Height = 1, 40, 10
    rib.Placement.Base = App.Vector(19.5, 0, 4)
    part = doc.addObject("Part::MultiFuse", "Part")
    part.Shapes = [plate, rib]
    part.Refine = True
    doc.recompute()
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(part)
    Gui.runCommand("MedialAxis_WallThickness")
    panel = Gui.Control.activeDialog() and __import__("cadmedial.gui.thickness_panel").gui
    from cadmedial.gui.thickness_panel import TaskPanelWallThickness
    dialogs = [w for w in QtWidgets.QApplication.allWidgets() if w.windowTitle() == "Wall thickness"]
    report["panel_open"] = bool(dialogs)
    task = None
    import gc
    for o in gc.get_objects():
        if isinstance(o, TaskPanelWallThickness):
            task = o
    task.min_wall.setValue(1.5)
    task.start()
    report["gui_thread_free"] = task._thread is not None and task._thread.is_alive()
    wait_until(lambda: task._thread is None, 300, "the analysis")
    report["status"] = task.status.text()
    report["regions"] = [task.regions.item(i).text() for i in range(task.regions.count())]
    objs = [o for o in doc.Objects if getattr(getattr(o, "Proxy", None), "Type", "") == "WallThickness"]
    report["objects"] = len(objs)
    if task.regions.count():
        task._show_region(task.regions.item(0))
        report["selected"] = [s for sel in Gui.Selection.getSelectionEx() for s in sel.SubElementNames]
    part.ViewObject.Visibility = False
    Gui.SendMsgToActiveView("ViewFit")
    Gui.activeDocument().activeView().viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")
    wait_until(lambda: True, 1, "")
    for _ in range(20):
        QtWidgets.QApplication.processEvents()
        time.sleep(0.05)
    Gui.activeDocument().activeView().saveImage(os.path.join(OUT, "thickness.png"), 1000, 750, "White")
    del panel


try:
    run()
except Exception:
    report["exception"] = traceback.format_exc()
with open(os.path.join(OUT, "thickness.json"), "w") as f:
    json.dump(report, f, indent=1)
os._exit(0)
