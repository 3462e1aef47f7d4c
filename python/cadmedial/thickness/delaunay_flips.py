"""Delaunay edge flips inside the faces of a surface mesh, round by round.

A round replaces each side shared by two triangles of one face whose opposite angles sum to more
than pi by the other diagonal, each triangle in at most one flip (the largest excess wins).
Bisection alone turns BRepMesh's long strips on cylinders into slivers; flips between the
bisection rounds keep the triangles near equilateral.

The flips of a round come in chains (a strip flips one triangle further each round: CTC 01 took
75 rounds of 1 to 9351 flips, 0.07 s each over its 69,000 triangles, 5 s in all). Only a side of
a triangle flipped in the last round can change its excess, so each round after the first looks
again only at those, carrying over the candidates that lost and those held back because their new
diagonal already was a side (it may have been flipped away since). The candidates, their order and
the winners are those of a round over every side (flip_round), so the mesh is the same.
"""

import numpy as np

from .mesh_sides import mesh_sides


def _angle(points, at, p, q):
    u, v = points[p] - points[at], points[q] - points[at]
    cos = np.einsum("ij,ij->i", u, v) / np.maximum(
        np.linalg.norm(u, axis=1) * np.linalg.norm(v, axis=1), 1e-300)
    return np.arccos(np.clip(cos, -1.0, 1.0))


