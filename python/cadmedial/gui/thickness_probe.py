"""Probe thickness: a click on the part (its WallThickness mesh or its source solid) reads the
thickness there by both methods (thickness/probe.py) and draws the inscribed ball (a transparent
SoSphere) and the ray along the inward normal (an SoLineSet) in the 3D view.

The click is a Coin3D SoEventCallback on the view; the probe runs on the GUI thread because it
is a few milliseconds: one face's projection, a linear scan of the balls' power (no KD-tree
build) and one OpenCASCADE line section (measured in tests/freecad/thickness_gui_smoke.py)."""

import time

import FreeCADGui as Gui
import numpy as np
from pivy import coin

from cadmedial.thickness import probe

PROBE_NODE = "cadmedial_thickness_probe"
BALL_NODE = "cadmedial_thickness_ball"
RAY_NODE = "cadmedial_thickness_ray"
BALL_RGB, BALL_TRANSPARENCY = (0.15, 0.55, 1.0), 0.65
RAY_RGB = (0.95, 0.45, 0.0)


def face_of_point(result, index):
    """Name of a B-rep face holding the analysis's mesh point ``index``."""
    tri = np.nonzero((result.triangles == index).any(axis=1))[0]
    return result.face_names[result.triangle_face[tri[0]]] if len(tri) else None


def probe_message(hit):
    ray = ("%.4g mm" % hit["ray"]) if np.isfinite(hit["ray"]) else "no opposite wall"
    p = hit["point"]
    return ("Thickness at (%.4g, %.4g, %.4g) on %s: sphere %.4g mm, ray %s"
            % (p[0], p[1], p[2], hit["face"], hit["sphere"], ray))


class ProbeMarks:
    """The ball and the ray of the last probe in one view's scene graph (one SoSeparator)."""

    def __init__(self):
        self.root = None
        self.graph = None

    def show(self, view, hit):
        self.clear()
        # The inscribed ball and the ray lie inside the part: an annotation is drawn after the
        # scene without the depth test, so they show through the surface.
        root = coin.SoAnnotation()
        root.setName(PROBE_NODE)
        ball = coin.SoSeparator()
        ball.setName(BALL_NODE)
        material = coin.SoMaterial()
        material.diffuseColor = BALL_RGB
        material.transparency = BALL_TRANSPARENCY
        place = coin.SoTranslation()
        place.translation = tuple(hit["ball_centre"])
        sphere = coin.SoSphere()
        sphere.radius = hit["ball_radius"]
        for node in (material, place, sphere):
            ball.addChild(node)
        root.addChild(ball)
        end = hit["ray_end"] or hit["point"]
        ray = coin.SoSeparator()
        ray.setName(RAY_NODE)
        colour = coin.SoBaseColor()
        colour.rgb = RAY_RGB
        style = coin.SoDrawStyle()
        style.lineWidth = 3
        style.pointSize = 7
        points = coin.SoCoordinate3()
        points.point.setValues(0, 2, [tuple(hit["point"]), tuple(end)])
        line = coin.SoLineSet()
        line.numVertices = 2
        ends = coin.SoPointSet()
        for node in (colour, style, points, line, ends):
            ray.addChild(node)
        root.addChild(ray)
        self.graph = view.getSceneGraph()
        self.graph.addChild(root)
        self.root = root

    def clear(self):
        if self.root is not None and self.graph is not None:
            try:
                self.graph.removeChild(self.root)
            except Exception:  # the view was closed
                pass
        self.root = self.graph = None


class _NoSelection:
    def allow(self, doc, obj, sub):
        return False


class ThicknessProbe:
    """Probes a ThicknessResult of ``source`` (its shape as analysed); on_probe(hit, ms) is called
    after each probe (the panel shows it)."""

    def __init__(self, shape, result, source, wall=None, on_probe=None):
        self.shape, self.result, self.source, self.wall = shape, result, source, wall
        self.on_probe = on_probe
        self.marks = ProbeMarks()
        self.view = None
        self._callback = None
        self._pressed = False
        self.pick_ms = None  # the last click's ray pick (getObjectInfo), for the stall test
        self.pick_cpu_ms = None  # the same in the GUI thread's CPU time (not inflated by load)
        self.last = None
        from scipy.spatial import cKDTree
        self._points = cKDTree(result.points)

    def probe_at(self, point, face=None):
        """Probes the boundary point nearest ``point``; face: the B-rep face name if known.
        Returns the probe's dict (see thickness.probe) with "ms", the time it took, and
        "cpu_ms", the GUI thread's CPU time it took."""
        started, started_cpu = time.perf_counter(), time.thread_time()
        if face is None:
            face = face_of_point(self.result, int(self._points.query(point)[1]))
        hit = probe(self.shape, point, self.result.medial, face=face,
                    reach=self.result.settings["spacing"])
        view = Gui.ActiveDocument.ActiveView if Gui.ActiveDocument else None
        if view is not None and hasattr(view, "getSceneGraph"):
            self.marks.show(view, hit)
        hit["ms"] = 1000.0 * (time.perf_counter() - started)
        hit["cpu_ms"] = 1000.0 * (time.thread_time() - started_cpu)
        self.last = hit
        Gui.getMainWindow().statusBar().showMessage(probe_message(hit), 30000)
        if self.on_probe is not None:
            self.on_probe(hit)
        return hit

    # The click mode: a left click on the source or the thickness mesh probes there; a selection
    # gate keeps the clicks from selecting (a selection rebuilds the property view: slow).
    def start(self, view):
        self.stop()
        self.view = view
        self._callback = view.addEventCallbackPivy(coin.SoMouseButtonEvent.getClassTypeId(),
                                                   self._on_mouse)
        Gui.Selection.addSelectionGate(_NoSelection())

    def stop(self):
        if self._callback is not None:
            Gui.Selection.removeSelectionGate()
        if self._callback is not None and self.view is not None:
            try:
                self.view.removeEventCallbackPivy(coin.SoMouseButtonEvent.getClassTypeId(),
                                                  self._callback)
            except Exception:  # the view was closed
                pass
        self._callback = self.view = None

    @property
    def active(self):
        return self._callback is not None

    def _on_mouse(self, node):
        event = node.getEvent()
        if event.getButton() != coin.SoMouseButtonEvent.BUTTON1:
            return
        if event.getState() != coin.SoButtonEvent.DOWN:
            if self._pressed:  # the release of a probing press: not a selection either
                node.setHandled()
            self._pressed = False
            return
        started, started_cpu = time.perf_counter(), time.thread_time()
        x, y = event.getPosition().getValue()
        info = self.view.getObjectInfo((int(x), int(y)))  # a ray pick: the press only
        names = {self.source.Name} | ({self.wall.Name} if self.wall is not None else set())
        self._pressed = bool(info) and info.get("Object") in names
        if not self._pressed:
            return
        node.setHandled()  # a probe, not a selection
        self.pick_ms = 1000.0 * (time.perf_counter() - started)
        self.pick_cpu_ms = 1000.0 * (time.thread_time() - started_cpu)
        # A pick on the source names its face; one on the mesh says "Main": the face is then
        # that of the nearest analysed point.
        component = info.get("Component") or ""
        face = component if info["Object"] == self.source.Name and component.startswith("Face") else None
        self.probe_at(np.array([info["x"], info["y"], info["z"]]), face)

    def close(self):
        self.stop()
        self.marks.clear()
