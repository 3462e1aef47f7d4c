"""structure(): sheets, seams, junctions, rims, free borders and curves of a MedialAxisResult."""

import numpy as np

from .borders import group_borders
from .curves import curves_of
from .edge_kinds import FREE, NAMES, RIM, SEAM, classify_edges
from .edge_sheets import EdgeSheets
from .edge_table import edge_table
from .junctions import junction_sheets, seams_and_junctions, sheets_near_curve_ends
from .sheets import face_areas, raw_sheets, renumber_by_size, sheet_table
from .slivers import resolve_slivers
from .touching import add_touches

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
                seams meet), curve_ends (curves ending at it), sheets (ids of its faces; where
                a curve ends, also of the sheets within tube_length * h)
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
    n_faces = len(result.faces)
    table = edge_table(result.faces, len(vertices))
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
    _count_slivers(sheets, sheet, labels)
    on_edge = EdgeSheets(table, sheet, n_sheets)
    curves, face_curve = curves_of(result, table, tube, vertices, radius, h, tube_length)
    seams, junctions = _seams(table, kinds, on_edge, sheets, curves, vertices, radius, join * h,
                              result.faces, sheet)
    sheets_near_curve_ends(junctions, result.faces, sheet, vertices, tube_length * h)

    def borders(wanted, key):
        rows = np.flatnonzero(kinds == wanted)
        out = group_borders(table.pairs[rows], on_edge.first(rows), vertices, radius, join * h)
        for b in out:
            sheets[b["sheet"]][key] += b["length"]
        return out

    rims, free = borders(RIM, "rim_length"), borders(FREE, "free_length")
    _tag_solids(result, sheet, sheets, seams + curves)
    if shape is not None:
        add_touches(result, shape, table, sheet, sheets, rims)
    return AxisStructure(face_sheet=sheet, face_curve=face_curve, edges=table.pairs,
                         edge_kind=kinds, edge_kind_names=dict(NAMES), sheets=sheets, seams=seams,
                         junctions=junctions, rims=rims, free=free, curves=curves, spacing=h)


def _count_slivers(sheets, sheet, labels):
    """Sets each sheet's seams [], rim_length, free_length 0 and slivers: the raw sheets merged
    into it besides its own."""
    raw = np.zeros(len(sheets), dtype=np.int64)
    if len(sheets):
        used = sheet >= 0
        pairs = np.unique(sheet[used] * (int(labels.max()) + 1) + labels[used])
        raw = np.bincount(pairs // (int(labels.max()) + 1), minlength=len(sheets))
    for s, d in enumerate(sheets):
        d.update(seams=[], rim_length=0.0, free_length=0.0, slivers=int(raw[s] - 1))


def _seams(table, kinds, on_edge, sheets, curves, vertices, radius, join, faces, sheet):
    """(seams, junctions) as AxisStructure lists; each sheet's "seams" filled in."""
    rows = np.flatnonzero(kinds == SEAM)
    raw, junctions, junction_of = seams_and_junctions(
        table.pairs[rows], [c["vertices"] for c in curves if not c["closed"]], vertices, radius,
        join)
    seams = []
    for path, edges, closed, length, ends in raw:
        ids, n = on_edge.tally(rows[edges])
        for s in ids:
            sheets[s]["seams"].append(len(seams))
        seams.append({"vertices": path, "length": length, "sheets": ids, "sheet_edges": n,
                      "closed": closed, "ends": ends})
    for d, ids in zip(junctions, junction_sheets(junction_of, faces, sheet, len(sheets))):
        d["sheets"] = ids
    return seams, junctions


def _tag_solids(result, sheet, sheets, polylines):
    """Sets "solid" of each sheet (that of its first face) and of each dict of ``polylines``
    (that of its first vertex; an assembly's solids share no vertex)."""
    vertex_solid = np.full(result.num_vertices, -1, dtype=np.int64)
    vertex_solid[np.asarray(result.edges, dtype=np.int64).ravel()] = np.repeat(
        np.asarray(result.edge_solid, dtype=np.int64), 2)
    vertex_solid[np.asarray(result.faces.indices, dtype=np.int64)] = np.repeat(
        np.asarray(result.face_solid, dtype=np.int64), result.faces.sizes())
    ids, first = np.unique(sheet, return_index=True)
    for k, f in zip(ids.tolist(), first.tolist()):
        if k >= 0:
            sheets[k]["solid"] = int(np.asarray(result.face_solid)[f])
    for d in polylines:
        d["solid"] = int(vertex_solid[d["vertices"][0]])