def _pairs(points, triangles, tri_face, sub):
    """The sides shared by two triangles of ``sub`` (ascending triangle indices) on one face:
    (t1, t2, a, b, c, d, excess), t1 < t2, a-b the side as t1 runs it, c opposite in t1, d in
    t2, excess = the opposite angles' sum - pi."""
    if len(sub) == 0:
        empty = np.zeros(0, dtype=np.int64)
        return empty, empty, empty, empty, empty, empty, np.zeros(0)
    local = triangles[sub]
    # One sort of the half-sides' keys: a side held by exactly two triangles is a run of two
    # equal keys (stable: the lower flat index first), in increasing key order.
    raw = np.stack([local[:, [0, 1]], local[:, [1, 2]], local[:, [2, 0]]], axis=1).reshape(-1, 2)
    n = np.int64(len(points))
    keys = np.minimum(raw[:, 0], raw[:, 1]) * n + np.maximum(raw[:, 0], raw[:, 1])
    order = np.argsort(keys, kind="stable")
    ks = keys[order]
    equal = ks[1:] == ks[:-1]
    before = np.concatenate([[False], equal[:-1]])  # the run started earlier
    after = np.concatenate([equal[1:], [False]])    # the run goes on past two
    first = np.nonzero(equal & ~before & ~after)[0]
    k1, k2 = order[first], order[first + 1]         # flat (triangle * 3 + local side)
    t1, j1, t2, j2 = sub[k1 // 3], k1 % 3, sub[k2 // 3], k2 % 3
    same = tri_face[t1] == tri_face[t2]
    t1, j1, t2, j2 = t1[same], j1[same], t2[same], j2[same]
    a, b = triangles[t1, j1], triangles[t1, (j1 + 1) % 3]
    c, d = triangles[t1, (j1 + 2) % 3], triangles[t2, (j2 + 2) % 3]
    excess = _angle(points, c, a, b) + _angle(points, d, a, b) - np.pi
    return t1, t2, a, b, c, d, excess


def _key(a, b, n):
    return np.minimum(a, b) * n + np.maximum(a, b)


def _winners(cand_t1, cand_t2, excess, count_triangles):
    """Indices into the candidates (in side-key order) that flip: each the largest excess of
    both its triangles (ties to the later side)."""
    prio = excess + 1e-12 * np.arange(len(excess)) / max(len(excess), 1)
    best = np.full(count_triangles, -np.inf)
    np.maximum.at(best, cand_t1, prio)
    np.maximum.at(best, cand_t2, prio)
    return np.nonzero((best[cand_t1] == prio) & (best[cand_t2] == prio))[0]


def flip_round(points, triangles, tri_face):
    """One round over every side. Returns (triangles, flipped count)."""
    n = np.int64(len(points))
    t1, t2, a, b, c, d, excess = _pairs(points, triangles, tri_face,
                                        np.arange(len(triangles)))
    sides, _ = mesh_sides(triangles)
    cand = np.nonzero((excess > 1e-9) & (c != d))[0]
    cand = cand[~np.isin(_key(c[cand], d[cand], n), sides[:, 0] * n + sides[:, 1])]
    if len(cand) == 0:
        return triangles, 0
    win = cand[_winners(t1[cand], t2[cand], excess[cand], len(triangles))]
    if len(win) == 0:
        return triangles, 0
    triangles = triangles.copy()
    triangles[t1[win]] = np.column_stack([c[win], a[win], d[win]])
    triangles[t2[win]] = np.column_stack([d[win], b[win], c[win]])
    return triangles, len(win)


def flip_until_delaunay(points, triangles, tri_face, rounds=12):
    """Up to ``rounds`` rounds of flips, stopping at the first round without one: the mesh that
    as many flip_round calls give. Returns triangles (T, 3)."""
    n = np.int64(len(points))
    triangles = triangles.copy()
    sides, _ = mesh_sides(triangles)
    existing = np.sort(sides[:, 0] * n + sides[:, 1])
    carried = tuple(np.zeros(0, dtype=np.int64) for _ in range(6)) + (np.zeros(0),)
    changed = None  # the first round looks at every side
    for _ in range(rounds):
        if changed is None:
            fresh = _pairs(points, triangles, tri_face, np.arange(len(triangles)))
        else:
            # The triangles around the flipped ones hold every side of a flipped triangle with
            # both its triangles (and any third on a non-manifold side).
            touched = np.zeros(len(points), bool)
            touched[triangles[changed].ravel()] = True
            sub = np.nonzero(touched[triangles].any(axis=1))[0]
            fresh = _pairs(points, triangles, tri_face, sub)
            was_changed = np.zeros(len(triangles), bool)
            was_changed[changed] = True
            mine = was_changed[fresh[0]] | was_changed[fresh[1]]
            fresh = tuple(x[mine] for x in fresh)
        # A side seen fresh replaces its carried copy (none: a carried side's triangles are
        # unchanged, a fresh one has a changed triangle); side-key order as in flip_round.
        t1, t2, a, b, c, d, excess = (np.concatenate([f, k]) for f, k in zip(fresh, carried))
        order = np.argsort(_key(a, b, n), kind="stable")
        t1, t2, a, b, c, d, excess = (x[order] for x in (t1, t2, a, b, c, d, excess))
        keep = (excess > 1e-9) & (c != d)
        t1, t2, a, b, c, d, excess = (x[keep] for x in (t1, t2, a, b, c, d, excess))
        new_key = _key(c, d, n)
        pos = np.minimum(np.searchsorted(existing, new_key), len(existing) - 1)
        blocked = existing[pos] == new_key
        cand = np.nonzero(~blocked)[0]
        if len(cand) == 0:
            break
        win = cand[_winners(t1[cand], t2[cand], excess[cand], len(triangles))]
        if len(win) == 0:
            break
        triangles[t1[win]] = np.column_stack([c[win], a[win], d[win]])
        triangles[t2[win]] = np.column_stack([d[win], b[win], c[win]])
        gone = _key(a[win], b[win], n)
        existing = np.sort(np.concatenate([np.delete(existing, np.searchsorted(existing, gone)),
                                           new_key[win]]))
        changed = np.concatenate([t1[win], t2[win]])
        flipped = np.zeros(len(triangles), bool)
        flipped[changed] = True
        stay = ~(flipped[t1] | flipped[t2])   # losers and held-back sides whose triangles stand
        carried = tuple(x[stay] for x in (t1, t2, a, b, c, d, excess))
    return triangles
