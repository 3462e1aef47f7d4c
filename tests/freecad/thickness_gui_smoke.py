# Runs inside the FreeCAD GUI under Xvfb (see test_thickness_gui.py): runs the Wall thickness
# command on a plate with a thin rib (20000 medial axis samples), waits for the worker thread,
# records the regions listed; then sets the legend range (colours without an analysis), probes
# points by mouse clicks on the 3D view (thickness, the ball and ray nodes, the longest GUI stall
# by a 10 ms timer), clicks a region, exports CSV and HTML, and saves screenshots.
# Writes $CADMEDIAL_GUI_OUT/thickness.json; exits with os._exit.
import os
import time

import FreeCAD as App
import FreeCADGui as Gui
from PySide2 import QtCore, QtGui, QtWidgets
import sys  # noqa: E402
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # gui_heartbeat beside this script
from gui_heartbeat import Heartbeat, run_and_report  # noqa: E402

OUT = os.environ["CADMEDIAL_GUI_OUT"]
SAMPLES = 20000
# Points on the part and their exact sphere thickness: the plate's top far from the rib (4) and
# the rib's side half-way up (1).
PROBES = [((8.0, 5.0, 4.0), 4.0), ((20.5, 20.0, 9.0), 1.0), ((30.0, 10.0, 4.0), 4.0)]
report = {}


def spin(seconds):
    # The event loop runs as FreeCAD's own would: control returns to it between short waits.
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        loop = QtCore.QEventLoop()
        QtCore.QTimer.singleShot(20, loop.quit)
        loop.exec_()


def click(view, point):
    """A left click, as the window system sends it, on the view's pixel showing ``point``."""
    widget = view.graphicsView().viewport()
    x, y = view.getPointOnScreen(App.Vector(*point))
    # Coin's pixels (getSize) are device pixels with y up; Qt's events are widget pixels, y down.
    width, height = view.getSize()
    pos = QtCore.QPoint(int(round(x * widget.width() / width)),
                        int(round((height - 1 - y) * widget.height() / height)))
    for kind in (QtCore.QEvent.MouseButtonPress, QtCore.QEvent.MouseButtonRelease):
        QtWidgets.QApplication.sendEvent(widget, QtGui.QMouseEvent(
            kind, pos, QtCore.Qt.LeftButton, QtCore.Qt.LeftButton, QtCore.Qt.NoModifier))
    return pos.x(), pos.y()


def node_named(name):
    from pivy import coin
    search = coin.SoSearchAction()
    search.setName(coin.SbName(name))
    search.setInterest(coin.SoSearchAction.FIRST)
    search.apply(Gui.ActiveDocument.ActiveView.getSceneGraph())
    path = search.getPath()
    return None if path is None else path.getTail()


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
    task.samples.setValue(SAMPLES)
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
    obj = objs[0]
    report["samples"] = task.result.medial.stats.get("samples")
    report["medial_vertices"] = int(task.result.medial.num_vertices)
    report["surface_points"] = len(task.result.points)
    check_legend(doc, obj, task)
    check_probe(doc, obj, task)
    check_files(doc, task)
    del panel


def check_legend(doc, obj, task):
    import numpy as np
    from cadmedial.app import thickness_object
    from cadmedial.colormap import colors_of
    from cadmedial.gui import thickness_legend
    spin(0.3)
    shown = thickness_legend.legend_on(doc)
    report["legend"] = shown.text() if shown is not None and shown.isVisible() else None
    if shown is not None:
        parent = shown.parentWidget()
        report["legend_rect"] = [shown.x(), shown.y(), shown.width(), shown.height()]
        report["view_size"] = [parent.width(), parent.height()]
    values, counted = np.array(obj.Values), np.array(obj.Counted, bool)
    # A counted point of the plate, neither thin nor thick, away from the legend's ends.
    i = int(np.nonzero(counted & (np.abs(values - 4.0) < 0.01))[0][0])
    report["legend_vertex"] = {"value": float(values[i]), "before": list(obj.ThicknessColors[i])[:3]}
    calls = []
    original = thickness_object.analyse
    thickness_object.analyse = lambda o: calls.append(o.Name) or original(o)
    try:
        task.legend_min.setValue(3.0)
        task.legend_max.setValue(6.0)
        task.apply_legend()
        after = list(obj.ThicknessColors[i])[:3]
        doc.recompute()  # the legend touched the object: a recompute recolours, no analysis
    finally:
        thickness_object.analyse = original
    spin(0.3)
    report["legend_vertex"].update(after=after, recomputed=list(obj.ThicknessColors[i])[:3],
                                   expected=colors_of([values[i]], 3.0, 6.0)[0].tolist(),
                                   analyses=len(calls), state=list(obj.State))
    shown = thickness_legend.legend_on(doc)
    report["legend_after"] = shown.text() if shown is not None else None


