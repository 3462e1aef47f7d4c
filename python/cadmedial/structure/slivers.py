"""Sub-resolution sheets ("slivers"): merged into the sheet they fray from, or gathered into tubes.

The raw Voronoi axis frays where the exact axis has a feature thinner than the sampling: the
ragged end of a sheet at a fillet's centre curve, the crossing of a seam, and above all a curve of
the axis (a cylinder's axis) which comes out as a bundle of thousands of sliver faces around the
line, each a sheet of its own since 3 to 6 of them share every edge. A sheet of less area than a
couple of spacings squared cannot be told from that noise: measured on the default density, the
real sheets of a cylinder (its cones) have 2,175 h^2, its axis's slivers at most 1.15 h^2;
filletBox's sheets at least 827 h^2, its slivers at most 0.15 h^2 (h: the sample spacing).

At a thin wall the engine samples finer (adaptive sampling), and real sheets are small: there
the area is measured in squares of the local spacing (local_spacing()). In h alone, the 4
corner triangles of a 60 x 40 x 0.5 plate (0.41 h^2 each) and 6 sheets of tail_turbine (0.42
to 0.78 h^2, each with a rim and two seams) were merged.

A sliver within ``reach`` (one spacing, along a path through touching slivers) of a real sheet is
part of that sheet's ragged border: it joins the nearest. Of the slivers left, a connected
cluster spanning ``tube_length`` (3 spacings) or more is a tube (a curve of the axis drawn as
faces); a shorter one is too small to hold structure of its own and joins the real sheet nearest
along its slivers, or becomes one sheet if it touches none.
"""

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components, dijkstra

from .grouped import grouped_extremes
from .sheets import face_vertex_rows


def _sheet_pairs(table, labels):
    """(a, b, edge) rows for each edge of 3+ faces and each pair of its faces' sheets a != b."""
    rows = []
    for c in np.unique(table.count[table.count >= 3]).tolist():
        edges = np.flatnonzero(table.count == c)
        f = table.faces[table.face_start[edges][:, None] + np.arange(c)]
        s = labels[f]
        for i in range(c):
            for j in range(i + 1, c):
                diff = s[:, i] != s[:, j]
                rows.append(np.stack([s[diff, i], s[diff, j], edges[diff]], axis=1))
    if not rows:
        return np.zeros((0, 3), dtype=np.int64)
    return np.concatenate(rows).astype(np.int64)


def sheet_centres(labels, count, vertices, faces):
    """(S, 3) mean of the corners of each sheet's faces."""
    s = labels[face_vertex_rows(faces)]
    corners = vertices[np.asarray(faces.indices)]
    n = np.maximum(np.bincount(s, minlength=count), 1)
    return np.stack([np.bincount(s, weights=corners[:, k], minlength=count) / n
                     for k in range(3)], axis=1)


def local_spacing(labels, count, radius, faces, spacing):
    """(S,) the spacing the engine sampled each sheet's walls with, about: at a wall thinner
    than the spacing its adaptive sampling spaces samples half the wall's half thickness apart
    (kSpacingPerRadius in pipeline/compute_medial_axis.cpp), at most 4 times finer than the
    spacing (kMaxRefinement; deeper only within a sample budget). A sheet's largest radius is
    its wall's half thickness. On a 60 x 40 x 0.5 plate the 4 exact corner triangles of 0.088
    (0.41 h^2) are real sheets, sampled about 4 times finer."""
    _, r_max = grouped_extremes(labels[face_vertex_rows(faces)],
                                radius[np.asarray(faces.indices)], count)
    return np.clip(0.5 * r_max, spacing / 4, spacing)


