# The screenshot of docs/workbench.md, made in the real FreeCAD GUI by the workbench's own
# command and task panel. With the addon installed (tools/install_addon.sh):
#
#   CADMEDIAL_SCREENSHOT=docs/img/workbench.png xvfb-run -a -s "-screen 0 1400x900x24" freecad examples/workbench_screenshot.py
#
# (As root, FreeCAD's Start page needs QTWEBENGINE_CHROMIUM_FLAGS=--no-sandbox.)
import os
import time

import FreeCAD as App
import FreeCADGui as Gui
from PySide2 import QtCore, QtGui, QtWidgets


def settle(seconds):
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        QtWidgets.QApplication.processEvents(QtCore.QEventLoop.AllEvents, 50)
        time.sleep(0.02)


def main():
    mw = Gui.getMainWindow()
    mw.setGeometry(QtGui.QGuiApplication.primaryScreen().availableGeometry())
    mw.findChild(QtWidgets.QMdiArea).closeAllSubWindows()
    Gui.activateWorkbench("MedialAxisWorkbench")
    doc = App.newDocument("Bracket")
    # A bracket: a plate with a hole and an upright web.
    plate = doc.addObject("Part::Box", "Plate")
    plate.Length, plate.Width, plate.Height = 60.0, 40.0, 10.0
    web = doc.addObject("Part::Box", "Web")
    web.Length, web.Width, web.Height = 10.0, 40.0, 40.0
    hole = doc.addObject("Part::Cylinder", "Hole")
    hole.Radius, hole.Height = 8.0, 20.0
    hole.Placement.Base = App.Vector(38, 20, -5)
    fused = doc.addObject("Part::MultiFuse", "Body")
    fused.Shapes = [plate, web]
    bracket = doc.addObject("Part::Cut", "Bracket")
    bracket.Base, bracket.Tool = fused, hole
    doc.recompute()
    for obj in (plate, web, hole, fused):
        obj.ViewObject.Visibility = False

    Gui.Selection.addSelection(bracket)
    Gui.runCommand("MedialAxis_Create")
    settle(0.5)
    from cadmedial.gui import task_panel
    panel = task_panel.active_panel
    panel.choose_mode("samples")
    panel.samples.setValue(30000)
    panel.accept()
    while task_panel.active_panel is not None:
        settle(0.2)
    feature = doc.getObject("MedialAxis")
    feature.ViewObject.Selectable = False  # show its properties without the selection colour
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(feature)
    view = Gui.ActiveDocument.ActiveView
    view.viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")
    settle(2.0)
    QtGui.QGuiApplication.primaryScreen().grabWindow(0).save(os.environ["CADMEDIAL_SCREENSHOT"])
    os._exit(0)


QtCore.QTimer.singleShot(1500, main)
