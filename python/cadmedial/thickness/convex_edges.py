"""Distance of the surface points to the solid's convex edges, where the sphere thickness goes
to zero: a ball tangent at a point a distance a from a convex edge of interior angle alpha
(between planar faces) is at most a * tan(alpha / 2) in radius."""

import numpy as np
from scipy.spatial import cKDTree

from .surface_mesh import _sides

# Faces meeting at less than this angle between their normals are tangent (a fillet's edge):
# the thickness is smooth across them.
SMOOTH_DEGREES = 10.0


def convex_edge_segments(mesh):
    """(segments (K, 2, 3), interior_angle (K,) radians) of the mesh sides that lie on a convex
    B-rep edge: two triangles of different faces, the second below the first's plane."""
    sides, tri_side = _sides(mesh.triangles)
    flat_side = tri_side.ravel()
    flat_tri = np.repeat(np.arange(len(mesh.triangles)), 3)
    order = np.argsort(flat_side, kind="stable")
    flat_side, flat_tri = flat_side[order], flat_tri[order]
    count = np.bincount(flat_side, minlength=len(sides))
    start = np.concatenate([[0], np.cumsum(count)[:-1]])
    two = np.nonzero(count == 2)[0]  # manifold sides; a non-manifold side is left out
    t1, t2 = flat_tri[start[two]], flat_tri[start[two] + 1]
    across = mesh.triangle_face[t1] != mesh.triangle_face[t2]
    two, t1, t2 = two[across], t1[across], t2[across]
    normals = mesh.triangle_normals()
    centre = mesh.points[mesh.triangles].mean(axis=1)
    n1, n2 = normals[t1], normals[t2]
    turn = np.arccos(np.clip(np.einsum("ij,ij->i", n1, n2), -1.0, 1.0))
    below = np.einsum("ij,ij->i", centre[t2] - centre[t1], n1) < 0
    convex = below & (turn > np.radians(SMOOTH_DEGREES))
    segs = mesh.points[sides[two[convex]]]
    return segs, np.pi - turn[convex]


def distance_to_convex_edges(mesh, step):
    """(distance (N,), interior_angle (N,)) from each surface point to the nearest convex edge
    (np.inf and angle pi when the solid has none). The edges are resampled every ``step``, so
    the distance is within step / 2 of the true one."""
    segs, angle = convex_edge_segments(mesh)
    n = len(mesh.points)
    if len(segs) == 0:
        return np.full(n, np.inf), np.full(n, np.pi)
    length = np.linalg.norm(segs[:, 1] - segs[:, 0], axis=1)
    pieces = np.maximum(np.ceil(length / step).astype(np.int64), 1)
    seg_of = np.repeat(np.arange(len(segs)), pieces + 1)
    first = np.concatenate([[0], np.cumsum(pieces + 1)[:-1]])
    t = (np.arange(len(seg_of)) - np.repeat(first, pieces + 1)) / np.repeat(pieces, pieces + 1)
    samples = segs[seg_of, 0] + t[:, None] * (segs[seg_of, 1] - segs[seg_of, 0])
    dist, nearest = cKDTree(samples).query(mesh.points)
    return dist, angle[seg_of[nearest]]


def edge_bound(distance, angle):
    """(N,) the sphere thickness a convex edge allows at that distance: 2 a tan(alpha / 2), the
    diameter of the largest ball tangent at the point that stays inside the edge's wedge."""
    return 2.0 * distance * np.tan(np.minimum(angle, np.pi * 0.999) / 2.0)
