"""A point picked on a MedialAxis result shows the medial radius there in the status bar: the
radii of the corners of the triangle under the point, interpolated as the per-vertex colours are
(the compact mesh's triangles are large: its nearest vertex can be far off, while the interpolated
ball is within Simplify of the full axis's); the nearest vertex's when no triangle is under it."""

import FreeCAD as App
import FreeCADGui as Gui
import numpy as np

from cadmedial.app import is_medial_axis, medial_result


def radius_at(obj, point):
    """(radius, distance) of a MedialAxis object's result at point: interpolated on the triangle
    nearest point among those it projects into (distance: to its plane), else the nearest
    vertex's (distance: to it)."""
    result = medial_result(obj)
    if not result.num_vertices:
        raise ValueError("%s has no vertices" % obj.Label)
    point = np.asarray(point, dtype=float)
    on_triangle = _interpolated(result, point)
    if on_triangle is not None:
        return on_triangle
    offsets = result.vertices - point
    nearest = int(np.argmin(np.einsum("ij,ij->i", offsets, offsets)))
    return float(result.radius[nearest]), float(np.linalg.norm(offsets[nearest]))


def _interpolated(result, point):
    """(radius, plane distance) on the nearest triangle whose inside point projects into, or None."""
    triangles = result.triangles()
    if not len(triangles):
        return None
    a, b, c = (result.vertices[triangles[:, k]] for k in range(3))
    ab, ac, ap = b - a, c - a, point - a
    # Barycentric coordinates of point's projection (Ericson, Real-Time Collision Detection 3.4).
    d00, d01, d11 = (np.einsum("ij,ij->i", x, y) for x, y in ((ab, ab), (ab, ac), (ac, ac)))
    d20, d21 = np.einsum("ij,ij->i", ap, ab), np.einsum("ij,ij->i", ap, ac)
    denominator = d00 * d11 - d01 * d01
    usable = denominator > 1e-12 * (d00 * d11 + 1e-300)  # not a sliver of zero area
    with np.errstate(divide="ignore", invalid="ignore"):
        v = (d11 * d20 - d01 * d21) / denominator
        w = (d00 * d21 - d01 * d20) / denominator
        u = 1.0 - v - w
        inside = usable & (u >= -1e-6) & (v >= -1e-6) & (w >= -1e-6)
    if not inside.any():
        return None
    normal = np.cross(ab, ac)
    with np.errstate(divide="ignore", invalid="ignore"):
        height = np.abs(np.einsum("ij,ij->i", ap, normal)) / np.linalg.norm(normal, axis=1)
    height[~inside] = np.inf
    best = int(np.argmin(height))
    r = result.radius[triangles[best]]
    return float(u[best] * r[0] + v[best] * r[1] + w[best] * r[2]), float(height[best])


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
