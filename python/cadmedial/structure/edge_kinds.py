"""What each polygon edge of the axis is, once faces carry their sheet: inside a sheet, on a seam
(three or more sheets meet), on a rim (a sheet's border on the solid's boundary) or on a free
border (a sheet's border away from the boundary: a fillet's centre curve, a hole in the axis)."""

import numpy as np

INSIDE, SEAM, RIM, FREE, TUBE = 0, 1, 2, 3, 4
NAMES = {INSIDE: "inside", SEAM: "seam", RIM: "rim", FREE: "free", TUBE: "tube"}


def classify_edges(table, sheet, core, kind, radius, rim_radius):
    """(E,) uint8 INSIDE/SEAM/RIM/FREE/TUBE of each edge of ``table``.

    sheet (F,) final sheet of each face (-1: a tube face); core (F,) bool: the face was in a real
    raw sheet (not a merged sliver); kind (F,) FaceKind; radius (V,); rim_radius: a border edge
    whose two ends have a radius at most this (or of a completion face) is a rim.

    An edge of three or more sheet faces is a seam when they belong to two distinct sheets or
    more, and three of them are core faces or three distinct sheets: a sliver merged into the
    sheet it hangs from does not make a seam of its border, nor does a fold of one sheet onto
    itself (measured on filletBox: 180 seams shorter than a spacing, all of one sheet, along its
    fillet's centre curve). Two sheets can meet at a real seam (a rib ending inside a plate: the
    plate's sheet runs round the rib's end and lies on two sides of the seam). An edge with tube
    faces only, or with one sheet face beside tube faces, is TUBE (the place where a sheet meets
    a curve of the axis)."""
    f = table.faces
    edge_of = np.repeat(np.arange(len(table)), table.count)
    in_sheet = sheet[f] >= 0
    n_sheet = np.bincount(edge_of, weights=in_sheet, minlength=len(table)).astype(np.int64)
    n_core = np.bincount(edge_of, weights=in_sheet & core[f], minlength=len(table)).astype(np.int64)
    n_tube = table.count - n_sheet
    # Distinct sheets per edge: unique (edge, sheet) keys.
    key = np.unique(edge_of[in_sheet] * (int(sheet.max()) + 2) + sheet[f][in_sheet])
    distinct = np.bincount(key // (int(sheet.max()) + 2), minlength=len(table))
    out = np.full(len(table), INSIDE, dtype=np.uint8)
    out[(n_sheet >= 3) & (distinct >= 2) & ((n_core >= 3) | (distinct >= 3))] = SEAM
    border = n_sheet == 1
    # The one sheet face of a border edge.
    pos = np.flatnonzero(in_sheet)
    one_face = np.full(len(table), -1, dtype=np.int64)
    one_face[edge_of[pos]] = f[pos]
    ends_r = radius[table.pairs].max(axis=1)
    rim = border & ((ends_r <= rim_radius) | (kind[np.maximum(one_face, 0)] != 0))
    out[border & rim] = RIM
    out[border & ~rim] = FREE
    out[(n_tube > 0) & (n_sheet <= 1)] = TUBE
    return out
