"""Thin and thick regions: connected patches of the surface mesh where the thickness is below the
minimum (or above the maximum), each with its extreme value, its place and its area."""

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components


def _patches(triangles, selected):
    """(labels (N,) patch index or -1, count): components of the selected points joined by the
    mesh's sides."""
    n = len(selected)
    e = np.vstack([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]])
    e = e[selected[e[:, 0]] & selected[e[:, 1]]]
    graph = coo_matrix((np.ones(len(e)), (e[:, 0], e[:, 1])), shape=(n, n))
    _, label = connected_components(graph, directed=False)
    label = np.where(selected, label, -1)
    kept = np.unique(label[selected])
    renumber = np.full(label.max() + 2, -1)
    renumber[kept] = np.arange(len(kept))
    return np.where(selected, renumber[label], -1), len(kept)


def find_regions(mesh, values, area, counted, limit, kind):
    """List of dicts, largest extreme first (thinnest for "thin", thickest for "thick"):
    kind, extreme (min or max thickness), at [x, y, z] (the point of the extreme), faces
    (B-rep face names the patch touches), area, points (count), min, max, and the (P,) int64
    indices of its points under "point_indices".

    values (N,) thickness; area (N,) point areas; counted (N,) bool: the points that take part
    (the corner band left out); limit: the threshold; kind "thin" (values < limit) or "thick"
    (values > limit)."""
    if limit is None:
        return []
    selected = counted & ((values < limit) if kind == "thin" else (values > limit))
    label, count = _patches(mesh.triangles, selected)
    if count == 0:
        return []
    # Point -> incident triangles in CSR form, for the faces a patch touches.
    order = np.argsort(mesh.triangles.ravel(), kind="stable")
    tri_of = order // 3
    starts = np.searchsorted(mesh.triangles.ravel()[order], np.arange(len(values) + 1))
    regions = []
    members = np.argsort(label, kind="stable")
    members = members[label[members] >= 0]
    bounds = np.searchsorted(label[members], np.arange(count + 1))
    for r in range(count):
        idx = members[bounds[r]:bounds[r + 1]]
        v = values[idx]
        pick = idx[np.argmin(v) if kind == "thin" else np.argmax(v)]
        lens = starts[idx + 1] - starts[idx]
        at = np.repeat(starts[idx] - np.cumsum(lens) + lens, lens) + np.arange(lens.sum())
        faces = np.unique(mesh.triangle_face[tri_of[at]]).tolist()
        regions.append({
            "kind": kind,
            "extreme": float(values[pick]),
            "at": [float(x) for x in mesh.points[pick]],
            "faces": [mesh.face_names[f] for f in faces],
            "area": float(area[idx].sum()),
            "points": int(len(idx)),
            "min": float(v.min()),
            "max": float(v.max()),
            "point_indices": idx,
        })
    regions.sort(key=lambda g: g["extreme"], reverse=(kind == "thick"))
    return regions
