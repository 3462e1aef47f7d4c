"""Surface left uncovered by an axis's balls, counted two ways, per solid: the balls at the output
vertices only (as bench/measures.py's reconstruction error and hard_eval's judge count it) and
the balls along the output faces too (radius interpolated linearly over each triangle of the
fan-triangulated polygons, the medial surface the output describes).

On a wall thinner than the spacing, the mid-sheet's vertices are about a spacing apart and their
balls are a half-thickness wide, so the first count leaves most of the wall's faces uncovered
though the sheet spans them.

    /usr/bin/python3 bench/uncovered_faces.py OUT/seed_019.brep OUT/seed_019.ply
"""
import os
import sys

import numpy as np
from scipy.spatial import cKDTree

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [os.path.join(HERE, "..", "python")]
sys.path.append("/usr/lib/freecad/lib")


def surface_points(solid, n, rng, deflection):
    pts, tris = solid.tessellate(deflection)
    P, T = np.array([[p.x, p.y, p.z] for p in pts]), np.array(tris)
    a, b, c = P[T[:, 0]], P[T[:, 1]], P[T[:, 2]]
    area = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)
    pick = rng.choice(len(T), n, p=area / area.sum())
    u, v = rng.random(n), rng.random(n)
    flip = u + v > 1
    u[flip], v[flip] = 1 - u[flip], 1 - v[flip]
    return a[pick] + u[:, None] * (b[pick] - a[pick]) + v[:, None] * (c[pick] - a[pick])


def face_balls(V, R, triangles, spacing, rng):
    """Centres and radii on the triangles, about `spacing` apart, radii interpolated."""
    a, b, c = V[triangles[:, 0]], V[triangles[:, 1]], V[triangles[:, 2]]
    area = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)
    n = int(min(2_000_000, max(1000, area.sum() / spacing ** 2)))
    if not (area > 0).any():
        return V[:0], R[:0]
    pick = rng.choice(len(triangles), n, p=area / area.sum())
    u, v = rng.random(n), rng.random(n)
    flip = u + v > 1
    u[flip], v[flip] = 1 - u[flip], 1 - v[flip]
    t = triangles[pick]
    C = V[t[:, 0]] * (1 - u - v)[:, None] + V[t[:, 1]] * u[:, None] + V[t[:, 2]] * v[:, None]
    return C, R[t[:, 0]] * (1 - u - v) + R[t[:, 1]] * u + R[t[:, 2]] * v


def uncovered(Y, C, R, k=64):
    """max over Y of the distance to the union of balls (C, R): exact for each point over its k
    nearest centres, then over all centres for the points still above a thousandth of the worst."""
    d, i = cKDTree(C).query(Y, k=min(k, len(C)))
    e = (d - R[i]).min(axis=1)
    worst = 0.0
    for j in np.argsort(-e)[:200]:
        worst = max(worst, float((np.linalg.norm(C - Y[j], axis=1) - R).min()))
    return max(worst, 0.0)


def main():
    import FreeCAD  # noqa: F401 - before Part
    import Part
    import cadmedial
    shape = Part.Shape()
    shape.read(sys.argv[1])
    result = cadmedial.load(sys.argv[2])
    V, R = np.asarray(result.vertices), np.asarray(result.radius)
    diag = shape.BoundBox.DiagonalLength
    tri, tri_face = result.faces.triangulate()
    tri = np.asarray(tri, np.int64).reshape(-1, 3)
    face_solid = np.asarray(result.face_solid)[np.asarray(tri_face)]
    rng = np.random.default_rng(1)
    for k, solid in enumerate(shape.Solids):
        Y = surface_points(solid, 20000, rng, 0.002 * diag)
        mine = tri[face_solid == k]
        used = np.unique(mine)
        h = 0.002 * diag
        C, Rf = face_balls(V, R, mine, h, rng)
        at_vertices = uncovered(Y, V[used], R[used])
        on_faces = uncovered(Y, np.vstack([V[used], C]), np.concatenate([R[used], Rf]))
        print("solid %d: uncovered %.4f (%.3f %% of the diagonal) by the vertices' balls, %.4f (%.3f %%) "
              "with the faces' balls" % (k + 1, at_vertices, 100 * at_vertices / diag, on_faces, 100 * on_faces / diag))


if __name__ == "__main__":
    main()
