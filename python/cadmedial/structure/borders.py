"""Borders of sheets (rims and free borders) grouped into the curves they trace.

A sheet's border is clean along a sharp edge of the solid (one chain of rim edges per edge), but
frays where the exact axis ends at a fillet's centre curve: filletBox's free border edges come
as 897 chains (893 separate pieces), a median 0.08 mm long (spacing 0.21 mm), the teeth of a
comb of slivers. Border edges of one sheet closer than ``join`` (a spacing) are one border.
"""

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree

from .chains import chain, polyline_length


def group_borders(pairs, edge_sheet, vertices, radius, join):
    """Dicts of the borders made of the (K, 2) edges ``pairs``, each of sheet edge_sheet[k]:
    sheet, length (sum of its edges), edges (n, 2) int64, vertices (P,) int64 the longest chain of
    its edges in order, closed (that chain is a loop), span (distance between its two farthest
    points, about), radius_min, radius_max. Largest length first."""
    pairs = np.asarray(pairs, dtype=np.int64).reshape(-1, 2)
    k = len(pairs)
    if k == 0:
        return []
    # Nodes: the (sheet, vertex) pairs of the border, linked by its edges and when closer than
    # join (and of one sheet); an edge's group is its first end's component.
    n = np.int64(len(vertices))
    key = np.repeat(np.asarray(edge_sheet, dtype=np.int64), 2) * n + pairs.ravel()
    nodes, node_of = np.unique(key, return_inverse=True)
    node_of = node_of.reshape(-1, 2)
    node_sheet, node_vertex = nodes // n, nodes % n
    near = cKDTree(vertices[node_vertex]).query_pairs(join, output_type="ndarray")
    near = near[node_sheet[near[:, 0]] == node_sheet[near[:, 1]]]
    a = np.r_[node_of[:, 0], near[:, 0]]
    b = np.r_[node_of[:, 1], near[:, 1]]
    graph = coo_matrix((np.ones(len(a)), (a, b)), shape=(len(nodes), len(nodes)))
    _, node_label = connected_components(graph, directed=False)
    label = node_label[node_of[:, 0]]
    order = np.argsort(label, kind="stable")
    bounds = np.searchsorted(label[order], np.arange(label.max() + 2))
    seg = np.linalg.norm(vertices[pairs[:, 0]] - vertices[pairs[:, 1]], axis=1)
    out = []
    for g in range(len(bounds) - 1):
        rows = order[bounds[g]:bounds[g + 1]]
        e = pairs[rows]
        chains = chain(e, len(vertices))
        path, _, closed = max(chains, key=lambda c: polyline_length(vertices, c[0]))
        p = vertices[np.unique(e)]
        far = p[np.argmax(np.linalg.norm(p - p.mean(axis=0), axis=1))]
        r = radius[e.ravel()]
        out.append({
            "sheet": int(edge_sheet[rows[0]]),
            "length": float(seg[rows].sum()),
            "edges": e,
            "vertices": path,
            "closed": bool(closed),
            "span": float(np.linalg.norm(p - far, axis=1).max()),
            "radius_min": float(r.min()),
            "radius_max": float(r.max()),
        })
    out.sort(key=lambda d: -d["length"])
    return out
