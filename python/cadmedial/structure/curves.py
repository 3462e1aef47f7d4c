"""Curves of the axis: the result's 1-D edges chained, and tubes of sliver faces reduced to the
line they hug."""

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import dijkstra

from .chains import chain, polyline_length


def _curve(vertices, radius, path, source, closed=False):
    p = np.asarray(path, dtype=np.int64)
    r = radius[p]
    return {
        "source": source,
        "vertices": p,
        "length": polyline_length(vertices, p),
        "radius_min": float(r.min()),
        "radius_max": float(r.max()),
        "radius_mean": float(r.mean()),
        "closed": bool(closed),
        "ends": [vertices[p[0]].tolist(), vertices[p[-1]].tolist()],
    }


def edge_curves(result, stops=None):
    """Dicts of the chains of result.edges (see chain()): source "edges", vertices (P,) in order,
    length, radius_min/max/mean, closed, ends [[x, y, z], [x, y, z]]."""
    edges = np.asarray(result.edges, dtype=np.int64).reshape(-1, 2)
    out = []
    for path, _, closed in chain(edges, result.num_vertices, stops):
        out.append(_curve(result.vertices, result.radius, path, "edges", closed))
    return out


def _diameter_path(pairs, vertices, seed):
    """Vertex indices of the shortest path between the two ends of the graph's (approximate)
    diameter: the farthest vertex u from ``seed``, then the farthest from u (two sweeps)."""
    nodes, local = np.unique(pairs, return_inverse=True)
    local = local.reshape(-1, 2)
    w = np.linalg.norm(vertices[pairs[:, 0]] - vertices[pairs[:, 1]], axis=1) + 1e-300
    g = coo_matrix((w, (local[:, 0], local[:, 1])), shape=(len(nodes), len(nodes))).tocsr()
    start = int(np.searchsorted(nodes, seed))
    d = dijkstra(g, directed=False, indices=start)
    u = int(np.argmax(np.where(np.isfinite(d), d, -1)))
    d, pred = dijkstra(g, directed=False, indices=u, return_predecessors=True)
    v = int(np.argmax(np.where(np.isfinite(d), d, -1)))
    path = [v]
    while path[-1] != u:
        path.append(int(pred[path[-1]]))
    return nodes[np.array(path[::-1], dtype=np.int64)]


def tube_curves(table, tube, vertices, radius):
    """Dicts (as edge_curves, source "tube", plus faces: the tube's face count) of each tube:
    the longest shortest path along its faces' edges, its line. (F,) ``tube`` labels faces."""
    out = []
    if not (tube >= 0).any():
        return out
    # Edge e is in tube t when one of its faces is.
    edge_of = np.repeat(np.arange(len(table)), table.count)
    t_of = tube[table.faces]
    sel = t_of >= 0
    key = np.unique(t_of[sel] * len(table) + edge_of[sel])
    t, e = key // len(table), key % len(table)
    bounds = np.searchsorted(t, np.arange(int(tube.max()) + 2))
    faces_per_tube = np.bincount(tube[tube >= 0])
    for k in range(len(bounds) - 1):
        pairs = table.pairs[e[bounds[k]:bounds[k + 1]]]
        path = _diameter_path(pairs, vertices, int(pairs[0, 0]))
        c = _curve(vertices, radius, path, "tube")
        c["faces"] = int(faces_per_tube[k])
        out.append(c)
    return out
