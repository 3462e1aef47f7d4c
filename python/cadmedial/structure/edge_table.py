"""The edges of the axis's polygons: each distinct vertex pair once, with the faces that hold it."""

import numpy as np


class EdgeTable:
    """Polygon edges of a Faces (CSR) mesh.

    pairs       (E, 2) int64 vertex indices of each edge, smaller first
    face_start  (E+1,) int64: the faces holding edge e are faces[face_start[e]:face_start[e+1]]
    faces       (S,) int64 face indices, each face at most once per edge
    count       (E,) int64 number of distinct faces holding each edge
    """

    def __init__(self, pairs, face_start, faces):
        self.pairs = pairs
        self.face_start = face_start
        self.faces = faces
        self.count = np.diff(face_start)

    def __len__(self):
        return len(self.pairs)

    def faces_of(self, e):
        return self.faces[self.face_start[e]:self.face_start[e + 1]]

    def first_faces(self, edges):
        """(len(edges),) the first face of each edge (the only one of a one-face edge)."""
        return self.faces[self.face_start[edges]]


def edge_table(faces, num_vertices):
    """EdgeTable of ``faces`` (a result.Faces): one edge per polygon side (v[i], v[i+1]), the
    closing side included. A side whose two ends are the same vertex (a repeated index) is no
    edge; a face that holds the same edge twice counts once for it."""
    offsets = np.asarray(faces.offsets, dtype=np.int64)
    corners = np.asarray(faces.indices, dtype=np.int64)
    sizes = np.diff(offsets)
    side_face = np.repeat(np.arange(len(sizes), dtype=np.int64), sizes)
    following = np.arange(1, len(corners) + 1, dtype=np.int64)
    following[offsets[1:][sizes > 0] - 1] = offsets[:-1][sizes > 0]  # the closing side
    a, b = corners, corners[following]
    keep = a != b
    lo, hi, side_face = np.minimum(a, b)[keep], np.maximum(a, b)[keep], side_face[keep]
    n = np.int64(max(num_vertices, 1))
    # One key per (edge, face): sorting by it groups an edge's faces and drops repeats.
    edge_key = lo * n + hi
    order = np.lexsort((side_face, edge_key))
    edge_key, side_face = edge_key[order], side_face[order]
    fresh = np.ones(len(edge_key), dtype=bool)
    fresh[1:] = (edge_key[1:] != edge_key[:-1]) | (side_face[1:] != side_face[:-1])
    edge_key, side_face = edge_key[fresh], side_face[fresh]
    starts = np.flatnonzero(np.r_[True, edge_key[1:] != edge_key[:-1]]) if len(edge_key) else \
        np.zeros(0, dtype=np.int64)
    keys = edge_key[starts]
    pairs = np.stack([keys // n, keys % n], axis=1)
    face_start = np.r_[starts, len(edge_key)].astype(np.int64)
    return EdgeTable(pairs, face_start, side_face)