def check_probe(doc, obj, task):
    from cadmedial.gui import thickness_probe
    view = Gui.ActiveDocument.ActiveView
    Gui.SendMsgToActiveView("ViewFit")
    spin(0.5)
    task.probe_button.setChecked(True)
    beat = Heartbeat()
    probes = []
    for point, exact in PROBES:
        before = task.probe.last
        spin(0.2)
        beat.reset()
        pixel = click(view, point)
        spin(0.3)
        hit = task.probe.last
        probes.append({"point": point, "exact": exact, "pixel": pixel,
                       "probed": hit is not before and hit is not None,
                       "sphere": hit and hit["sphere"], "ray": hit and hit["ray"],
                       "at": hit and hit["point"], "ball_radius": hit and hit["ball_radius"],
                       "probe_ms": hit and round(hit["ms"], 1),
                       "probe_cpu_ms": hit and round(hit["cpu_ms"], 1),
                       "pick_ms": round(task.probe.pick_ms or 0, 1),
                       "pick_cpu_ms": round(task.probe.pick_cpu_ms or 0, 1), "stall_ms": beat.gap()})
    report["probes"] = probes
    report["selection_after_clicks"] = [s.ObjectName for s in Gui.Selection.getSelectionEx()]
    Gui.Selection.clearSelection()
    redraws = []
    for _ in range(3):  # what one redraw alone costs (software OpenGL under Xvfb)
        spin(0.3)
        beat.reset()
        view.redraw()
        spin(0.3)
        redraws.append(beat.gap())
    report["redraw_stall_ms"] = max(redraws)
    report["redraws_ms"] = redraws
    beat.reset()
    click(view, (200.0, 200.0, 0.0))  # off the part
    spin(0.3)
    report["background_click_stall_ms"] = beat.gap()
    report["status_bar"] = Gui.getMainWindow().statusBar().currentMessage()
    report["probe_text"] = task.probe_text.text()
    # On the source solid (the mesh hidden): the pick names the B-rep face.
    obj.ViewObject.Visibility, task.source.ViewObject.Visibility = False, True
    spin(0.3)
    click(view, PROBES[0][0])
    spin(0.3)
    report["source_probe"] = {"face": task.probe.last["face"], "sphere": task.probe.last["sphere"],
                              "at": task.probe.last["point"]}
    obj.ViewObject.Visibility, task.source.ViewObject.Visibility = True, False
    ball = node_named(thickness_probe.BALL_NODE)
    report["ball_node"] = ball is not None
    report["last_ball_radius"] = task.probe.last["ball_radius"]
    report["ray_node"] = node_named(thickness_probe.RAY_NODE) is not None
    if ball is not None:
        from pivy import coin
        spheres = [ball.getChild(k) for k in range(ball.getNumChildren())
                   if ball.getChild(k).isOfType(coin.SoSphere.getClassTypeId())]
        report["ball_node_radius"] = spheres[0].radius.getValue() if spheres else None
    task.probe_button.setChecked(False)
    # The first probe's ball, seen: a screenshot with it drawn.
    task.probe.probe_at(PROBES[0][0])
    spin(0.5)
    view.saveImage(os.path.join(OUT, "thickness_probe.png"), 1000, 750, "White")
    Gui.getMainWindow().grab().save(os.path.join(OUT, "thickness_window.png"))  # with the legend
    # A region's click draws the ball at its extreme.
    task._show_region(task.regions.item(0))
    g = (task.result.thin_regions + task.result.thick_regions)[0]
    report["region_ball"] = {"extreme": g["extreme"], "at": g["at"],
                             "sphere": task.probe.last["sphere"],
                             "probed_at": task.probe.last["point"]}


def check_files(doc, task):
    from cadmedial.gui import thickness_export
    doc.saveAs(os.path.join(OUT, "Ribbed.FCStd"))
    report["dialog_folder"] = thickness_export.document_folder(doc)
    regions, faces = task.export_csv(os.path.join(OUT, "Ribbed-regions.csv"))
    report["regions_csv"] = open(regions).read()
    report["faces_csv"] = open(faces).read()
    html = task.export_html(os.path.join(OUT, "Ribbed-thickness.html"))
    report["html"] = open(html).read()
    report["result_min"] = task.result.statistics["min"]
    report["out"] = OUT


run_and_report(run, report, os.path.join(OUT, "thickness.json"))
