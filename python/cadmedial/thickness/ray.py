"""Ray thickness: from a surface point along the inward normal to the opposite wall, intersected
with the exact B-rep by OpenCASCADE (BRepAlgoAPI_Section through Part's Shape.section).

This is what most CAD tools call "ray" thickness; on a wall tilted against the ray it reads more
than the wall (a 2 mm slab read along a direction 30 degrees off its normal gives 2.31), but
along the exact normal it equals the sphere thickness wherever the walls are parallel."""

import numpy as np

from .shape_source import import_part


def _vector(p):
    import FreeCAD
    return FreeCAD.Vector(float(p[0]), float(p[1]), float(p[2]))


def outward_normal(face, point):
    """(3,) unit outward normal of ``face`` (a Part.Face, orientation taken into account) at its
    point nearest to ``point``."""
    u, v = face.Surface.parameter(_vector(point))
    n = face.normalAt(u, v)
    return np.array([n.x, n.y, n.z]) / max(n.Length, 1e-300)


def ray_thickness_one(solid, point, inward, length, start=1e-7):
    """Distance from ``point`` along the unit ``inward`` direction to the first boundary crossing
    of ``solid`` past start * length; np.nan when the ray meets nothing (it started outside)."""
    Part = import_part()
    p = np.asarray(point, dtype=np.float64)
    d = np.asarray(inward, dtype=np.float64)
    d = d / np.linalg.norm(d)
    a, b = p + start * length * d, p + length * d
    edge = Part.makeLine(_vector(a), _vector(b))
    hits = solid.section(edge).Vertexes
    if not hits:
        return float("nan")
    q = np.array([(v.Point.x, v.Point.y, v.Point.z) for v in hits])
    t = (q - p) @ d
    t = t[t > start * length * 2]
    return float(t.min()) if len(t) else float("nan")


def ray_thickness(solid, points, inward):
    """(N,) ray thickness of points (N, 3) along their unit inward directions (N, 3)."""
    box = solid.BoundBox
    length = 2.0 * box.DiagonalLength
    return np.array([ray_thickness_one(solid, p, d, length) for p, d in zip(points, inward)])
