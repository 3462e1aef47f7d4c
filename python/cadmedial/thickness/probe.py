"""The thickness at one point by both methods, with what to draw: the ball and the ray."""

import numpy as np

from .. import _core
from .ray import outward_normal, ray_thickness_one
from .refine import START, _shrink
from .shape_source import solids_of
from .sphere import NEIGHBOURS, sphere_thickness


def _vector(p):
    import FreeCAD
    return FreeCAD.Vector(float(p[0]), float(p[1]), float(p[2]))


def least_power_balls(point, centres, radii, k=NEIGHBOURS):
    """(k,) int64 indices of the balls (V, 3), (V,) of least power |p - v|^2 - r^2 at point (3,):
    the candidates sphere_thickness's KD-tree query finds, found in O(V) with no tree, so that
    one point (a probe click) costs milliseconds on a large axis."""
    power = np.einsum("ij,ij->i", centres - point, centres - point) - radii * radii
    k = min(k, len(radii))
    return np.argpartition(power, k - 1)[:k] if k < len(radii) else np.arange(len(radii))


def probe(source, point, medial, face=None, reach=0.0):
    """Dict for the boundary point of ``source`` nearest ``point`` (3,): point, face (name),
    normal (outward), sphere (thickness: the exact largest tangent ball's diameter when
    ``exact``, else the medial reading), sphere_medial (the medial axis's reading), exact,
    ball_centre, ball_radius (of that ball), ray (thickness along the
    inward normal, nan if the ray finds no wall), ray_end. ``medial`` is the MedialAxisResult
    (or a ThicknessResult's .medial) of the same shape. ``face``: the name ("Face3") of the face
    the point lies on when the caller knows it (a pick): only that face is searched. ``reach``:
    as sphere_thickness's (the analysis passes its sample spacing, settings["spacing"])."""
    shape, solids = solids_of(source)
    p = _vector(point)
    best = None
    candidates = ([int(face[4:]) - 1] if face and face.startswith("Face")
                  else range(len(shape.Faces)))
    for i in candidates:
        d, pairs, _ = shape.Faces[i].distToShape(_vertex(p))
        if best is None or d < best[0]:
            q = pairs[0][0]
            best = (d, i, np.array([q.x, q.y, q.z]))
    _, i, q = best
    face = shape.Faces[i]
    normal = outward_normal(face, q)
    solid = next((s for s in solids if s.isInside(_vector(q - 1e-6 * normal * shape.BoundBox
                                                          .DiagonalLength), 0.0, True)),
                 solids[0])
    centres, radii = np.asarray(medial.vertices), np.asarray(medial.radius)
    near = least_power_balls(q, centres, radii)
    top = np.empty(1)  # the largest ball in reach: the shrinking ball's start, as in the analysis
    value, _, ball = sphere_thickness(q[None, :], centres[near], radii[near], reach=reach,
                                      upper=top)
    ball = near[ball]
    ball_centre = np.asarray(medial.vertices[ball[0]], dtype=np.float64)
    ball_radius = float(medial.radius[ball[0]])
    medial_value = float(value[0])
    # The exact largest ball tangent at q (refine.py's shrinking ball), as the analysis reads it;
    # where it cannot be confirmed the medial reading stands.
    exact = False
    if np.isfinite(top[0]) and top[0] > 0:
        core = _core.read_brep_string(solid.exportBrepToString())
        r, ok = _shrink(core, q[None, :], normal[None, :], np.array([START * top[0] / 2.0]),
                        shape.BoundBox.DiagonalLength)
        if ok[0]:
            exact = True
            ball_radius = float(r[0])
            ball_centre = q - ball_radius * normal
    ray = ray_thickness_one(solid, q, -normal, 2.0 * shape.BoundBox.DiagonalLength)
    return {"point": q.tolist(), "face": "Face%d" % (i + 1), "normal": normal.tolist(),
            "sphere": 2.0 * ball_radius if exact else medial_value, "sphere_medial": medial_value,
            "exact": exact, "ball_centre": [float(x) for x in ball_centre], "ball_radius": ball_radius,
            "ray": ray, "ray_end": (q - ray * normal).tolist() if np.isfinite(ray) else None}


def _vertex(p):
    import Part
    return Part.Vertex(p)
