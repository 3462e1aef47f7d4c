"""Edges chained into polylines that end where the edge graph branches or stops."""

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components


def vertex_degree(pairs, num_vertices):
    """(V,) number of the (K, 2) edges ``pairs`` at each vertex."""
    return np.bincount(np.asarray(pairs, dtype=np.int64).ravel(), minlength=num_vertices)


def chain(pairs, num_vertices, stops=None):
    """Polylines of the (K, 2) edges ``pairs``: list of (vertices, edges, closed), vertices a
    (P,) int64 array of vertex indices in order along the chain, edges (P-1,) int64 the rows of
    ``pairs`` in the same order, closed True for a loop (then vertices[0] == vertices[-1]).

    A chain runs through vertices where exactly two of the edges meet and ends elsewhere
    (degree 1: an end; 3 or more: a branch point), or at a vertex where ``stops`` ((V,) bool)
    is true. Chains are ordered by their smallest edge row, so the output does not depend on
    dict order."""
    pairs = np.asarray(pairs, dtype=np.int64).reshape(-1, 2)
    k = len(pairs)
    if k == 0:
        return []
    # Work on the vertices the edges use (a border of a few edges in a mesh of 100,000 vertices).
    used, local = np.unique(pairs, return_inverse=True)
    pairs = local.reshape(-1, 2)
    degree = vertex_degree(pairs, len(used))
    through = degree == 2
    if stops is not None:
        through &= ~np.asarray(stops, dtype=bool)[used]
    # Two edges belong to one chain when they share a pass-through vertex: components of that
    # edge graph (vectorised), then a walk per component to order it.
    ends = pairs.ravel()
    edge_of_end = np.repeat(np.arange(k), 2)
    order = np.argsort(ends, kind="stable")
    ends_sorted, edges_sorted = ends[order], edge_of_end[order]
    same = (ends_sorted[1:] == ends_sorted[:-1]) & through[ends_sorted[1:]]
    a, b = edges_sorted[:-1][same], edges_sorted[1:][same]
    graph = coo_matrix((np.ones(len(a)), (a, b)), shape=(k, k))
    _, label = connected_components(graph, directed=False)
    members = np.argsort(label, kind="stable")
    bounds = np.searchsorted(label[members], np.arange(label.max() + 2))
    incident = {}
    for e, (u, v) in enumerate(pairs.tolist()):
        incident.setdefault(u, []).append(e)
        incident.setdefault(v, []).append(e)
    out = []
    for c in range(len(bounds) - 1):
        group = members[bounds[c]:bounds[c + 1]]
        path, edges, closed = _walk(group, pairs, through, incident)
        out.append((used[path], edges, closed))
    out.sort(key=lambda ch: int(ch[1].min()))
    return out


def _walk(group, pairs, through, incident):
    # Start at an end of the chain (a vertex that does not pass through), or anywhere on a loop.
    start_edge, start_vertex = int(group[0]), int(pairs[group[0], 0])
    for e in group.tolist():
        u, v = pairs[e].tolist()
        if not through[u]:
            start_edge, start_vertex = e, u
            break
        if not through[v]:
            start_edge, start_vertex = e, v
            break
    vertices, edges = [start_vertex], []
    e, at = start_edge, start_vertex
    while True:
        u, v = pairs[e].tolist()
        at = v if u == at else u
        edges.append(e)
        vertices.append(at)
        if not through[at]:
            break
        nxt = [f for f in incident[at] if f != e]
        if not nxt or nxt[0] == start_edge:
            break
        e = nxt[0]
    closed = len(edges) > 1 and vertices[0] == vertices[-1]
    return np.array(vertices, dtype=np.int64), np.array(edges, dtype=np.int64), bool(closed)


def polyline_length(points, vertices):
    """Sum of the segment lengths of the polyline through points[vertices]."""
    p = points[vertices]
    return float(np.linalg.norm(np.diff(p, axis=0), axis=1).sum())
