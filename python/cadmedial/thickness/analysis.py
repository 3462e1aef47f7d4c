"""cadmedial.thickness(): the wall thickness of a solid's surface from its medial axis."""

import builtins
import math
import time
from dataclasses import dataclass, field

import numpy as np

from .. import _core
from ..api import _number, compute
from .convex_edges import distance_to_convex_edges, edge_bound
from .refine import edge_normals_from_faces, refine_thickness
from .regions import find_regions
from .shape_source import solids_of
from .sphere import sphere_thickness
from .statistics import HISTOGRAM_BINS, thickness_statistics
from .surface_mesh import surface_mesh

CORNER_POLICIES = ("exclude", "zero")
# corners="exclude" also leaves out points whose ball is held by a convex edge rather than by an
# opposite wall: value above what the edge allows divided by 1 + this (a plate's rim reads its
# thickness only at mid-height, less towards both edges; that is the corner, not a thin wall).
# 0.25, not less: today's engine reads up to ~15 % under the edge's bound within a few spacings
# of a convex edge (rims of a 4 mm plate at 0.7 from the edge read 1.19 for 1.38), which made
# false thin patches of a few points along every rim.
EDGE_LIMITED_TOL = 0.25
# The exact refinement (refine.py) gets at most the medial axis's own compute time, and at least
# REFINE_FLOOR seconds (a reused medial result took no time here). A third of it (what the 1.3x
# target would leave) refined 8 % of a tube's points on a loaded machine; the rest of the
# analysis (surface mesh, 4-D queries) already takes 1.5-12x the medial time (docs/thickness.md).
REFINE_SHARE = 1.0
REFINE_FLOOR = 2.0


@dataclass
class ThicknessResult:
    """The thickness field on the surface mesh and what was found in it.

    points (N, 3), values (N,) sphere thickness, counted (N,) bool (False: in the band next to a
    convex edge that corners="exclude" leaves out of statistics and regions), area (N,) surface
    area per point, edge_distance (N,) distance to the nearest convex edge (inf without one),
    triangles (T, 3) and triangle_face (T,) (index into face_names, "Face12"), gap (N,) how far
    outside its ball a point lies, relative to the radius, ball (N,) the medial vertex used,
    thin_regions / thick_regions (lists of dicts, see regions.find_regions), statistics (dict,
    see statistics.thickness_statistics), settings (dict), timings (seconds per stage), medial
    (the MedialAxisResult it was built on)."""
    points: np.ndarray
    values: np.ndarray
    counted: np.ndarray
    area: np.ndarray
    edge_distance: np.ndarray
    triangles: np.ndarray
    triangle_face: np.ndarray
    face_names: list
    gap: np.ndarray
    ball: np.ndarray
    thin_regions: list
    thick_regions: list
    statistics: dict
    settings: dict
    timings: dict = field(default_factory=dict)
    medial: object = None
    refined: np.ndarray = None

    @property
    def passed(self):
        """True when no counted point is thinner than min or thicker than max."""
        return not self.thin_regions and not self.thick_regions

    def to_dict(self):
        """Plain data (JSON-ready) without the per-point arrays."""
        strip = lambda regions: [{k: v for k, v in g.items() if k != "point_indices"}
                                 for g in regions]
        return {"passed": self.passed, "settings": self.settings, "statistics": self.statistics,
                "thin_regions": strip(self.thin_regions),
                "thick_regions": strip(self.thick_regions), "timings": self.timings,
                "points": int(len(self.points))}


def _limit(name, value):
    if value is None:
        return None
    v = _number(name, value)
    if not (math.isfinite(v) and v > 0):
        raise _core.InvalidInput("%s must be a positive thickness, got %r" % (name, value))
    return v


def check_settings(minimum, maximum, corners):
    """(min, max) as floats or None; InvalidInput on absurd limits or an unknown policy."""
    minimum, maximum = _limit("min", minimum), _limit("max", maximum)
    if minimum is not None and maximum is not None and not minimum < maximum:
        raise _core.InvalidInput("min (%g) must be less than max (%g)" % (minimum, maximum))
    if corners not in CORNER_POLICIES:
        raise _core.InvalidInput("corners must be one of %s, got %r"
                                 % (", ".join(CORNER_POLICIES), corners))
    return minimum, maximum


