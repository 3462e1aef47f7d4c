# Runs inside the FreeCAD GUI (`freecad gui_color_range.py`, under Xvfb; see
# test_color_range_gui.py): a box's medial axis, then a colour range set by hand
# (ColorRangeMin/Max), the automatic one again, the set one after save and reopen. Writes what the
# radius legend's ticks and lines say at each step, and the longest stall of the GUI (10 ms
# heartbeat) while recolouring, to $CADMEDIAL_GUI_OUT/color_range.json, plus window grabs.
#   CADMEDIAL_RANGE_SAMPLES  samples of the box (default 3000; 300000 measures a big mesh)
import os
import sys
import time

import FreeCAD as App
import FreeCADGui as Gui
from PySide2 import QtCore, QtGui, QtWidgets

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # gui_heartbeat beside this script
from gui_checks import cut_off  # noqa: E402
from gui_heartbeat import Heartbeat, run_and_report  # noqa: E402

OUT = os.environ["CADMEDIAL_GUI_OUT"]
SAMPLES = int(os.environ.get("CADMEDIAL_RANGE_SAMPLES", "3000"))
report = {"samples": SAMPLES}


def settle(seconds=0.5):
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        QtWidgets.QApplication.processEvents(QtCore.QEventLoop.AllEvents, 50)
        time.sleep(0.02)


def legend_state(doc):
    from cadmedial.gui import legend
    shown = legend.first_legend(doc)
    if shown is None or not shown.isVisible():
        return None
    return {"ticks": [tick.text() for tick in shown.ticks], "lines": shown.lines.text()}


def shown_colour(vobj, index):
    """The colour the 3D view's material node gives mesh point `index` (what is drawn)."""
    from pivy import coin
    search = coin.SoSearchAction()
    search.setType(coin.SoMaterial.getClassTypeId())
    search.setInterest(coin.SoSearchAction.ALL)
    search.apply(vobj.RootNode)
    for i in range(search.getPaths().getLength()):
        colours = search.getPaths().get(i).getTail().diffuseColor
        if colours.getNum() > index:
            return [round(c, 4) for c in colours[index].getValue()]
    return None


def grab(name):
    QtGui.QGuiApplication.primaryScreen().grabWindow(0).save(os.path.join(OUT, name))


def timed_set(beat, change):
    """Runs change(), lets the GUI draw the new colours; returns (seconds change() took,
    longest stall ms till the view is drawn)."""
    settle(0.3)
    beat.reset()
    started = time.monotonic()
    change()
    seconds = time.monotonic() - started
    settle(1.5)
    return round(seconds, 3), beat.gap()


def run():
    mw = Gui.getMainWindow()
    mw.setGeometry(QtGui.QGuiApplication.primaryScreen().availableGeometry())
    mw.findChild(QtWidgets.QMdiArea).closeAllSubWindows()  # the Start page
    Gui.activateWorkbench("MedialAxisWorkbench")
    import cadmedial.app
    doc = App.newDocument("Range")
    box = doc.addObject("Part::Box", "Box")
    box.Length, box.Width, box.Height = 10.0, 20.0, 30.0
    doc.recompute()
    # The full axis: the checks need a vertex of every radius (the compact mesh has few).
    feature = cadmedial.app.make_medial_axis(box, samples=SAMPLES, simplify=0.0)
    box.ViewObject.Visibility = False
    view = Gui.ActiveDocument.ActiveView
    view.viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")
    settle(1.0)
    report["vertices"] = feature.VertexCount
    report["radius"] = [feature.RadiusMin.Value, feature.RadiusMax.Value]
    report["automatic"] = legend_state(doc)
    grab("range_automatic.png")

    beat = Heartbeat()

    def set_range():
        feature.ColorRangeMin = 1.0
        feature.ColorRangeMax = 3.0
    report["set_seconds"], report["set_stall_ms"] = timed_set(beat, set_range)
    report["set"] = legend_state(doc)
    # The point whose radius is nearest the range's middle, 2: drawn in the map's middle colour.
    from cadmedial.app import medial_result
    radius = medial_result(feature).radius
    middle = int(abs(radius - 2.0).argmin())
    report["middle_radius"] = float(radius[middle])
    report["middle_shown"] = shown_colour(feature.ViewObject, middle)
    report["set_properties"] = [feature.AutoColorRange, feature.ColorRangeMin.Value,
                                feature.ColorRangeMax.Value, "Touched" in feature.State]
    grab("range_set.png")

    # What one new end costs: the colours alone (numpy), the whole change, and for scale the
    # redraw of the mesh when the view turns.
    from cadmedial.app.color_range import radius_colors
    started = time.monotonic()
    radius_colors(medial_result(feature).radius, 1.0, 3.5)
    report["colours_seconds"] = round(time.monotonic() - started, 3)

    def one_end():
        feature.ColorRangeMax = 3.5
    report["one_end_seconds"], report["one_end_stall_ms"] = timed_set(beat, one_end)
    _, report["turn_stall_ms"] = timed_set(beat, view.viewRight)
    view.viewIsometric()
    feature.ColorRangeMax = 3.0
    settle(1.0)

    def automatic():
        feature.AutoColorRange = True
    report["auto_seconds"], report["auto_stall_ms"] = timed_set(beat, automatic)
    report["automatic_again"] = legend_state(doc)
    report["middle_shown_automatic"] = shown_colour(feature.ViewObject, middle)

    # The task panel on the object: its Colours rows show the range in use and set one.
    Gui.ActiveDocument.setEdit(feature.Name)
    settle(0.5)
    from cadmedial.gui import task_panel
    rows = task_panel.active_panel.colors
    report["rows_loaded"] = [rows.automatic.isChecked(), rows.low.isEnabled(), rows.low.value(),
                             rows.high.value()]
    rows.automatic.setChecked(False)
    rows.low.setValue(1.5)
    rows.low.editingFinished.emit()
    rows.high.setValue(2.5)
    rows.high.editingFinished.emit()
    settle(0.5)
    report["rows_set"] = {"object": [feature.AutoColorRange, feature.ColorRangeMin.Value,
                                     feature.ColorRangeMax.Value, "Touched" in feature.State],
                          "legend": legend_state(doc), "shown": shown_colour(feature.ViewObject, middle),
                          "panel_width": task_panel.active_panel.form.width(),
                          "cut_off": cut_off(task_panel.active_panel.form)}
    task_panel.active_panel.form.grab().save(os.path.join(OUT, "range_panel.png"))
    task_panel.active_panel.reject()
    settle(0.3)
    report["rows_dialog_open_after_cancel"] = Gui.Control.activeDialog()

    set_range()
    settle(0.5)
    path = os.path.join(OUT, "range.FCStd")
    doc.saveAs(path)
    App.closeDocument(doc.Name)
    settle(0.5)
    doc = App.openDocument(path)
    settle(2.0)
    report["reopened"] = legend_state(doc)
    grab("range_reopened.png")


QtCore.QTimer.singleShot(1500, lambda: run_and_report(run, report, os.path.join(OUT, "color_range.json")))
