"""The B-rep faces whose balls touch each sheet: for a wall, its two faces.

A point of a sheet is the centre of a ball touching the boundary on both sides of the sheet;
moved off the sheet by a tenth of its radius along the sheet's normal, its nearest boundary point
is on the side it moved to. So, from up to ``per_sheet`` of a sheet's Voronoi faces (evenly
spread over its face list), the exact distance (the engine's, B-rep faces and edges) from
centroid +- radius / 10 * normal names one face on each side.
"""

import numpy as np


def _face_frames(vertices, radius, faces, picked):
    """(centroid (k, 3), unit normal (k, 3), mean radius (k,)) of the picked faces."""
    sizes = faces.sizes()[picked]
    starts = np.asarray(faces.offsets)[picked]
    at = np.repeat(starts - np.cumsum(sizes) + sizes, sizes) + np.arange(sizes.sum())
    corner = np.asarray(faces.indices)[at]
    which = np.repeat(np.arange(len(picked)), sizes)
    p = vertices[corner]
    n = np.maximum(sizes, 1)[:, None]
    centre = np.stack([np.bincount(which, weights=p[:, k], minlength=len(picked))
                       for k in range(3)], axis=1) / n
    r = np.bincount(which, weights=radius[corner], minlength=len(picked)) / n[:, 0]
    # Newell's normal: the sum of (p_i - c) x (p_i+1 - c).
    following = np.arange(1, len(at) + 1)
    last = np.cumsum(sizes) - 1
    following[last] = last - sizes + 1
    q = p - centre[which]
    cross = np.cross(q, q[following])
    normal = np.stack([np.bincount(which, weights=cross[:, k], minlength=len(picked))
                       for k in range(3)], axis=1)
    length = np.linalg.norm(normal, axis=1)
    return centre, normal / np.maximum(length, 1e-300)[:, None], r, length > 0


def touching(result, groups, solids, per_group=64, min_share=0.1):
    """Per group of axis faces (a list of (k,) int arrays), a list of [face index, share]: the
    faces of its solid (in the solid's own face order, that of FreeCAD's solid.Faces) nearest to
    its faces' two sides, with the share of the probes that met each, largest first, those under
    ``min_share`` left out. At most ``per_group`` faces of a group are probed, evenly spread.

    solids: the engine's solids (``_core.extract_solids``), indexed by result.face_solid."""
    from .. import _core
    vertices = np.asarray(result.vertices, dtype=np.float64)
    radius = np.asarray(result.radius, dtype=np.float64)
    solid_of = np.asarray(result.face_solid)
    out = [[] for _ in groups]
    picked, group_of = [], []
    for g, mine in enumerate(groups):
        mine = np.asarray(mine, dtype=np.int64)
        if len(mine) > per_group:
            mine = mine[np.linspace(0, len(mine) - 1, per_group).round().astype(np.int64)]
        picked.append(mine)
        group_of.append(np.full(len(mine), g, dtype=np.int64))
    if not picked:
        return out
    picked, group_of = np.concatenate(picked), np.concatenate(group_of)
    if not len(picked):
        return out
    centre, normal, r, ok = _face_frames(vertices, radius, result.faces, picked)
    keep = ok & (r > 0)
    picked, group_of, centre, normal, r = (x[keep] for x in (picked, group_of, centre, normal, r))
    hits_group, hits_face = [], []
    for k, solid in enumerate(solids):
        mine = np.flatnonzero(solid_of[picked] == k)
        if not len(mine):
            continue
        for side in (1.0, -1.0):
            probe = centre[mine] + side * 0.1 * r[mine, None] * normal[mine]
            _, _, face, _ = _core.boundary_distance(solid, probe, 1.5 * r[mine])
            hit = face >= 0
            hits_group.append(group_of[mine][hit])
            hits_face.append(face[hit].astype(np.int64))
    if not hits_group or not sum(len(h) for h in hits_group):
        return out
    hg, hf = np.concatenate(hits_group), np.concatenate(hits_face)
    probes = np.bincount(group_of, minlength=len(groups)) * 2
    span = int(hf.max()) + 1
    key, n = np.unique(hg * span + hf, return_counts=True)
    for k, c in zip(key.tolist(), n.tolist()):
        g, f = divmod(k, span)
        share = c / probes[g]
        if share >= min_share:
            out[g].append([f, share])
    for lst in out:
        lst.sort(key=lambda x: (-x[1], x[0]))
    return out


def touching_faces(result, face_sheet, n_sheets, solids, per_sheet=64, min_share=0.1):
    """touching() of each sheet's Voronoi faces (completion triangles lie against an edge)."""
    usable = (face_sheet >= 0) & (np.asarray(result.face_kind) == 0)
    order = np.argsort(face_sheet, kind="stable")
    order = order[usable[order]]
    bounds = np.searchsorted(face_sheet[order], np.arange(n_sheets + 1))
    groups = [order[bounds[s]:bounds[s + 1]] for s in range(n_sheets)]
    return touching(result, groups, solids, per_sheet, min_share)


def add_touches(result, shape, table, face_sheet, sheets, rims):
    """Sets "touches" of each sheet (touching_faces) and rim (touching() of the one face of each
    of its edges) from ``shape``, the source the axis was computed from."""
    from .. import _core
    from ..api import read_shape
    solids = _core.extract_solids(read_shape(shape))
    for d, touches in zip(sheets, touching_faces(result, face_sheet, len(sheets), solids)):
        d["touches"] = touches
    # The table's edges are sorted by this key: a rim's rows by binary search.
    n = np.int64(result.num_vertices)
    keys = table.pairs[:, 0] * n + table.pairs[:, 1]
    groups = [table.first_faces(np.searchsorted(keys, b["edges"][:, 0] * n + b["edges"][:, 1]))
              for b in rims]
    for b, touches in zip(rims, touching(result, groups, solids)):
        b["touches"] = touches