def _on_one_face(mesh):
    """(N,) bool: the point's triangles all lie on one B-rep face (not on an edge between two;
    a seam's points are on one face)."""
    t, f = mesh.triangles.ravel(), np.repeat(mesh.triangle_face, 3)
    lo = np.full(len(mesh.points), np.iinfo(np.int64).max)
    hi = np.full(len(mesh.points), -1)
    np.minimum.at(lo, t, f)
    np.maximum.at(hi, t, f)
    return lo == hi


def _vertex_solid(medial):
    solid = np.zeros(medial.num_vertices, dtype=np.int64)
    solid[medial.faces.indices] = np.repeat(medial.face_solid, medial.faces.sizes())
    if medial.num_edges:
        solid[medial.edges.ravel()] = np.repeat(medial.edge_solid, 2)
    return solid


def thickness(source, min=None, max=None, corners="exclude", samples=None, spacing=None,
              medial=None, max_edge=None, deflection=None, bins=HISTOGRAM_BINS, progress=None,
              refine_budget=None):
    """The sphere wall thickness over the surface of every solid of ``source``.

    source     a STEP/IGES/BREP path, BREP text or a FreeCAD Part.Shape
    min, max   thin / thick limits in model units (None: not checked); regions are the connected
               patches below min and above max
    corners    "exclude" (default) leaves out of statistics and regions the points within one
               sample spacing of a convex edge, where the sphere thickness goes to zero, and
               those whose ball is held by a convex edge rather than an opposite wall (value
               at least 2 a tan(alpha / 2) / 1.25 at distance a from an edge of interior angle
               alpha: a plate's rim); "zero" counts every point, with at most that value near
               an edge (the exact sphere thickness beside a planar wedge), so every convex
               edge reads zero
    samples, spacing  the medial axis's density (see cadmedial.compute)
    medial     a MedialAxisResult of the same shape, to reuse instead of computing it
    max_edge   longest side of the surface mesh; default 1.5 sample spacings (its sides are then
               0.75 to 1.5 spacings long: about as many points as samples)
    deflection BRepMesh's linear deflection; default a 20th of the spacing
    bins       histogram bins (count or edges)
    progress   passed to cadmedial.compute
    refine_budget  seconds for the exact refinement of the medial reading (refine.py), thinnest
               points first; None: REFINE_SHARE of the medial axis's time, at least REFINE_FLOOR;
               0: none (the medial reading); math.inf: every point

    Returns a ThicknessResult. Raises InvalidInput (bad source or settings) or what compute
    raises."""
    minimum, maximum = check_settings(min, max, corners)
    timings = {}
    t0 = time.perf_counter()
    c0 = time.process_time()  # CPU seconds too: wall times on a shared machine say little
    shape, solids = solids_of(source)
    timings["read"] = time.perf_counter() - t0
    if medial is None:
        kwargs = {} if samples is None and spacing is None else {"samples": samples,
                                                                  "spacing": spacing}
        medial = compute(shape, progress=progress, **kwargs)
    t1 = time.perf_counter()
    c1 = time.process_time()
    timings["medial_axis"] = t1 - t0 - timings["read"]
    h = float(medial.stats.get("spacing") or 0.0)
    if not h > 0:  # a loaded result has no stats: a spacing from the vertices' spread
        box = shape.BoundBox
        h = box.DiagonalLength / 200.0
    max_edge = 1.5 * h if max_edge is None else _limit("max_edge", max_edge)
    deflection = h / 20.0 if deflection is None else _limit("deflection", deflection)
    # The solids for the engine's exact distance: the surface mesh's projections, the refinement.
    core_solids = [_core.read_brep_string(solid.exportBrepToString()) for solid in solids]
    mesh = surface_mesh(shape, solids, max_edge, deflection, exact=core_solids)
    t2 = time.perf_counter()
    timings["surface_mesh"] = t2 - t1

    values = np.empty(len(mesh.points))
    start = np.empty(len(mesh.points))  # the largest ball in reach: where refinement starts
    gap = np.empty(len(mesh.points))
    ball = np.empty(len(mesh.points), dtype=np.int64)
    vsolid = _vertex_solid(medial)
    # Each solid's points against its own balls, when the engine's solids are FreeCAD's (same
    # count, each with balls); otherwise all balls (touching solids may then lend a ball).
    per_solid = (len(medial.stats.get("solids", [])) == len(solids) and len(solids) > 1
                 and np.all(np.bincount(vsolid, minlength=len(solids))[:len(solids)] > 0))
    groups = range(len(solids)) if per_solid else [None]
    for s in groups:
        pick = np.ones(len(mesh.points), bool) if s is None else mesh.point_solid == s
        balls = np.arange(medial.num_vertices) if s is None else np.nonzero(vsolid == s)[0]
        if len(balls) == 0:
            raise _core.GeometryError("the medial axis has no vertices")
        top = np.empty(int(pick.sum()))
        v, g, b = sphere_thickness(mesh.points[pick], medial.vertices[balls], medial.radius[balls],
                                   reach=h, upper=top)
        values[pick], gap[pick], ball[pick], start[pick] = v, g, balls[b], top
    # On an edge between two faces the balls touching either face contain the point, and the
    # largest is its thickness (a concave edge): the largest ball in reach, not the weighted mean
    # (which made io1-cm-214's thinnest counted value 1.87, at an edge point, for 2). Inside a
    # face the tangent ball is one, and the weighted mean reads it (sphere.SIGMA).
    one_face = _on_one_face(mesh)
    values[~one_face] = start[~one_face]
    t3 = time.perf_counter()
    timings["sphere"] = t3 - t2

    band = h
    dist, angle = distance_to_convex_edges(mesh, max_edge / 4.0)
    bound = edge_bound(dist, angle)
    if refine_budget is None:
        refine_budget = builtins.max(REFINE_FLOOR, REFINE_SHARE * timings["medial_axis"])
    refined = np.zeros(len(values), bool)
    # Outside the corner band only (inside it the edge's bound rules), thinnest first, and on
    # one face only: at a point on an edge between faces (even a convex one turning by less than
    # the band's 10 degrees) no ball is tangent, and the exact value would be about 0 there.
    todo = np.nonzero((dist >= band) & one_face)[0]
    todo = todo[np.argsort(values[todo], kind="stable")]
    diag = shape.BoundBox.DiagonalLength
    t_refine = time.perf_counter()
    edge_normals = edge_normals_from_faces(list(shape.Faces), mesh) if len(todo) else None
    for s, solid in enumerate(solids):
        spent = time.perf_counter() - t_refine
        if spent >= refine_budget:
            break
        mine = todo[mesh.point_solid[todo] == s]
        if not len(mine):
            continue
        v, ok = refine_thickness(core_solids[s], mesh.points[mine], values[mine], max_edge, diag,
                                 budget=refine_budget - spent,
                                 edge_normals=lambda i, feet, mine=mine: edge_normals(mine[i], feet),
                                 start=start[mine])
        values[mine], refined[mine] = v, ok
    t4 = time.perf_counter()
    timings["refine"] = t4 - t_refine
    if corners == "zero":
        values = np.minimum(values, bound)
        counted = np.ones(len(values), bool)
    else:
        counted = (dist >= band) & (bound > (1.0 + EDGE_LIMITED_TOL) * values)
    area = mesh.point_areas()
    stats = thickness_statistics(values, area, counted, minimum, maximum, bins)
    thin = find_regions(mesh, values, area, counted, minimum, "thin")
    thick = find_regions(mesh, values, area, counted, maximum, "thick")
    t5 = time.perf_counter()
    timings["corners_regions"] = (t_refine - t3) + (t5 - t4)
    timings["analysis"] = t5 - t1
    timings["total"] = t5 - t0
    timings["medial_axis_cpu"] = c1 - c0  # (with the read)
    timings["analysis_cpu"] = time.process_time() - c1
    settings = {"min": minimum, "max": maximum, "corners": corners, "spacing": h,
                "band": band, "max_edge": max_edge, "deflection": deflection,
                "contain_tol": 0.01, "solids": len(solids), "refine_budget": refine_budget,
                "refined": int(refined.sum())}
    return ThicknessResult(mesh.points, values, counted, area, dist, mesh.triangles,
                           mesh.triangle_face, mesh.face_names, gap, ball, thin, thick, stats,
                           settings, timings, medial, refined)
