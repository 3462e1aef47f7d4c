# Runs inside the FreeCAD GUI (`freecad gui_smoke.py`, under Xvfb; see test_gui.py): uses the
# Medial Axis workbench as a person would and writes what it saw to $CADMEDIAL_GUI_OUT/report.json,
# plus screenshots. Exits FreeCAD itself with os._exit (status 0 = the script ran to its end).
import json
import os
import sys
import time
import traceback

import FreeCAD as App
import FreeCADGui as Gui
from PySide2 import QtCore, QtGui, QtWidgets

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # gui_checks beside this script
from gui_checks import cut_off  # noqa: E402

OUT = os.environ["CADMEDIAL_GUI_OUT"]
report = {"steps": []}


def finish(code):
    with open(os.path.join(OUT, "report.json"), "w") as f:
        json.dump(report, f, indent=1)
    os._exit(code)


def wait_until(condition, seconds, what):
    end = time.monotonic() + seconds
    while not condition():
        if time.monotonic() > end:
            raise TimeoutError("waited %.0f s for %s" % (seconds, what))
        QtWidgets.QApplication.processEvents(QtCore.QEventLoop.AllEvents, 50)
        time.sleep(0.02)


def settle(seconds=0.5):
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        QtWidgets.QApplication.processEvents(QtCore.QEventLoop.AllEvents, 50)
        time.sleep(0.02)


def report_view_text():
    for widget in QtWidgets.QApplication.allWidgets():
        if widget.objectName() == "Report view" and hasattr(widget, "toPlainText"):
            return widget.toPlainText()
    return ""


def coloured_pixels(path):
    """Of every 4th pixel in x and y, those in the radius colour map's range (violet..yellow)."""
    image = QtGui.QImage(path)
    coloured = 0
    for y in range(0, image.height(), 4):
        for x in range(0, image.width(), 4):
            c = QtGui.QColor(image.pixel(x, y))
            if abs(c.red() - c.green()) > 60 or abs(c.green() - c.blue()) > 60:
                coloured += 1
    return coloured


