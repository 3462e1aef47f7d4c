"""Points moved onto a face's surface: the nearest point of its (untrimmed) surface.

Closed forms, vectorised, on planes, cylinders, spheres, cones and tori; other surfaces
(B-splines, surfaces of revolution or extrusion, offsets) one point at a time through
OpenCASCADE's projection (Part's Surface.parameter, then value). The points lie within about the
tessellation's deflection of the surface (midpoints of mesh sides inside the face), where the
nearest point is the one on the face's own sheet.
"""

import numpy as np

CLOSED_FORMS = ("Plane", "Cylinder", "Sphere", "Cone", "Toroid")


def _array(v):
    return np.array([v.x, v.y, v.z], dtype=np.float64)


def _unit_rows(d):
    return d / np.maximum(np.linalg.norm(d, axis=1), 1e-300)[:, None]


def project_on_surface(surface, points):
    """(M, 3) the points (M, 3) moved onto ``surface`` (a Part geometry surface)."""
    points = np.asarray(points, dtype=np.float64)
    kind = type(surface).__name__
    if kind == "Plane":
        o, n = _array(surface.Position), _array(surface.Axis)
        n = n / np.linalg.norm(n)
        return points - ((points - o) @ n)[:, None] * n
    if kind in ("Cylinder", "Sphere"):  # (the expressions of the first closed forms, kept)
        c = _array(surface.Center)
        d = points - c
        if kind == "Cylinder":
            axis = _array(surface.Axis)
            along = (d @ axis)[:, None] * axis
            d = d - along
            c = c + along
        return c + surface.Radius * d / np.maximum(np.linalg.norm(d, axis=1), 1e-300)[:, None]
    if kind in ("Cone", "Toroid"):
        c, a = _array(surface.Center), _array(surface.Axis)
        a = a / np.linalg.norm(a)
        d = points - c
        z = d @ a
        radial = _unit_rows(d - z[:, None] * a)
        if kind == "Toroid":  # onto the tube's circle in the point's meridian plane, then out
            m = c + surface.MajorRadius * radial
            return m + surface.MinorRadius * _unit_rows(points - m)
        # Cone: onto the generator in the point's half-plane, a line through the apex.
        apex = _array(surface.Apex)
        u = _unit_rows(a + np.tan(surface.SemiAngle) * radial)
        w = points - apex
        return apex + np.einsum("ij,ij->i", w, u)[:, None] * u
    import FreeCAD
    out = np.empty_like(points)
    for j, p in enumerate(points):
        u, v = surface.parameter(FreeCAD.Vector(*map(float, p)))
        q = surface.value(u, v)
        out[j] = (q.x, q.y, q.z)
    return out
