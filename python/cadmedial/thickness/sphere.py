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
# Leaves of 64 lifted balls, and the points asked in the order of a KD-tree over them (neighbours
# one after the other): 0.94, 0.64, 0.33 s of CPU for 2.15, 1.26, 0.48 s with leaves of 16 in the
# given order (CTC 01, holesInFace2, io1-cm-214, 2026-12-08). The same candidates except
# where the 24th least power is a tie (the cut then keeps another of the tied balls: 20 of
# holesInFace2's 24,362 points read differently, none of the two others').
LEAFSIZE = 64
# The reading itself: the mean of the containing balls' radii weighted by
# exp(-(a / (SIGMA * reach))^2), a = sqrt(power) the distance from p to where each ball touches
# (exact balls: power a^2). The largest containing ball (kept as `upper`: the refinement's start,
# and the reading on edges) read 13-33 % p95 over on parts whose walls are about one spacing
# thick, where the thickness changes within a spacing: against the exact values at their face
# points (2026-12-08) io1-cm-214, strange_part_with_holes, holesInFace2, CTC 01 read p95 30.0,
# 33.0, 13.5, 27.5 % by the largest ball and 9.4, 6.4, 2.6, 8.9 % by the weighted mean; tilted
# slab, rib on plate, tube, filleted corner 0.32, 0.10, 0.13, 3.7 % and 1.29, 1.15, 0.50, 0.81 %.
# The least-power ball alone reads under (15.7, 8.6, 4.5, 10.2 % on the parts): the engine's
# vertices are Voronoi vertices of the samples, off the medial surface, and a ball centred off it
# (its radius the exact distance) is smaller than the medial ball at its foot.
SIGMA = 0.5


def sphere_thickness(points, centres, radii, tol=CONTAIN_TOL, k=NEIGHBOURS, reach=0.0,
                     upper=None):
    """(thickness (N,), gap (N,), ball (N,) int64 index of the ball used) for points (N, 3) from balls centres (V, 3), radii (V,).

    upper = 2 max r_v over the balls of the k least-power ones that contain the point to
    within tol (|p - v| <= r_v (1 + tol)) or of power at most reach^2; where none does (exact balls touch the boundary at
    one point each and p lies between), 2 r_v of the least-power ball; that ball is the one
    used. thickness = upper when reach is 0, else 2 sum w r_v / sum w over the containing balls
    of the k with w = exp(-(a / (SIGMA reach))^2), a = sqrt(max(power, 0)) (see SIGMA). gap = (|p - v| - r_v)
    / r_v of the ball used: how far outside it p lies (<= tol where a ball contains it).
    ``upper``: an (N,) array to receive upper, or None."""
    points = np.asarray(points, dtype=np.float64)
    centres = np.asarray(centres, dtype=np.float64)
    radii = np.asarray(radii, dtype=np.float64)
    if len(centres) == 0:
        raise ValueError("no medial balls")
    big = float(radii.max())
    lifted = np.column_stack([centres, np.sqrt(np.maximum(big * big - radii * radii, 0.0))])
    tree = cKDTree(lifted, leafsize=LEAFSIZE)
    k = min(k, len(centres))
    thickness = np.empty(len(points))
    gap = np.empty(len(points))
    ball = np.empty(len(points), dtype=np.int64)
    order = cKDTree(points, leafsize=LEAFSIZE).indices if len(points) > 1 else np.arange(len(points))
    for lo in range(0, len(points), CHUNK):
        at = order[lo:lo + CHUNK]
        p = points[at]
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
        top = 2.0 * r[rows, best]
        if upper is not None:
            upper[at] = top
        if reach > 0:
            power = np.maximum(d * d - r * r, 0.0) / (SIGMA * reach) ** 2
            power = np.where(contains, power, np.inf)
            least = np.where(none, 0.0, power.min(axis=1))[:, None]  # its weight 1: no underflow
            w = np.exp(-(power - least))
            w[none, 0] = 1.0  # no ball contains p: the least-power one alone, as for upper
            top = 2.0 * np.einsum("ij,ij->i", w, r) / w.sum(axis=1)
        thickness[at] = top
        gap[at] = rel[rows, best]
        ball[at] = idx[rows, best]
    return thickness, gap, ball
