"""Sphere (rolling ball) thickness of surface points from the medial balls.

The thickness at a boundary point p is the diameter of the largest ball inside the solid that
contains p; every such ball lies in a medial ball touching p, so it is 2 max{r_v : p in B(v, r_v)}
over the medial axis's vertices v. A boundary point cannot lie deep inside an inner ball, so the
balls containing p are those whose sphere passes through it, and they have the smallest power
|p - v|^2 - r_v^2 at p. The power is a distance in 4-D once the balls are lifted to
(v, sqrt(R^2 - r_v^2)) with R the largest radius: the k balls of least power are a k-nearest
query in a KD-tree, with no radius search over large balls.
"""

import numpy as np
from scipy.spatial import cKDTree

# Balls whose distance to p is within this fraction of their radius count as containing it.
CONTAIN_TOL = 0.01
# Exact medial balls touch the boundary at one point each, and p lies between the touching
# points of the balls around it: a ball tangent a distance a from p has power exactly a^2 at p,
# whatever its radius, so a ball of power up to reach^2 (reach: the spacing of the touching
# points, the sampling's) is one touching p's neighbourhood. A relative test alone failed small
# balls: near a convex edge p fell outside all of them and read a third under the edge's bound.
# Candidates per point, in increasing power: enough to pass the many small balls of an edge's
# sheet (a box's rims: nine of r 0.32 before the first of 0.66, spacing 0.30).
NEIGHBOURS = 24
CHUNK = 65536


def sphere_thickness(points, centres, radii, tol=CONTAIN_TOL, k=NEIGHBOURS, reach=0.0):
    """(thickness (N,), gap (N,), ball (N,) int64 index of the ball used) for points (N, 3) from balls centres (V, 3), radii (V,).

    thickness = 2 max r_v over the balls of the k least-power ones that contain the point to
    within tol (|p - v| <= r_v (1 + tol)) or of power at most reach^2; where none does (exact balls touch the boundary at
    one point each and p lies between), 2 r_v of the least-power ball. gap = (|p - v| - r_v) / r_v
    of the ball used: how far outside it p lies (<= tol where a ball contains it)."""
    points = np.asarray(points, dtype=np.float64)
    centres = np.asarray(centres, dtype=np.float64)
    radii = np.asarray(radii, dtype=np.float64)
    if len(centres) == 0:
        raise ValueError("no medial balls")
    big = float(radii.max())
    lifted = np.column_stack([centres, np.sqrt(np.maximum(big * big - radii * radii, 0.0))])
    tree = cKDTree(lifted)
    k = min(k, len(centres))
    thickness = np.empty(len(points))
    gap = np.empty(len(points))
    ball = np.empty(len(points), dtype=np.int64)
    for lo in range(0, len(points), CHUNK):
        p = points[lo:lo + CHUNK]
        _, idx = tree.query(np.column_stack([p, np.zeros(len(p))]), k=k, workers=2)
        idx = idx.reshape(len(p), k)
        r = radii[idx]
        d = np.linalg.norm(centres[idx] - p[:, None, :], axis=2)
        rel = (d - r) / np.maximum(r, 1e-300)
        contains = (rel <= tol) | (d * d - r * r <= reach * reach)
        r_in = np.where(contains, r, -np.inf)
        best = np.argmax(r_in, axis=1)
        none = ~contains.any(axis=1)
        best[none] = 0  # least power
        rows = np.arange(len(p))
        thickness[lo:lo + CHUNK] = 2.0 * r[rows, best]
        gap[lo:lo + CHUNK] = rel[rows, best]
        ball[lo:lo + CHUNK] = idx[rows, best]
    return thickness, gap, ball