def run():
    mw = Gui.getMainWindow()
    mw.setGeometry(QtGui.QGuiApplication.primaryScreen().availableGeometry())
    mdi = mw.findChild(QtWidgets.QMdiArea)
    mdi.closeAllSubWindows()  # the Start page
    Gui.activateWorkbench("MedialAxisWorkbench")
    report["workbench"] = Gui.activeWorkbench().name()
    doc = App.newDocument("Smoke")
    box = doc.addObject("Part::Box", "Box")
    box.Length, box.Width, box.Height = 40.0, 20.0, 10.0
    doc.recompute()
    Gui.Selection.clearSelection()
    report["create_active_without_selection"] = Gui.Command.get("MedialAxis_Create").isActive()
    Gui.Selection.addSelection(box)
    settle(0.3)
    report["create_active_with_box"] = Gui.Command.get("MedialAxis_Create").isActive()
    report["steps"].append("selected")

    Gui.runCommand("MedialAxis_Create")
    settle(0.5)
    from cadmedial.gui import task_panel
    panel = task_panel.active_panel
    report["task_dialog_open"] = Gui.Control.activeDialog()
    report["mode_default"] = panel.mode_key()
    panel.choose_mode("samples")
    wait_until(panel.estimate_idle, 60, "the estimate")
    report["preview_default"] = panel.preview.text()
    report["refine_default"] = panel.refine.isChecked()
    panel.samples.setValue(4000)
    wait_until(panel.estimate_idle, 60, "the estimate")
    report["preview_4000"] = panel.preview.text()
    # The panel at the default Combo View width: Stop shown, nothing wider than the panel.
    report["panel_width"] = panel.form.width()
    report["panel_min_width"] = panel.form.minimumSizeHint().width()
    report["stop_visible"] = panel.stop.isVisible() and panel.stop.width() > 20
    # The Min feature row: a length, "none" at 0; shown whole at this width with a value too.
    report["min_feature_default"] = [panel.min_feature.value(), panel.min_feature.text()]
    panel.min_feature.setValue(0.125)
    wait_until(panel.estimate_idle, 60, "the estimate")
    settle(0.2)
    report["min_feature_row"] = {
        "label": panel.form.findChild(QtWidgets.QGroupBox).layout().labelForField(panel.min_feature).text(),
        "text": panel.min_feature.text(), "visible": panel.min_feature.isVisible()}
    report["panel_cut_off"] = cut_off(panel.form)
    panel.form.grab().save(os.path.join(OUT, "panel.png"))
    panel.make_shape.setChecked(True)
    panel.accept()
    report["stop_enabled_while_running"] = panel.stop.isEnabled()
    wait_until(lambda: task_panel.active_panel is None, 300, "the task panel to finish")
    report["steps"].append("computed")
    settle(1.0)

    feature = doc.getObject("MedialAxis")
    vobj = feature.ViewObject
    report["feature"] = {
        "status": feature.Status, "points": feature.Mesh.CountPoints,
        "facets": feature.Mesh.CountFacets, "vertex_count": feature.VertexCount,
        "colors": len(feature.RadiusColors), "coloring": vobj.Coloring,
        "samples": feature.Samples, "refine": feature.Refine,
        "min_feature": feature.MinFeature.Value, "radius": [feature.RadiusMin.Value, feature.RadiusMax.Value],
        "proxy": type(vobj.Proxy).__module__ + "." + type(vobj.Proxy).__name__,
        "source_display": box.ViewObject.DisplayMode}
    shape = doc.getObject("MedialShape")
    report["shape_faces"] = len(shape.Shape.Faces) if shape else None

    from cadmedial.gui import legend
    view = Gui.ActiveDocument.ActiveView
    widget = view.graphicsView()
    shown = legend.legend_of(widget)
    report["legend"] = shown.text() if shown is not None and shown.isVisible() else None

    Gui.Selection.clearSelection()
    view.viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")
    settle(1.0)
    view.saveImage(os.path.join(OUT, "view.png"), 800, 600, "White")
    screen = QtGui.QGuiApplication.primaryScreen().grabWindow(0)
    screen.save(os.path.join(OUT, "workbench.png"))
    # Pixels of the 3D view area that are in the radius colour map's range (violet..yellow).
    image = QtGui.QImage(os.path.join(OUT, "view.png"))
    report["view_size"] = [image.width(), image.height()]
    report["coloured_pixels_sampled"] = coloured_pixels(os.path.join(OUT, "view.png"))

    # Changing the box recomputes the medial axis.
    box.Length = 80.0
    doc.recompute()
    settle(0.5)
    report["bbox_after_change"] = [feature.Mesh.BoundBox.XLength, feature.Mesh.BoundBox.YLength]
    report["colors_after_change"] = [len(feature.RadiusColors), feature.Mesh.CountPoints]

    # A face is no solid: the command stays inactive, the API raises and reports.
    plane = doc.addObject("Part::Plane", "Plane")
    doc.recompute()
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(plane)
    settle(0.3)
    report["create_active_with_face"] = Gui.Command.get("MedialAxis_Create").isActive()
    from cadmedial.gui import commands
    commands.last_message = None
    Gui.runCommand("MedialAxis_Create")
    settle(0.3)
    box_shown = commands.last_message
    report["face_message"] = box_shown.text() if box_shown is not None else None
    report["dialog_open_for_face"] = Gui.Control.activeDialog()
    if box_shown is not None:
        box_shown.grab().save(os.path.join(OUT, "face_message.png"))
        box_shown.close()
    count = len(doc.Objects)
    import cadmedial.app
    try:
        cadmedial.app.make_medial_axis(plane)
        report["face_error"] = None
    except Exception as error:
        report["face_error"] = "%s: %s" % (type(error).__name__, error)
    settle(0.3)
    report["objects_added_by_face"] = len(doc.Objects) - count
    report["report_view_has_error"] = "Medial axis of Plane" in report_view_text()

    # Two selected solids give two features.
    before = [o.Name for o in doc.Objects if o.Name.startswith("MedialAxis")]
    boxes = [doc.addObject("Part::Box", "Small") for _ in range(2)]
    boxes[1].Placement.Base = App.Vector(0, 0, 50)
    doc.recompute()
    Gui.Selection.clearSelection()
    for b in boxes:
        Gui.Selection.addSelection(b)
    Gui.runCommand("MedialAxis_Create")
    settle(0.3)
    task_panel.active_panel.samples.setValue(1000)
    task_panel.active_panel.accept()
    wait_until(lambda: task_panel.active_panel is None, 300, "the two computes")
    after = [o.Name for o in doc.Objects if o.Name.startswith("MedialAxis")]
    report["features_for_two_boxes"] = len(after) - len(before)

    # Stop during a long compute: nothing is added.
    count = len(doc.Objects)
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(box)
    Gui.runCommand("MedialAxis_Create")
    settle(0.3)
    panel = task_panel.active_panel
    panel.choose_mode("samples")
    panel.samples.setValue(3000000)
    panel.accept()
    settle(0.5)
    panel.stop.click()
    wait_until(lambda: panel.job is None, 120, "the stopped compute to end")
    report["stopped_message"] = panel.stage.text()
    report["objects_added_by_stop"] = len(doc.Objects) - count
    panel.reject()
    settle(0.3)
    report["dialog_open_after_reject"] = Gui.Control.activeDialog()
    # One Cancel while computing stops and closes.
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(box)
    Gui.runCommand("MedialAxis_Create")
    settle(0.3)
    panel = task_panel.active_panel
    panel.choose_mode("samples")
    panel.samples.setValue(3000000)
    panel.accept()
    settle(0.5)
    panel.reject()
    wait_until(lambda: panel.job is None, 120, "the cancelled compute to end")
    settle(0.3)
    report["dialog_open_after_one_cancel"] = Gui.Control.activeDialog()
    report["objects_added_by_cancel"] = len(doc.Objects) - count

    # Editing: the task panel on an existing feature changes its parameters and recomputes.
    Gui.ActiveDocument.setEdit(feature.Name)
    settle(0.3)
    panel = task_panel.active_panel
    report["edit_panel_for"] = panel.edit.Name if panel and panel.edit else None
    report["edit_mode"] = panel.mode_key()
    report["edit_min_feature"] = panel.min_feature.value()
    panel.theta.setValue(10.0)
    panel.refine.setChecked(False)
    panel.min_feature.setValue(0.25)
    panel.accept()
    settle(0.5)
    report["edited"] = {"theta": feature.Theta, "refine": feature.Refine, "status": feature.Status,
                        "min_feature": feature.MinFeature.Value,
                        "dialog_open": Gui.Control.activeDialog()}
    # Opened again, the panel shows what was saved.
    Gui.ActiveDocument.setEdit(feature.Name)
    settle(0.3)
    report["reedit_min_feature"] = task_panel.active_panel.min_feature.value()
    task_panel.active_panel.reject()
    settle(0.3)

    # The console one-liner gets the coloured view provider too.
    cube = doc.addObject("Part::Box", "Cube")
    cube.Placement.Base = App.Vector(0, 60, 0)
    doc.recompute()
    made = cadmedial.app.make_medial_axis(cube, samples=1000)
    settle(0.3)
    report["console"] = {
        "proxy": type(made.ViewObject.Proxy).__name__, "coloring": made.ViewObject.Coloring,
        "colors": len(made.RadiusColors), "points": made.Mesh.CountPoints}
    # A picked point says its radius in the status bar.
    from cadmedial.gui import picking
    p = feature.Mesh.Points[0]
    picking.observer.addSelection(doc.Name, feature.Name, "", (p.x, p.y, p.z))
    report["pick_message"] = picking.observer.last_message

    # One click zooms onto the thinnest wall.
    plate = doc.addObject("Part::Box", "Plate")
    plate.Length, plate.Width, plate.Height = 40.0, 40.0, 1.0
    plate.Placement.Base = App.Vector(0, -80, 0)
    doc.recompute()
    thin = cadmedial.app.make_medial_axis(plate, samples=2000)
    # Nothing selected: the click goes to the thinnest wall of the visible medial axes.
    Gui.Selection.clearSelection()
    view = Gui.ActiveDocument.ActiveView
    view.viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")
    settle(0.3)
    report["thinnest_wall_active_unselected"] = Gui.Command.get("MedialAxis_ThinnestWall").isActive()
    Gui.runCommand("MedialAxis_ThinnestWall")
    settle(0.5)
    from pivy import coin
    camera = view.getCameraNode()
    direction = camera.orientation.getValue().multVec(coin.SbVec3f(0, 0, -1))
    focal = camera.position.getValue() + direction * camera.focalDistance.getValue()
    from cadmedial.gui.wall_marker import NODE_NAME, marker
    marks = coin.SoSearchAction()
    marks.setName(NODE_NAME)
    marks.setInterest(coin.SoSearchAction.ALL)
    marks.apply(view.getSceneGraph())
    report["thinnest_wall"] = {"thickness": thin.ThinnestWall.Value,
                               "at": [thin.ThinnestWallAt.x, thin.ThinnestWallAt.y, thin.ThinnestWallAt.z],
                               "camera": view.getCamera(), "focal_point": list(focal.getValue()),
                               "marks_in_view": marks.getPaths().getLength(),
                               "mark_at": list(marker.point) if marker.point else None,
                               "status": mw.statusBar().currentMessage()}
    view.saveImage(os.path.join(OUT, "thinnest_wall.png"), 800, 600, "White")
    # Again: still one mark.
    Gui.runCommand("MedialAxis_ThinnestWall")
    marks.apply(view.getSceneGraph())
    report["thinnest_wall"]["marks_after_second_click"] = marks.getPaths().getLength()
    marker.clear()
    doc.removeObject(thin.Name)
    doc.removeObject(plate.Name)
    doc.recompute()

    # Save, close, reopen: the colours come back (pixels of the view).
    path = os.path.join(OUT, "reopen.FCStd")
    for o in doc.Objects:
        if o.Name != feature.Name and o.ViewObject is not None:
            o.ViewObject.Visibility = False
    doc.saveAs(path)
    App.closeDocument(doc.Name)
    settle(0.5)
    doc = App.openDocument(path)
    settle(1.5)
    view = Gui.ActiveDocument.ActiveView
    view.viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")
    settle(1.0)
    view.saveImage(os.path.join(OUT, "reopened.png"), 800, 600, "White")
    report["reopened_coloured_pixels_sampled"] = coloured_pixels(os.path.join(OUT, "reopened.png"))
    # The closed document's view can still be listed: read the legend of a visible view.
    shown = legend.first_legend(doc)
    report["reopened_legend"] = shown.text() if shown is not None and shown.isVisible() else None
    QtGui.QGuiApplication.primaryScreen().grabWindow(0).save(os.path.join(OUT, "reopened_workbench.png"))
    report["steps"].append("done")


def main():
    try:
        run()
        finish(0)
    except Exception:
        report["exception"] = traceback.format_exc()
        finish(1)


QtCore.QTimer.singleShot(1500, main)
