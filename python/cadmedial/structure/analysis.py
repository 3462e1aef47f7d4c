"""structure(): sheets, seams, junctions, rims, free borders and curves of a MedialAxisResult."""

import numpy as np

from .borders import group_borders
from .curves import edge_curves, link_curves, tube_curves
from .edge_kinds import FREE, NAMES, RIM, SEAM, classify_edges
from .edge_table import edge_table
from .junctions import seams_and_junctions
from .sheets import face_areas, face_vertex_rows, raw_sheets, renumber_by_size, sheet_table
from .slivers import resolve_slivers
from .touching import touching, touching_faces

TABLES = ("sheets", "seams", "junctions", "rims", "free", "curves")


class AxisStructure:
    """The structure of one medial axis (see structure()).

    face_sheet  (F,) int64 sheet id of each face, sheets numbered by decreasing area; -1 for a
                face of a tube (a curve of the axis drawn as sliver faces, see face_curve)
    face_curve  (F,) int64 curve id of a tube face, else -1
    edges       (E, 2) int64 the distinct polygon edges (vertex pairs, smaller first)
    edge_kind   (E,) uint8 INSIDE 0, SEAM 1, RIM 2, FREE 3, TUBE 4 (see edge_kinds.py)
    sheets      list of dicts, index = sheet id: faces, area, radius_min, radius_max,
                centroid [x, y, z] (mean of its vertices), normal, flatness (RMS distance of its
                vertices to their least-squares plane), completion_faces, seams (ids),
                rim_length, free_length, slivers (raw sheets merged into it), solid (index of
                the input solid), touches (with shape=: [[face index, share], ...])
    seams       list of dicts: vertices (P,) int64 polyline, length, sheets (ids, most edges
                first), sheet_edges (how many of its edges each of them holds), closed,
                ends [junction id or -1, junction id or -1], solid
    junctions   list of dicts: vertex, vertices (near-duplicates merged into it), point
                [x, y, z], radius, seam_degree (seam ends at it: 1 a seam's end, 3 or more where
                seams meet), curve_ends (curves ending at it), sheets (ids of its faces)
    rims, free  lists of dicts (see borders.group_borders): sheet, length, edges, vertices,
                closed, span, radius_min, radius_max; rims with shape=: touches, the faces
                beside it (two for a rim along one convex edge: that edge's faces)
    curves      list of dicts: source ("edges": the result's 1-D edges; "tube": sliver faces),
                vertices (P,) polyline, length, radius_min, radius_max, radius_mean, closed,
                ends, faces (tubes only), solid; longest first
    spacing     the sample spacing h the tolerances are relative to
    """

    def __init__(self, **fields):
        self.__dict__.update(fields)

    def to_dict(self):
        """Plain data for JSON: spacing and the tables, arrays as lists (face labels left out)."""
        def plain(x):
            if isinstance(x, np.ndarray):
                return x.tolist()
            if isinstance(x, dict):
                return {k: plain(v) for k, v in x.items()}
            if isinstance(x, list):
                return [plain(v) for v in x]
            return x
        out = {name: plain(getattr(self, name)) for name in TABLES}
        out["spacing"] = self.spacing
        return out

    def counts(self):
        """dict: how many sheets, seams, junctions, rims, free borders and curves there are."""
        return {name: len(getattr(self, name)) for name in TABLES}

    def __repr__(self):
        return "<cadmedial.structure.AxisStructure %s>" % ", ".join(
            "%d %s" % (n, k) for k, n in self.counts().items())


def _spacing_of(result, spacing, table):
    if spacing is not None:
        if not float(spacing) > 0:
            raise ValueError("spacing must be > 0, got %r" % (spacing,))
        return float(spacing)
    h = (result.stats or {}).get("spacing")
    if h:
        return float(h)
    # A loaded file has no stats: the median polygon edge is about a spacing.
    if len(table) == 0:
        return 1.0
    p = result.vertices[table.pairs]
    return float(np.median(np.linalg.norm(p[:, 0] - p[:, 1], axis=1))) or 1.0


