"""The exact sphere thickness at surface points, from the medial reading as a start.

At a point p of a face with outward unit normal n, the balls inside the solid that contain p are
tangent there: centred at p - r n. The largest is found by shrinking (Ma, Bae, Choi and Kim's
shrinking ball): while the boundary's nearest point q to the centre lies closer than r, replace r
by the radius of the ball tangent at p through q, r' = |q - p|^2 / (2 (p - q) . n). Each r' is an
upper bound of the answer (no inscribed ball tangent at p holds a boundary point inside), and the
sequence falls to it: in one step between two planes or coaxial cylinders, in a few elsewhere.
Starting just above the medial ball's radius (exact since the engine measures radii on the
B-rep), most points end in one or two steps. The distances are the engine's exact ones
(_core.boundary_distance: its B-rep faces and edges, OpenCASCADE's projections; analytic
surfaces are projected in closed form there).

A value is returned only for a ball that was checked to lie inside: its centre's distance to the
boundary is at least r (1 - TOL). Points where that was not reached within the steps or the time
budget, or whose nearest boundary point lies on a B-rep edge (no normal) unless one face holds
both sides (a seam), keep the medial reading. (The caller leaves out points on an edge between
two faces: no ball is tangent there.)
"""

import time

import numpy as np

from .. import _core

# Faces meeting at an edge with normals closer than this (radians) are one smooth surface there.
SMOOTH_RADIANS = 1e-3
# Relative tolerance of the final check: the ball's centre lies at least r (1 - TOL) from the
# boundary. The returned radius is then within about TOL of the largest tangent ball's.
TOL = 1e-6
# The medial ball containing p (to CONTAIN_TOL, or by power) can be a little smaller than the
# tangent ball at p: start this much above it, and grow by GROW while the start ball still fits
# (a start below the answer would be returned as it is: shrinking only goes down).
START = 1.02
GROW = 1.5
MAX_GROW = 6
MAX_STEPS = 40
CHUNK = 8192


def _foot(solid, points, reach):
    """(exact boundary point (N, 3), outward normal (N, 3), on_face (N,) bool) of each point."""
    _, foot, face, normal = _core.boundary_distance(solid, points, np.full(len(points), reach))
    return foot, normal, face >= 0


def _shrink(solid, p, n, r, diag):
    """(radius (M,), ok (M,) bool) of the largest ball tangent at p (M, 3) with outward normal n
    inside the solid, from start radii r (M,)."""
    r = r.copy()
    ok = np.zeros(len(p), bool)
    state = np.zeros(len(p), np.int8)  # 0 growing the start, 1 shrinking, 2 done, 3 failed
    grown = np.zeros(len(p), np.int64)
    active = np.arange(len(p))
    for _ in range(MAX_GROW + MAX_STEPS):
        if not len(active):
            break
        c = p[active] - r[active, None] * n[active]
        d, q, _, _ = _core.boundary_distance(solid, c, r[active] * (1.0 + 1e-9))
        fits = d >= r[active] * (1.0 - TOL)
        growing = state[active] == 0
        # Still fits at the start: grow it (the answer is above), unless grown enough.
        grow = growing & fits & (grown[active] < MAX_GROW)
        gi = active[grow]
        r[gi] *= GROW
        grown[gi] += 1
        done = fits & ~grow
        ok[active[done]] = True
        state[active[done]] = 2
        # A grown ball that fits after MAX_GROW: the largest checked one is kept (a lower bound).
        shrink = ~fits
        si = active[shrink]
        w = q[shrink] - p[si]
        along = -np.einsum("ij,ij->i", w, n[si])
        bad = along <= 1e-12 * diag  # q behind p's tangent plane: no ball tangent at p through it
        r_new = np.where(bad, 0.0, np.einsum("ij,ij->i", w, w) / (2.0 * np.maximum(along, 1e-300)))
        state[si[bad]] = 3
        good = ~bad
        r[si[good]] = np.minimum(r[si[good]], r_new[good])
        state[si[good]] = 1
        active = active[state[active] < 2]
    return r, ok


