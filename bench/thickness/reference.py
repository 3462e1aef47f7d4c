"""The exact reference for sphere thickness: a shrinking ball on the B-rep, per point.

Start from the ball tangent at p whose diameter is the ray to the opposite wall (OpenCASCADE
section of the inward normal line), then, while the boundary comes closer to its centre than its
radius (BRepExtrema_DistShapeShape through Part's distToShape), replace it by the ball tangent at
p through that nearest boundary point q: r' = |q - p|^2 / (2 (q - p) . d). The radii decrease to
the largest ball tangent at p inside the solid (Ma, Bae, Choi and Kim's shrinking ball, 2012).
This is what a per-point add-on does; it is the reference, not the method."""

import numpy as np

import FreeCAD
import Part

from cadmedial.thickness.ray import ray_thickness_one

V = FreeCAD.Vector


def exact_point_and_normal(face, p):
    """(point on the face nearest p, its unit outward normal)."""
    u, v = face.Surface.parameter(V(*p))
    q = face.Surface.value(u, v)
    n = face.normalAt(u, v)
    return np.array([q.x, q.y, q.z]), np.array([n.x, n.y, n.z]) / n.Length


def shrinking_ball(solid, boundary, p, normal, diag, rel_tol=1e-9, max_steps=60):
    """(thickness = 2 r, steps) at boundary point p (3,) with outward unit normal (3,)."""
    d = -normal
    ray = ray_thickness_one(solid, p, d, 2.0 * diag)
    r = ray / 2.0 if np.isfinite(ray) and ray > 0 else diag
    for step in range(max_steps):
        c = p + r * d
        dist, pairs, _ = boundary.distToShape(Part.Vertex(V(*c)))
        if dist >= r * (1.0 - 1e-7):
            return 2.0 * r, step
        q = np.array(tuple(pairs[0][0]))
        w = q - p
        along = float(w @ d)
        if along <= 1e-12 * diag:
            # q is p itself (to tolerance): the ball touches the boundary only at p.
            return 2.0 * r, step
        r_new = float(w @ w) / (2.0 * along)
        if r_new >= r * (1.0 - rel_tol):
            return 2.0 * r_new, step
        r = r_new
    return 2.0 * r, max_steps
