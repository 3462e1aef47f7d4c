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
    whose two ends are that close closed. Joined curves get source "edges+tube" and "tubes": the
    ids of the tubes (key "tube" of a tube's curve) they hold."""
    curves = list(curves)
    while True:
        best = None
        ends = [(i, side) for i, c in enumerate(curves) if not c["closed"] for side in (0, -1)]
        for x in range(len(ends)):
            for y in range(x + 1, len(ends)):
                (i, si), (j, sj) = ends[x], ends[y]
                d = np.linalg.norm(vertices[curves[i]["vertices"][si]] -
                                   vertices[curves[j]["vertices"][sj]])
                if d < gap and (best is None or d < best[0]):
                    best = (d, i, si, j, sj)
        if best is None:
            return curves
        _, i, si, j, sj = best
        a, b = curves[i], curves[j]
        if i == j:
            path = np.r_[a["vertices"], a["vertices"][:1]]
            merged = _curve(vertices, radius, path, a["source"], closed=True)
        else:
            pa = a["vertices"] if si == -1 else a["vertices"][::-1]
            pb = b["vertices"] if sj == 0 else b["vertices"][::-1]
            source = a["source"] if a["source"] == b["source"] else "edges+tube"
            merged = _curve(vertices, radius, np.r_[pa, pb], source)
        merged["faces"] = a.get("faces", 0) + (b.get("faces", 0) if i != j else 0)
        merged["tubes"] = _tubes_of(a) + (_tubes_of(b) if i != j else [])
        curves = [c for k, c in enumerate(curves) if k not in (i, j)] + [merged]


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
