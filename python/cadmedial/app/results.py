"""From a MedialAxisResult to what a MedialAxis object keeps (mesh, colours, counts, PLY file), and
back. Split in two so that the slow half can run in a worker thread:

    stored = prepare_result(result, simplify=0.2)  # any thread: simplifies (0: keeps the full
                                                   # axis), builds the Mesh, colours, PLY file
    store_result(obj, stored)         # the thread that owns the document: assigns properties

No proxy class here, so that both document objects can import this module without importing
each other.
"""

import os
import shutil
import tempfile

import FreeCAD as App
import Mesh

import cadmedial
from . import color_range as colors
from .compact_mesh import compact_of, simplify_seconds, summary
from .registry import let_gui_breathe


class StoredResult:
    """What store_result() assigns, built from one MedialAxisResult. Owns a temporary folder
    holding the PLY file until store_result() (or discard()) removes it.

    full     the engine's MedialAxisResult
    source   the shape it was computed from (a _core.Shape), or None: the compact mesh's
             vertices are moved onto its exact axis first
    percent  the Simplify it was made for (0: the full axis)
    result   what the object shows and keeps: the compact mesh of full, or full itself for 0"""

    def __init__(self, result, color_range=None, simplify=0.0, source=None, progress=None):
        self.full = result
        self.source = source
        self.percent = float(simplify or 0.0)
        result = self.result = compact_of(result, self.percent, source, progress)
        self.mesh = Mesh.Mesh()
        # False: no manifold check. The medial surface is non-manifold where sheets meet, and the
        # check (also done by Mesh.Mesh((points, facets))) would delete every facet at a junction.
        points = [App.Vector(*p) for p in result.vertices.tolist()]
        self.mesh.addFacets((points, [tuple(t) for t in result.triangles().tolist()]), False)
        if result.num_vertices:
            self.low, self.high = float(result.radius.min()), float(result.radius.max())
        else:
            self.low = self.high = 0.0
        # color_range: the object's own (see color_range.set_range), or None: the radii's.
        self.color_range = color_range or (self.low, self.high)
        self.colors = colors.radius_colors(result.radius, *self.color_range)
        self.folder = tempfile.mkdtemp(prefix="cadmedial-")
        self.ply = os.path.join(self.folder, "medial_axis.ply")
        result.save(self.ply)

    def discard(self):
        shutil.rmtree(self.folder, ignore_errors=True)


def prepare_result(result, color_range=None, simplify=0.0, source=None, progress=None):
    """The StoredResult of a MedialAxisResult (slow: run it off the GUI thread), coloured for
    color_range (low, high), or for its radii when None; simplify: percent of the diagonal for
    the compact mesh (compact_mesh.py), 0 for the full axis; source: the shape it was computed
    from (its vertices are snapped onto that shape's exact axis first); progress as for
    cadmedial.simplify."""
    return StoredResult(result, color_range, simplify, source, progress)


def store_result(obj, stored):
    """Puts a StoredResult (or a MedialAxisResult, prepared here as it is) into obj's Mesh,
    colours, counts and ResultFile: those of the compact mesh when it was made for a Simplify."""
    if not isinstance(stored, StoredResult):
        stored = prepare_result(stored, colors.set_range(obj))
    result = stored.result
    try:
        # Each of the mesh and the colours takes the GUI about 3 s per million vertices to
        # take in (FreeCAD's view provider, in the GUI thread): let it draw in between.
        obj.Mesh = stored.mesh
        let_gui_breathe()
        obj.RadiusMin, obj.RadiusMax = stored.low, stored.high
        colors.follow_radii(obj)
        wanted = colors.color_range(obj)
        if wanted != stored.color_range:  # the range was set since the compute started
            stored.colors = colors.radius_colors(result.radius, *wanted)
        obj.RadiusColors = stored.colors
        let_gui_breathe()
        stats = result.stats
        obj.SampleCount = int(stats.get("samples", 0))
        solids = stats.get("solids", [])
        obj.SpacingUsed = min((float(s["spacing"]) for s in solids if "spacing" in s),
                              default=float(stats.get("spacing", 0.0)))
        obj.Refinements = max((int(s.get("refinements", 0)) for s in solids), default=0)
        obj.VertexCount = result.num_vertices
        obj.FaceCount = result.num_faces
        obj.EdgeCount = result.num_edges
        timings = ["%s: %.3f s" % (stage, seconds)
                   for stage, seconds in stats.get("timings", {}).items()]
        if "simplify" in stats:
            timings.append("simplify: %.3f s" % simplify_seconds(result))
        obj.Timings = timings
        if "Simplified" in obj.PropertiesList:
            obj.Simplified = summary(result)
        store_thinnest_wall(obj, stats)
        obj.ResultFile = stored.ply  # FreeCAD copies it into the document's own folder
    finally:
        stored.discard()


def store_thinnest_wall(obj, stats):
    """ThinnestWall / ThinnestWallAt from the engine's stats (the smallest wall thickness it
    measured while sampling, and where); 0 and the origin when it reported none."""
    walls = [(float(s["thinnest_wall"]), s.get("thinnest_wall_at"))
             for s in stats.get("solids", []) if s.get("thinnest_wall")]
    if "ThinnestWall" not in obj.PropertiesList:
        return
    if not walls:
        obj.ThinnestWall = 0.0
        obj.ThinnestWallAt = App.Vector()
        return
    thickness, where = min(walls, key=lambda wall: wall[0])
    obj.ThinnestWall = thickness
    obj.ThinnestWallAt = App.Vector(*where) if where is not None else App.Vector()


def medial_result(obj):
    """The MedialAxisResult of a MedialAxis object, the one its Mesh shows (the compact mesh when
    Simplify > 0): in memory after a compute, else read from its ResultFile (after reopening a
    document; its stats are empty then). Raises cadmedial.InvalidInput when there is none."""
    proxy = obj.Proxy
    if proxy.result is None:
        if not obj.ResultFile or not os.path.isfile(obj.ResultFile):
            raise cadmedial.InvalidInput("%s has no result yet: recompute it" % obj.Label)
        proxy.result = cadmedial.load(obj.ResultFile)
    return proxy.result


def recolour(obj):
    """RadiusColors for obj's colour range, from the radii of its result (read from ResultFile
    after a reopen; no engine run). Does nothing while obj has no result of its mesh's size."""
    try:
        radius = medial_result(obj).radius
    except cadmedial.InvalidInput:  # no result file (yet): the colours stay
        return
    if len(radius) == obj.VertexCount:
        obj.RadiusColors = colors.radius_colors(radius, *colors.color_range(obj))
