"""Sheets: the faces of the axis joined across edges that exactly two faces share."""

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

from .grouped import grouped_extremes


def join_faces(pairs_a, pairs_b, num_faces):
    """(labels (F,) int64 component of each face, count): components of the graph whose nodes
    are the faces and whose links are (pairs_a[i], pairs_b[i])."""
    graph = coo_matrix((np.ones(len(pairs_a)), (pairs_a, pairs_b)), shape=(num_faces, num_faces))
    count, labels = connected_components(graph, directed=False)
    return labels.astype(np.int64), int(count)


def raw_sheets(table, num_faces):
    """(labels (F,), count): faces joined across each edge held by exactly two faces; an edge of
    three or more faces (a seam) or of one (a boundary) joins nothing."""
    two = np.flatnonzero(table.count == 2)
    first = table.faces[table.face_start[two]]
    second = table.faces[table.face_start[two] + 1]
    return join_faces(first, second, num_faces)


def renumber_by_size(labels, weight):
    """labels renumbered 0, 1, ... by decreasing total ``weight`` (ties: smaller old label
    first); labels < 0 stay -1. Returns (new labels, count)."""
    used = labels >= 0
    if not used.any():
        return np.full(len(labels), -1, dtype=np.int64), 0
    totals = np.bincount(labels[used], weights=weight[used])
    present = np.flatnonzero(np.bincount(labels[used]) > 0)
    order = present[np.lexsort((present, -totals[present]))]
    new = np.full(len(totals), -1, dtype=np.int64)
    new[order] = np.arange(len(order))
    out = np.full(len(labels), -1, dtype=np.int64)
    out[used] = new[labels[used]]
    return out, len(order)


def face_areas(vertices, faces):
    """(F,) area of each polygon: half the norm of its vector area, Newell's sum of
    (p_i - p_0) x (p_i+1 - p_0) over its sides (exact for planar polygons, the vector area for
    the slightly warped Voronoi facets)."""
    offsets = np.asarray(faces.offsets, dtype=np.int64)
    corners = np.asarray(faces.indices, dtype=np.int64)
    sizes = np.diff(offsets)
    rows = np.repeat(np.arange(len(sizes)), sizes)
    following = np.arange(1, len(corners) + 1)
    last = offsets[1:][sizes > 0] - 1
    following[last] = offsets[:-1][sizes > 0]
    q = vertices[corners] - vertices[corners[offsets[:-1][rows]]]
    x, y, z = q[:, 0], q[:, 1], q[:, 2]
    xn, yn, zn = x[following], y[following], z[following]
    total = [np.bincount(rows, weights=w, minlength=len(sizes))
             for w in (y * zn - z * yn, z * xn - x * zn, x * yn - y * xn)]
    return 0.5 * np.sqrt(total[0] ** 2 + total[1] ** 2 + total[2] ** 2)


def face_vertex_rows(faces):
    """(M,) face index of each entry of faces.indices."""
    return np.repeat(np.arange(len(faces), dtype=np.int64), faces.sizes())


def sheet_table(labels, count, vertices, radius, faces, area, kinds):
    """List of per-sheet dicts (index = sheet id): faces (count), area, radius_min, radius_max,
    centroid [x, y, z] (mean of its vertices), normal [x, y, z] and flatness (RMS distance of its
    vertices to the least-squares plane through them: 0 for a plane), completion_faces."""
    rows = face_vertex_rows(faces)
    corner_sheet = labels[rows]
    keep = corner_sheet >= 0
    corner_sheet, corner_vertex = corner_sheet[keep], np.asarray(faces.indices)[keep]
    r_min, r_max = grouped_extremes(corner_sheet, radius[corner_vertex], count)
    used = labels >= 0
    n_faces = np.bincount(labels[used], minlength=count)
    areas = np.bincount(labels[used], weights=area[used], minlength=count)
    n_completion = np.bincount(labels[used & (kinds != 0)], minlength=count)
    # One vertex once per sheet for the plane fit.
    key = np.unique(corner_sheet * len(vertices) + corner_vertex)
    s, v = key // len(vertices), key % len(vertices)
    bounds = np.searchsorted(s, np.arange(count + 1))
    out = []
    for k in range(count):
        p = vertices[v[bounds[k]:bounds[k + 1]]]
        centre = p.mean(axis=0)
        _, sv, vt = np.linalg.svd(p - centre, full_matrices=False)
        normal = vt[-1] if len(sv) == 3 else np.zeros(3)
        flat = float(sv[-1] / np.sqrt(len(p))) if len(sv) == 3 else 0.0
        out.append({
            "faces": int(n_faces[k]),
            "area": float(areas[k]),
            "radius_min": float(r_min[k]),
            "radius_max": float(r_max[k]),
            "centroid": [float(x) for x in centre],
            "normal": [float(x) for x in normal],
            "flatness": flat,
            "completion_faces": int(n_completion[k]),
        })
    return out