def refine_thickness(solid, points, values, reach, diag, budget=np.inf, order=None,
                     edge_normals=None, start=None):
    """(values (N,), refined (N,) bool): the exact sphere thickness 2 r at each surface point
    (N, 3) of ``solid`` (a _core.Shape solid), starting from the medial reading ``values``
    (N,), within ``budget`` seconds. reach bounds how far a point lies from the B-rep (the
    mesh's deflection, say); diag the solid's size. Points are taken in ``order`` (indices, all
    by default), chunk by chunk until the budget is spent; the others keep their reading.
    edge_normals(indices, feet) -> (normals (M, 3), ok (M,)): for points whose nearest boundary
    point lies on a B-rep edge, the outward normal where one face holds both sides (a seam, a
    tangent edge); None: such points keep their reading. start (N,): the thickness to shrink
    from (sphere_thickness's upper reading), values by default."""
    points = np.asarray(points, dtype=np.float64)
    out = np.array(values, dtype=np.float64)
    start = out if start is None else np.asarray(start, dtype=np.float64)
    refined = np.zeros(len(points), bool)
    order = np.arange(len(points)) if order is None else np.asarray(order)
    t0 = time.perf_counter()
    for lo in range(0, len(order), CHUNK):
        if time.perf_counter() - t0 > budget:
            break
        idx = order[lo:lo + CHUNK]
        idx = idx[np.isfinite(start[idx]) & (start[idx] > 0)]
        if not len(idx):
            continue
        foot, normal, on_face = _foot(solid, points[idx], reach)
        if edge_normals is not None and not on_face.all():
            off = np.nonzero(~on_face)[0]
            n_edge, ok_edge = edge_normals(idx[off], foot[off])
            normal[off[ok_edge]] = n_edge[ok_edge]
            on_face[off[ok_edge]] = True
        idx, foot, normal = idx[on_face], foot[on_face], normal[on_face]
        r, ok = _shrink(solid, foot, normal, START * start[idx] / 2.0, diag)
        out[idx[ok]] = 2.0 * r[ok]
        refined[idx[ok]] = True
    return out, refined


def edge_normals_from_faces(faces, mesh):
    """edge_normals for refine_thickness: the exact normal of the face (Part.Face list, as
    mesh.triangle_face numbers them) around a mesh point on a seam; where the point's triangles
    lie on several faces, their normals must agree. Its sign is the mesh's (outward by the
    right-hand rule): Face.normalAt ignores a reversed face."""
    import FreeCAD

    tri_normal = mesh.triangle_normals()
    order = np.argsort(mesh.triangles.ravel(), kind="stable")
    corner_point = mesh.triangles.ravel()[order]
    corner_tri = order // 3
    start = np.searchsorted(corner_point, np.arange(len(mesh.points) + 1))

    def normals(indices, feet):
        out = np.zeros((len(indices), 3))
        ok = np.zeros(len(indices), bool)
        for k, (i, q) in enumerate(zip(indices.tolist(), feet)):
            tris = corner_tri[start[i]:start[i + 1]]
            if not len(tris):
                continue
            around = tri_normal[tris].sum(axis=0)
            v = FreeCAD.Vector(*map(float, q))
            ns = []
            for f in np.unique(mesh.triangle_face[tris]).tolist():
                face = faces[f]
                u, w = face.Surface.parameter(v)
                n = face.normalAt(u, w)
                if not n.Length > 0:
                    break
                n = np.array([n.x, n.y, n.z]) / n.Length
                ns.append(n if float(n @ around) > 0 else -n)
            else:
                if ns and all(float(n @ ns[0]) > np.cos(SMOOTH_RADIANS) for n in ns):
                    out[k], ok[k] = ns[0], True
        return out, ok

    return normals
