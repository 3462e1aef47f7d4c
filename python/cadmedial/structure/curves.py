"""Curves of the axis: the result's 1-D edges chained, and tubes of sliver faces reduced to the
line they hug."""

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import breadth_first_order, dijkstra
from scipy.spatial import cKDTree

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
    diameter: the vertex u farthest from ``seed`` in hops, then the farthest from u in length
    (two sweeps)."""
    nodes, local = np.unique(pairs, return_inverse=True)
    local = local.reshape(-1, 2)
    w = np.linalg.norm(vertices[pairs[:, 0]] - vertices[pairs[:, 1]], axis=1) + 1e-300
    g = coo_matrix((w, (local[:, 0], local[:, 1])), shape=(len(nodes), len(nodes))).tocsr()
    start = int(np.searchsorted(nodes, seed))
    # The first sweep by hops (breadth first, its last vertex is farthest in hops): along a tube
    # that is about the farthest in length, and a third of the cost of a Dijkstra sweep.
    u = int(breadth_first_order(g, start, directed=False, return_predecessors=False)[-1])
    d, pred = dijkstra(g, directed=False, indices=u, return_predecessors=True)
    v = int(np.argmax(np.where(np.isfinite(d), d, -1)))
    path = [v]
    while path[-1] != u:
        path.append(int(pred[path[-1]]))
    return nodes[np.array(path[::-1], dtype=np.int64)]


def _trim_ends(path, radius, slack):
    """path without the end vertices whose ball is more than ``slack`` smaller than those just
    inside: a point of a curve of the axis has the largest ball around, one a distance d off the
    line a ball about d smaller, and the longest path through a tube starts and ends on the
    outermost sliver vertices (the torus's tube: its first vertex 0.72 off the core circle,
    3.6 spacings, the next 0.024)."""
    r = radius[path]
    lo, hi = 0, len(path)
    while hi - lo > 2 and r[lo] < np.median(r[lo + 1:lo + 11]) - slack:
        lo += 1
    while hi - lo > 2 and r[hi - 1] < np.median(r[max(lo, hi - 11):hi - 1]) - slack:
        hi -= 1
    return path[lo:hi]


def _tubes_of(c):
    return c.get("tubes", [c["tube"]] if "tube" in c else [])


def link_curves(curves, vertices, radius, gap):
    """curves with those whose ends are less than ``gap`` apart joined end to end (a curve that
    comes out partly as 1-D edges and partly as a tube: the torus's core circle), and a curve
    longer than pi * gap whose two ends are that close closed. Joined curves get source
    "edges+tube" (or their common source) and "tubes": the ids of the tubes (key "tube" of a
    tube's curve) they hold.

    Each end links to at most one other, nearest pairs first; then curves and links form paths
    of end nodes (node 2i and 2i+1 are curve i's ends), chained like any edges. Longest first."""
    open_ids = [i for i, c in enumerate(curves) if not c["closed"]]
    if not open_ids:
        return sorted(curves, key=lambda c: -c["length"])
    ends = np.array([[curves[i]["vertices"][0], curves[i]["vertices"][-1]] for i in open_ids])
    points = vertices[ends.ravel()]
    near = cKDTree(points).query_pairs(gap, output_type="ndarray")
    d = np.linalg.norm(points[near[:, 0]] - points[near[:, 1]], axis=1) if len(near) else []
    taken = np.zeros(len(points), dtype=bool)
    links = []
    length = np.array([curves[i]["length"] for i in open_ids])
    for k in np.argsort(d, kind="stable").tolist():
        a, b = near[k]
        # A curve closes on itself only if it is longer than a circle of diameter gap: a
        # straight piece of the axis shorter than gap has its ends that close too.
        if a // 2 == b // 2 and length[a // 2] <= np.pi * gap:
            continue
        if not taken[a] and not taken[b]:
            taken[a] = taken[b] = True
            links.append((a, b))
    if not links:
        return sorted(curves, key=lambda c: -c["length"])
    own = np.stack([np.arange(0, len(points), 2), np.arange(1, len(points), 2)], axis=1)
    graph = np.concatenate([own, np.array(links, dtype=np.int64)])
    out = [c for c in curves if c["closed"]]
    for nodes, rows, closed in chain(graph, len(points)):
        path, tubes, faces, sources = [], [], 0, set()
        for r, (u, v) in zip(rows.tolist(), zip(nodes[:-1].tolist(), nodes[1:].tolist())):
            if r >= len(own):
                continue  # a link: the next curve starts where this one ended
            c = curves[open_ids[r]]
            piece = c["vertices"] if u % 2 == 0 else c["vertices"][::-1]
            path.append(piece if not path else piece[1:] if piece[0] == path[-1][-1] else piece)
            tubes += _tubes_of(c)
            faces += c.get("faces", 0)
            sources.add(c["source"])
        path = np.concatenate(path)
        if closed and path[0] != path[-1]:
            path = np.r_[path, path[:1]]
        merged = _curve(vertices, radius, path,
                        sources.pop() if len(sources) == 1 else "edges+tube", closed)
        if faces:
            merged["faces"] = faces
        if tubes:
            merged["tubes"] = tubes
        out.append(merged)
    out.sort(key=lambda c: -c["length"])
    return out


def tube_curves(table, tube, vertices, radius, spacing):
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
        path = _trim_ends(_diameter_path(pairs, vertices, int(pairs[0, 0])), radius,
                          0.5 * spacing)
        c = _curve(vertices, radius, path, "tube")
        c["faces"] = int(faces_per_tube[k])
        out.append(c)
    return out


def curves_of(result, table, tube, vertices, radius, spacing, tube_length):
    """(curves, face_curve): the 1-D edges' chains and the tubes' lines, linked end to end where
    less than tube_length spacings apart (link_curves), longest first; face_curve (F,) int64 the
    curve of each tube face, else -1."""
    tubes = tube_curves(table, tube, vertices, radius, spacing)
    for k, c in enumerate(tubes):
        c["tube"] = k
    curves = link_curves(edge_curves(result) + tubes, vertices, radius, tube_length * spacing)
    tube_to_curve = np.full(len(tubes) + 1, -1, dtype=np.int64)
    for k, c in enumerate(curves):
        for t in c.pop("tubes", [c["tube"]] if "tube" in c else []):
            tube_to_curve[t] = k
        c.pop("tube", None)
    return curves, np.where(tube >= 0, tube_to_curve[tube], -1)