def structure(result, spacing=None, merge_slivers=True, rim_radius=1.0, sliver_area=2.0,
              reach=1.0, tube_length=3.0, join=1.0, shape=None):
    """AxisStructure of ``result`` (a MedialAxisResult).

    spacing        length unit h of the tolerances; None: result.stats["spacing"] (for a loaded
                   file, the median polygon edge)
    merge_slivers  True: sheets of less area than sliver_area * h^2 (h the local spacing at thin
                   walls, see slivers.local_spacing) join the real sheet they
                   touch within reach * h, or form tubes (curves) when a cluster of them spans
                   tube_length * h or more (see slivers.py); False: the raw labels
    rim_radius     a sheet's border edge is a rim when the medial radius at both ends is at most
                   rim_radius * h (the ball reaches the boundary within a spacing), or when it is
                   a completion face's; else a free border
    join           seams shorter than join * h between two meeting points are contracted
                   (junctions.py); border edges of a sheet closer than that are one border
    shape          None, or the source the axis was computed from (as for compute(): a path,
                   BREP text, a Part.Shape, a _core.Shape): then each sheet also gets
                   "touches", [[face index, share], ...], the faces of its solid its balls touch
                   (touching.py; for a wall its two faces, about half the probes each), and
                   each rim the faces beside it (those of the convex edge it lies on)
    """
    vertices = np.asarray(result.vertices, dtype=np.float64)
    radius = np.asarray(result.radius, dtype=np.float64)
    kind = np.asarray(result.face_kind)
    n_faces, n_vertices = len(result.faces), len(vertices)
    table = edge_table(result.faces, n_vertices)
    h = _spacing_of(result, spacing, table)
    area = face_areas(vertices, result.faces) if n_faces else np.zeros(0)
    labels, count = raw_sheets(table, n_faces)
    if merge_slivers and n_faces:
        sheet, tube, core = resolve_slivers(table, labels, count, area, vertices, radius,
                                            result.faces, h, sliver_area, reach, tube_length)
    else:
        sheet, tube, core = labels, np.full(n_faces, -1, dtype=np.int64), np.ones(n_faces, bool)
    sheet, n_sheets = renumber_by_size(sheet, area)
    kinds = classify_edges(table, sheet, core, kind, radius, rim_radius * h) if len(table) else \
        np.zeros(0, dtype=np.uint8)
    sheets = sheet_table(sheet, n_sheets, vertices, radius, result.faces, area, kind)
    raw_per_sheet = np.zeros(n_sheets, dtype=np.int64)
    if n_faces and n_sheets:
        pairs = np.unique(np.stack([sheet, labels], axis=1)[sheet >= 0], axis=0)
        raw_per_sheet = np.bincount(pairs[:, 0], minlength=n_sheets)
    for s, d in enumerate(sheets):
        d.update(seams=[], rim_length=0.0, free_length=0.0, slivers=int(raw_per_sheet[s] - 1))

    # (edge, sheet) keys, sorted: the sheets of each edge as CSR slices.
    edge_of = np.repeat(np.arange(len(table)), table.count)
    face_sheet_of = sheet[table.faces]
    keyed = face_sheet_of >= 0
    edge_sheet_key = np.unique(edge_of[keyed] * (n_sheets + 1) + face_sheet_of[keyed])
    key_start = np.searchsorted(edge_sheet_key // (n_sheets + 1), np.arange(len(table) + 1))

    def sheets_of_edges(edges):
        n = key_start[edges + 1] - key_start[edges]
        at = np.repeat(key_start[edges] - np.cumsum(n) + n, n) + np.arange(n.sum())
        ids, times = np.unique(edge_sheet_key[at] % (n_sheets + 1), return_counts=True)
        order = np.lexsort((ids, -times))
        return ids[order].tolist(), times[order].tolist()

    curves_edges = edge_curves(result)
    curves_tubes = tube_curves(table, tube, vertices, radius, h)
    for k, c in enumerate(curves_tubes):
        c["tube"] = k
    curves = link_curves(curves_edges + curves_tubes, vertices, radius, tube_length * h)
    # A tube face's curve: the one its tube went into.
    tube_to_curve = np.full(len(curves_tubes) + 1, -1, dtype=np.int64)
    for k, c in enumerate(curves):
        for t in c.pop("tubes", [c["tube"]] if "tube" in c else []):
            tube_to_curve[t] = k
        c.pop("tube", None)
    face_curve = np.where(tube >= 0, tube_to_curve[tube], -1)

    seam_rows = np.flatnonzero(kinds == SEAM)
    raw_seams, junctions, junction_of = seams_and_junctions(
        table.pairs[seam_rows], [c["vertices"] for c in curves if not c["closed"]],
        vertices, radius, join * h)
    seams = []
    for path, edges, closed, length, ends in raw_seams:
        ids, n = sheets_of_edges(seam_rows[edges])
        for s in ids:
            sheets[s]["seams"].append(len(seams))
        seams.append({"vertices": path, "length": length, "sheets": ids, "sheet_edges": n,
                      "closed": closed, "ends": ends})
    # The sheets at each junction: those of the faces at its vertices.
    rows = face_vertex_rows(result.faces)
    corner = np.asarray(result.faces.indices, dtype=np.int64)
    hit = (junction_of[corner] >= 0) & (sheet[rows] >= 0)
    jkeys = np.unique(junction_of[corner[hit]] * (n_sheets + 1) + sheet[rows[hit]])
    jstart = np.searchsorted(jkeys // (n_sheets + 1), np.arange(len(junctions) + 1))
    for j, d in enumerate(junctions):
        d["sheets"] = (jkeys[jstart[j]:jstart[j + 1]] % (n_sheets + 1)).tolist()

    def borders(wanted, key):
        rows_w = np.flatnonzero(kinds == wanted)
        # A border edge has one sheet face: its sheet is the edge's one key.
        out = group_borders(table.pairs[rows_w], edge_sheet_key[key_start[rows_w]] % (n_sheets + 1),
                            vertices, radius, join * h)
        for b in out:
            sheets[b["sheet"]][key] += b["length"]
        return out

    rims = borders(RIM, "rim_length")
    # The input solid of each table row (an assembly's solids share no vertex).
    vertex_solid = np.full(n_vertices, -1, dtype=np.int64)
    vertex_solid[np.asarray(result.edges, dtype=np.int64).ravel()] = np.repeat(
        np.asarray(result.edge_solid, dtype=np.int64), 2)
    vertex_solid[corner] = np.asarray(result.face_solid, dtype=np.int64)[rows]
    ids, first = np.unique(sheet[rows], return_index=True)  # each sheet's first corner
    for k, at in zip(ids.tolist(), first.tolist()):
        if k >= 0:
            sheets[k]["solid"] = int(vertex_solid[corner[at]])
    for d in seams + curves:
        d["solid"] = int(vertex_solid[d["vertices"][0]])
    if shape is not None:
        from .. import _core
        from ..api import read_shape
        solids = _core.extract_solids(read_shape(shape))
        for d, touches in zip(sheets, touching_faces(result, sheet, n_sheets, solids)):
            d["touches"] = touches
        # A rim's faces: the one face of each of its edges (rows found by their sorted keys).
        keys = table.pairs[:, 0] * n_vertices + table.pairs[:, 1]
        groups = [table.first_faces(np.searchsorted(keys, b["edges"][:, 0] * n_vertices
                                                    + b["edges"][:, 1])) for b in rims]
        for b, touches in zip(rims, touching(result, groups, solids)):
            b["touches"] = touches
    return AxisStructure(face_sheet=sheet, face_curve=face_curve, edges=table.pairs,
                         edge_kind=kinds, edge_kind_names=dict(NAMES), sheets=sheets, seams=seams,
                         junctions=junctions, rims=rims,
                         free=borders(FREE, "free_length"), curves=curves, spacing=h)
