"""The sides of a triangle list, each once."""

import numpy as np


def mesh_sides(triangles):
    """(unique sides (S, 2) sorted pairs, (T, 3) side index of each triangle's sides a-b, b-c,
    c-a)."""
    raw = np.stack([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]], axis=1)
    raw = np.sort(raw.reshape(-1, 2), axis=1)
    # One int64 key per side: np.unique on rows (axis=0) is several times slower.
    n = np.int64(triangles.max() + 1)
    keys, inverse = np.unique(raw[:, 0] * n + raw[:, 1], return_inverse=True)
    sides = np.column_stack([keys // n, keys % n])
    return sides, inverse.reshape(-1, 3)
