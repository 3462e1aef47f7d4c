"""Seams (chains of seam edges) and junctions (where seams meet or end, and curves' ends).

Near-duplicate vertices split one meeting point of the exact axis into two: on filletBox two
junctions of degree 3 and 4, 0.0004 and 0.001 mm apart (spacing 0.21 mm), joined by a seam of
one edge, where the exact axis has one point at which five sheets meet. A seam shorter than
``join`` (a spacing) between two meeting points (3 or more seams each) is below the sampling's
resolution: its two junctions become one and the seam goes.
"""

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree

from .chains import chain, polyline_length, vertex_degree


def seams_and_junctions(seam_pairs, curve_paths, vertices, radius, join):
    """(seams, junctions, junction_of): seams a list of (vertices (P,), edge rows, closed, length,
    ends [junction id or -1, junction id or -1]); junctions a list of dicts: vertex (the first of
    its cluster), vertices (all of it), point [x, y, z] (their mean), radius, seam_degree (seam
    ends at it: 1 a seam's end, 3 or more a meeting point), curve_ends; junction_of (V,) int64
    junction id of each vertex, -1 elsewhere.

    seam_pairs (K, 2) the seam edges; curve_paths: the vertex paths of the open curves, whose ends
    are junctions too."""
    n = len(vertices)
    degree = vertex_degree(seam_pairs, n)
    curve_end = np.zeros(n, dtype=np.int64)
    for p in curve_paths:
        curve_end[p[0]] += 1
        curve_end[p[-1]] += 1
    at = np.flatnonzero(((degree > 0) & (degree != 2)) | (curve_end > 0))
    first_id = np.full(n, -1, dtype=np.int64)
    first_id[at] = np.arange(len(at))
    raw = []
    for path, edges, closed in chain(seam_pairs, n):
        ends = [-1, -1] if closed else [int(first_id[path[0]]), int(first_id[path[-1]])]
        raw.append((path, edges, closed, polyline_length(vertices, path), ends))
    # Contract short seams between two meeting points.
    short = [s for s in raw if not s[2] and s[3] < join and min(s[4]) >= 0
             and degree[at[s[4][0]]] >= 3 and degree[at[s[4][1]]] >= 3]
    a = np.array([s[4][0] for s in short], dtype=np.int64)
    b = np.array([s[4][1] for s in short], dtype=np.int64)
    graph = coo_matrix((np.ones(len(a)), (a, b)), shape=(len(at), len(at)))
    _, cluster = connected_components(graph, directed=False)
    # Renumber clusters by their first vertex's order.
    _, first = np.unique(cluster, return_index=True)
    rank = np.empty(len(first), dtype=np.int64)
    rank[np.argsort(first)] = np.arange(len(first))
    cluster = rank[cluster] if len(at) else cluster
    short_ids = {id(s) for s in short}
    seams = []
    seam_ends = np.zeros(len(first), dtype=np.int64)
    for s in raw:
        if id(s) in short_ids:
            continue
        ends = [int(cluster[e]) if e >= 0 else -1 for e in s[4]]
        for e in ends:
            if e >= 0:
                seam_ends[e] += 1
        seams.append((s[0], s[1], s[2], s[3], ends))
    junctions = []
    junction_of = np.full(n, -1, dtype=np.int64)
    junction_of[at] = cluster if len(at) else []
    for j in range(len(first)):
        vs = at[cluster == j]
        junctions.append({"vertex": int(vs[0]), "vertices": vs,
                          "point": vertices[vs].mean(axis=0).tolist(),
                          "radius": float(radius[vs].mean()), "seam_degree": int(seam_ends[j]),
                          "curve_ends": int(curve_end[vs].sum())})
    return seams, junctions, junction_of


def junction_sheets(junction_of, faces, face_sheet, n_sheets):
    """For each junction, the sorted ids of the sheets of the faces at its vertices."""
    rows = np.repeat(np.arange(len(faces), dtype=np.int64), faces.sizes())
    corner = np.asarray(faces.indices, dtype=np.int64)
    hit = (junction_of[corner] >= 0) & (face_sheet[rows] >= 0)
    base = n_sheets + 1
    keys = np.unique(junction_of[corner[hit]] * base + face_sheet[rows[hit]])
    count = int(junction_of.max()) + 1 if len(junction_of) else 0
    start = np.searchsorted(keys // base, np.arange(count + 1))
    return [(keys[start[j]:start[j + 1]] % base).tolist() for j in range(count)]


def sheets_near_curve_ends(junctions, faces, face_sheet, vertices, reach):
    """Adds to the "sheets" of each junction where a curve ends those with a vertex within
    ``reach`` of it: a tube's line stops short of the sheets it runs into (the cylinder's axis
    ends about a spacing from its cones' apexes), sharing no vertex with them."""
    at = [j for j in junctions if j["curve_ends"]]
    if not at:
        return
    rows = np.repeat(np.arange(len(faces), dtype=np.int64), faces.sizes())
    corner = np.asarray(faces.indices, dtype=np.int64)
    keep = face_sheet[rows] >= 0
    if not keep.any():
        return
    corner, sheet_of = corner[keep], face_sheet[rows[keep]]
    tree = cKDTree(vertices[corner])
    for j, near in zip(at, tree.query_ball_point([j["point"] for j in at], reach)):
        j["sheets"] = sorted(set(j["sheets"]) | set(sheet_of[near].tolist()))
