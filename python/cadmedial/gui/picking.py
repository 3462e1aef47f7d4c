"""A point picked on a MedialAxis result shows the medial radius there in the status bar
(the radius of the nearest mesh vertex: the colours are per vertex, so this is the colour's
value)."""

import FreeCAD as App
import FreeCADGui as Gui
import numpy as np

from cadmedial.app import is_medial_axis, medial_result


def radius_at(obj, point):
    """(radius, distance to the nearest vertex) of a MedialAxis object's result at point."""
    result = medial_result(obj)
    if not result.num_vertices:
        raise ValueError("%s has no vertices" % obj.Label)
    offsets = result.vertices - np.asarray(point, dtype=float)
    nearest = int(np.argmin(np.einsum("ij,ij->i", offsets, offsets)))
    return float(result.radius[nearest]), float(np.linalg.norm(offsets[nearest]))


class PickObserver:
    """Gui.Selection observer: on a pick of a MedialAxis, the radius in the status bar."""

    last_message = ""

    def addSelection(self, doc_name, obj_name, sub, point):
        try:
            obj = App.getDocument(doc_name).getObject(obj_name)
        except Exception:
            return
        if obj is None or not is_medial_axis(obj) or point is None:
            return
        try:
            radius, _gap = radius_at(obj, point)
        except Exception:  # no result yet: nothing to say
            return
        self.last_message = "%s: medial radius %.4g mm (wall about %.4g mm) at (%.4g, %.4g, %.4g)" % (
            obj.Label, radius, 2 * radius, point[0], point[1], point[2])
        Gui.getMainWindow().statusBar().showMessage(self.last_message, 15000)


observer = PickObserver()


def install():
    Gui.Selection.addObserver(observer)