def resolve_slivers(table, labels, count, area, vertices, radius, faces, spacing,
                    sliver_area=2.0, reach=1.0, tube_length=3.0):
    """Merges slivers of the raw sheets ``labels`` (F,) (``count`` of them).

    area (F,) face areas; radius (V,); spacing h; sliver_area in squares of each sheet's local
    spacing (local_spacing()), reach and tube_length in h.
    Returns (sheet (F,) int64 new sheet label or -1 for a tube face, tube (F,) int64 tube label or
    -1, core (F,) bool: the face was in a real (not sliver) raw sheet)."""
    sheet_area = np.bincount(labels, weights=area, minlength=count)
    small = sheet_area < sliver_area * local_spacing(labels, count, radius, faces, spacing) ** 2
    core = ~small[labels]
    if not small.any():
        return labels.copy(), np.full(len(labels), -1, dtype=np.int64), core
    centre = sheet_centres(labels, count, vertices, faces)
    pairs = _sheet_pairs(table, labels)
    a, b, e = pairs[:, 0], pairs[:, 1], pairs[:, 2]
    # Only links that touch a sliver matter; a real sheet's position is where it meets the sliver
    # (the shared edge's midpoint), a sliver's its centroid.
    touch = small[a] | small[b]
    a, b, e = a[touch], b[touch], e[touch]
    mid = 0.5 * (vertices[table.pairs[e, 0]] + vertices[table.pairs[e, 1]])
    pa = np.where(small[a][:, None], centre[a], mid)
    pb = np.where(small[b][:, None], centre[b], mid)
    w = np.linalg.norm(pa - pb, axis=1) + 1e-12 * spacing  # 0 would drop the link
    # Keep the shortest of parallel links (coo_matrix would add them up).
    key = np.minimum(a, b) * count + np.maximum(a, b)
    order = np.argsort(key)
    key, w = key[order], w[order]
    starts = np.flatnonzero(np.r_[True, key[1:] != key[:-1]]) if len(key) else \
        np.zeros(0, dtype=np.int64)
    w = np.minimum.reduceat(w, starts) if len(key) else w
    lo, hi = key[starts] // count, key[starts] % count
    sources = np.flatnonzero(~small)
    new = np.arange(count, dtype=np.int64)
    left = small.copy()
    if len(sources):
        # Paths may run only through slivers: cut links between two real sheets.
        both_real = ~small[lo] & ~small[hi]
        through = coo_matrix((w[~both_real], (lo[~both_real], hi[~both_real])),
                             shape=(count, count)).tocsr()
        dist, _, source = dijkstra(through, directed=False, indices=sources, min_only=True,
                                   return_predecessors=True)
        joined = small & (dist <= reach * spacing) & (source >= 0)
        new[joined] = source[joined]
        left &= ~joined
    # Clusters of the slivers left, joined through the links between two of them.
    keep = left[lo] & left[hi]
    n_left = int(left.sum())
    tube = np.full(count, -1, dtype=np.int64)
    if n_left:
        cluster_graph = coo_matrix((np.ones(int(keep.sum())), (lo[keep], hi[keep])),
                                   shape=(count, count))
        _, cluster = connected_components(cluster_graph, directed=False)
        ids = np.flatnonzero(left)
        rows = face_vertex_rows(faces)
        corners = vertices[np.asarray(faces.indices)]
        face_left = left[labels]
        c_of_corner = cluster[labels[rows]][face_left[rows]]
        pts = corners[face_left[rows]]
        uniq, inv = np.unique(c_of_corner, return_inverse=True)
        bl, bh = grouped_extremes(inv, pts, len(uniq))
        length = np.linalg.norm(bh - bl, axis=1)
        is_tube = length >= tube_length * spacing
        tube_no = np.full(len(uniq), -1, dtype=np.int64)
        tube_no[is_tube] = np.arange(int(is_tube.sum()))
        where = np.searchsorted(uniq, cluster[ids])
        tube[ids] = tube_no[where]
        # A short cluster joins the real sheet nearest along its slivers (it is too small to
        # show any structure of its own), or, touching none, becomes one sheet: that of its
        # first raw sheet.
        rep = np.full(len(uniq), -1, dtype=np.int64)
        for i, c in zip(ids.tolist(), where.tolist()):
            if rep[c] < 0:
                rep[c] = i
        reached = source[ids] >= 0 if len(sources) else np.zeros(len(ids), dtype=bool)
        nearest = source[ids] if len(sources) else rep[where]
        new[ids] = np.where(tube[ids] >= 0, -1, np.where(reached, nearest, rep[where]))
    sheet = new[labels]
    return sheet, tube[labels], core
