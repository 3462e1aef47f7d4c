"""The MedialAxis document object: a parametric Mesh::FeaturePython that holds the medial axis of
its Source, coloured by medial radius.

Saved inside .FCStd files, keep them: module ``cadmedial.app.medial_axis``, class ``MedialAxis``,
object type ``Mesh::FeaturePython``, property names below.

What the document keeps (so reopening needs no recompute), of the mesh the object shows: the
compact mesh of the axis when Simplify > 0 (new objects: 0.2 % of the diagonal; compact_mesh.py),
the full axis for 0 (documents saved before Simplify existed):
  Mesh          the polygons fanned into triangles (all of them: non-manifold junctions too);
                points in the engine's vertex order
  RadiusColors  one colour per point (the view provider's per-vertex colouring), for the
                colour range of color_range.py
  ResultFile    the engine's own mesh as binary PLY (polygons, radius, kind, solid, 1-D edges)
                for export and for the Part shape
The full axis stays in memory (proxy.full) after a compute, so that a new Simplify only simplifies
again; after a reopen it is not there, and a new Simplify computes the axis again.
The 1-D edges of the axis (where it is a curve no face carries) cannot be shown by a Mesh
feature: EdgeCount says how many there are, and the MedialShape (Part) holds them as edges.
"""

import hashlib
import time

import FreeCAD as App
import Part

import cadmedial
from cadmedial.api import refines_by_default

from . import registry
from .compact_mesh import (DEFAULT_PERCENT, SIMPLIFIED_DOC, add_simplify, simplify_of,
                           simplify_seconds, summary)
from .color_range import add_color_range, range_changed, set_range
from .registry import attach_view_provider
from .medial_shape import make_medial_shape
from .results import (StoredResult, medial_result, prepare_result,  # noqa: F401 (medial_result: API)
                      recolour, store_result)

INPUTS = "Medial Axis"
OUTPUTS = "Result"
READ_ONLY, HIDDEN = 1, 2
# Read-only counts added after the first release: documents saved before lack them, and get them
# when reopened (see onDocumentRestored). Their default, 0, is right for those: no edges, no
# refinement then.
LATER_COUNTS = [("App::PropertyInteger", "EdgeCount",
                 "1-D edges of the medial mesh (segments of the axis that no face carries)"),
                ("App::PropertyInteger", "Refinements",
                 "Times a solid was sampled again, finer, because its axis's topology was wrong "
                 "(the most over the solids)"),
                ("App::PropertyLength", "ThinnestWall",
                 "Thickness of the thinnest wall the samples found (0: no wall under 2 spacings)"),
                ("App::PropertyVector", "ThinnestWallAt", "Where that thinnest wall is"),
                ("App::PropertyString", "Simplified", SIMPLIFIED_DOC)]
MIN_FEATURE_DOC = ("Walls thinner than this are not sampled finer than it needs (a warning names "
                   "them and where); 0: none")
REFINE_DOC = ("Sample a solid again with 2.5 times the samples (at most twice) where its medial "
              "axis's Euler characteristic is not the solid's")


class MedialAxis:
    """Proxy of the MedialAxis feature. Its execute() computes; a failure is reported in the
    report view and in Status, the object gets FreeCAD's error mark, and the last good result
    stays."""

    Type = "MedialAxis"

    def __init__(self, obj):
        obj.Proxy = self
        self._init_transient()
        add = obj.addProperty
        add("App::PropertyLink", "Source", INPUTS, "The solid (or shape of solids) to compute the medial axis of")
        add("App::PropertyLength", "Spacing", INPUTS, "Boundary sample spacing; 0 derives it from Samples")
        add("App::PropertyInteger", "Samples", INPUTS,
            "Approximate number of boundary samples, used when Spacing is 0; both 0: automatic "
            "density (as dense as the part needs)")
        add("App::PropertyFloat", "Theta", INPUTS, "Angle condition threshold in degrees, in (0, 90)")
        add("App::PropertyFloat", "Rho", INPUTS, "Ratio condition threshold, > 0")
        add("App::PropertyBool", "Refine", INPUTS, REFINE_DOC)
        add("App::PropertyLength", "MinFeature", INPUTS, MIN_FEATURE_DOC)
        add_simplify(obj, DEFAULT_PERCENT)
        obj.Theta = 5.0
        obj.Rho = 8.0
        obj.Refine = True
        for kind, name, doc in [
                ("App::PropertyInteger", "SampleCount", "Number of boundary samples used"),
                ("App::PropertyInteger", "VertexCount", "Vertices of the medial mesh"),
                ("App::PropertyInteger", "FaceCount",
                 "Polygons of the medial mesh (triangles of the compact mesh when Simplify > 0)"),
                ("App::PropertyLength", "SpacingUsed",
                 "Sample spacing used (the finest, where a solid was refined)"),
                ("App::PropertyLength", "RadiusMin", "Smallest medial radius"),
                ("App::PropertyLength", "RadiusMax", "Largest medial radius"),
                ("App::PropertyFloat", "ComputeTime", "Seconds of the last compute"),
                ("App::PropertyStringList", "Timings", "Seconds per stage of the last compute"),
                ("App::PropertyString", "Status", "'ok', or why the last compute failed")]:
            add(kind, name, OUTPUTS, doc)
            obj.setEditorMode(name, READ_ONLY)
        add_later_counts(obj)
        add("App::PropertyColorList", "RadiusColors", OUTPUTS, "Colour of each mesh point by medial radius")
        add("App::PropertyFileIncluded", "ResultFile", OUTPUTS, "The medial mesh as binary PLY")
        obj.setEditorMode("RadiusColors", HIDDEN)
        obj.setEditorMode("ResultFile", HIDDEN)
        add_color_range(obj)

    def _init_transient(self):
        self.result = None    # the last MedialAxisResult shown (compact or full), in memory only
        self.full = None      # the full axis it was simplified from, in memory only
        self.full_key = None  # (parameters, source digest) self.full was computed for
        self.pending = None   # (parameters, result) computed before the object existed

    # Saved state: the type only; the result lives in the document's properties.
    def __getstate__(self):
        return {"Type": self.Type}

    def __setstate__(self, state):
        self._init_transient()

    dumps, loads = __getstate__, __setstate__  # the names FreeCAD 0.21+ looks for

    def onDocumentRestored(self, obj):
        self._init_transient()
        add_later_counts(obj)
        if "Refine" not in obj.PropertiesList:
            # Off for a document saved before it existed: a recompute gives what it gave then.
            obj.addProperty("App::PropertyBool", "Refine", INPUTS, REFINE_DOC)
            obj.Refine = False
        if "MinFeature" not in obj.PropertiesList:
            obj.addProperty("App::PropertyLength", "MinFeature", INPUTS, MIN_FEATURE_DOC)
        add_simplify(obj, 0.0)  # 0 (the full axis) for a document saved before it: what it showed
        add_color_range(obj)  # automatic for a document saved before it: what it showed

    def onChanged(self, obj, prop):
        if range_changed(obj, prop):
            recolour(obj)

    def execute(self, obj):
        started = time.perf_counter()
        try:
            stored, reused = self._stored_for(obj)
        except Exception as error:  # any failure: report it, keep the last good result
            obj.Status = "failed: %s" % error
            App.Console.PrintError("%s: medial axis not updated: %s\n" % (obj.Label, error))
            # Raised, FreeCAD marks the object in error in the tree (the properties stay as
            # they were): the Status says why.
            raise FeatureError("%s: %s" % (obj.Label, error)) from None
        result = self.result = stored.result
        self.full = stored.full
        store_result(obj, stored)
        # The engine's total (a result computed before the object existed took no time here)
        # and the simplification's; only the time spent here when the axis was not computed.
        total = result.stats.get("timings", {}).get("total")
        if reused or total is None:
            obj.ComputeTime = time.perf_counter() - started
        else:
            obj.ComputeTime = float(total) + simplify_seconds(result)
        obj.Status = "ok"
        if summary(result):
            App.Console.PrintMessage("%s: compact: %s%s\n" % (
                obj.Label, summary(result), " (the axis not computed again)" if reused else ""))
        # e.g. walls too thin for the spacing: the result stands, the user should know.
        for warning in result.stats.get("warnings", []):
            App.Console.PrintWarning("%s: %s\n" % (obj.Label, warning))
        # e.g. a construction surface beside the solid: left out of the axis, which the user
        # may not expect of a compound.
        for what in result.stats.get("skipped", []):
            App.Console.PrintWarning("%s: skipped %s\n" % (obj.Label, what))

    def _stored_for(self, obj):
        """(StoredResult for obj's parameters and Simplify, whether the full axis in memory was
        reused): the result given before the object existed, else the full axis in memory when
        it was computed for these parameters and this source shape (only the Simplify changed:
        simplified again, no engine run), else a new compute."""
        percent = simplify_of(obj)
        key = (parameters_of(obj), source_digest(obj))
        pending, self.pending = self.pending, None
        reused = False
        if pending is not None and pending[0] == key[0]:
            got = pending[1]
        elif self.full is not None and self.full_key == key:
            got, reused = self.full, True
        else:
            got = compute_for(obj, percent)
        stored = stored_as(obj, got, percent)
        self.full_key = key  # once all went well: it names stored.full
        return stored, reused


class FeatureError(RuntimeError):
    """A MedialAxis recompute failed (FreeCAD shows the object with its error mark)."""


def add_later_counts(obj):
    """Adds the read-only counts of LATER_COUNTS that obj lacks."""
    for kind, name, doc in LATER_COUNTS:
        if name not in obj.PropertiesList:
            obj.addProperty(kind, name, OUTPUTS, doc)
            obj.setEditorMode(name, READ_ONLY)


def parameters_of(obj):
    """What compute_for(obj) depends on besides the source's shape."""
    return (obj.Source.Name if obj.Source else None, float(obj.Spacing.Value), int(obj.Samples),
            float(obj.Theta), float(obj.Rho), bool(obj.Refine), min_feature_of(obj))


def min_feature_of(obj):
    """obj's MinFeature in model units (0: none; a document saved before it existed has none)."""
    return float(obj.MinFeature.Value) if "MinFeature" in obj.PropertiesList else 0.0


def source_digest(obj):
    """A digest of obj's source shape as the engine reads it (its BREP text, placement included):
    the same shape gives the same axis. None without a Source."""
    if obj.Source is None:
        return None
    shape = Part.getShape(obj.Source)
    return None if shape.isNull() else hashlib.sha1(shape.exportBrepToString().encode()).hexdigest()


def stored_as(obj, got, percent):
    """The StoredResult of got (a MedialAxisResult of the full axis, or a StoredResult) for
    Simplify = percent: got itself when it was made for it, else simplified (in the GUI in a
    thread, behind a progress dialog: seconds on parts of 50,000 polygons, docs/workbench.md)."""
    source = None
    if isinstance(got, StoredResult):
        if got.percent == percent:
            return got
        got.discard()
        got, source = got.full, got.source
    if not percent:
        return prepare_result(got, set_range(obj))
    color_range = set_range(obj)
    if source is None and obj.Source is not None:
        source = cadmedial.read_shape(Part.getShape(obj.Source))  # read here, in this thread

    def simplify(progress):
        if progress is not None:
            progress("simplifying within %g %% of the diagonal" % percent, 0.0)
        stored = prepare_result(got, color_range, percent, source, progress)
        if progress is not None and not progress("simplified", 1.0):
            stored.discard()
            raise cadmedial.Cancelled()
        return stored
    return registry.run_long("Compact mesh of %s" % obj.Label, simplify)


def compute_for(obj, percent=0.0):
    """Runs the engine on obj's Source with obj's parameters; raises on failure. In the GUI, a
    StoredResult simplified for percent."""
    if obj.Source is None:
        raise cadmedial.InvalidInput("no Source: link a solid")
    return compute_shape(Part.getShape(obj.Source), obj.Spacing.Value, obj.Samples, obj.Theta,
                         obj.Rho, obj.Label, bool(obj.Refine), min_feature_of(obj), set_range(obj),
                         percent)


def compute_shape(shape, spacing, samples, theta, rho, label, refine=None, min_feature=0.0,
                  color_range=None, simplify=0.0):
    """cadmedial.compute on a Part.Shape, with FreeCAD's progress bar (Esc cancels) in the GUI.
    color_range: (low, high) the GUI's worker colours the mesh for, None: its radii. simplify:
    the percent the GUI's worker simplifies for. Returns the full axis (a MedialAxisResult), or
    in the GUI's worker a StoredResult of it."""
    if shape.isNull():
        raise cadmedial.InvalidInput("the source has no shape (recompute it first?)")
    spacing = spacing if spacing > 0 else None
    samples = samples if (spacing is None and samples > 0) else None
    params = dict(spacing=spacing, samples=samples, theta=theta, rho=rho, refine=refine,
                  min_feature=min_feature if min_feature > 0 else None)
    if App.GuiUp and registry.background_runner is not None:
        # The GUI computes, and builds the mesh and colours, in a thread and keeps drawing,
        # with a progress dialog and Stop. Returns a StoredResult.
        core = cadmedial.read_shape(shape)  # the Part.Shape is read here, in this thread
        return registry.run_long("Medial axis of %s" % label, lambda progress: prepare_result(
            cadmedial.compute(core, progress=progress, **params), color_range, simplify, core, progress))
    if not App.GuiUp:
        return cadmedial.compute(shape, **params)
    with StatusBarProgress("Medial axis of %s" % label) as progress:
        return cadmedial.compute(shape, progress=progress, **params)


class StatusBarProgress:
    """FreeCAD's own progress indicator as a compute() callback: keeps the GUI drawn during a
    recompute, and Esc cancels (ProgressIndicator.next raises, which cancels the engine)."""

    def __init__(self, text):
        self.text = text
        self.indicator = App.Base.ProgressIndicator()
        self.last = 0.0

    def __enter__(self):
        self.indicator.start(self.text, 0)
        return self

    def __call__(self, stage, fraction):
        now = time.monotonic()
        if now - self.last > 0.05:  # the engine may report far more often than we can draw
            self.last = now
            self.indicator.next(True)
        return True

    def __exit__(self, *exc):
        self.indicator.stop()
        return False


def make_medial_axis(source, spacing=None, samples=None, theta=5.0, rho=8.0, shape=False,
                     result=None, name="MedialAxis", refine=None, min_feature=None,
                     simplify=DEFAULT_PERCENT):
    """Adds a MedialAxis feature for ``source`` (a document object with a solid shape) and
    computes it; with shape=True also a MedialShape (Part feature of planar faces).

    spacing/samples/theta/rho/refine/min_feature as in cadmedial.compute. simplify: the Simplify
    property, percent of the bounding-box diagonal (0.2 by default; 0 or None: the full axis).
    ``result``: the full axis (a MedialAxisResult) already computed with these parameters, or a
    StoredResult of it (the task panel computes in a thread first).
    Returns the new object. When the compute fails, the error goes to the report view and is
    raised, and the document is left as it was: no object is added.
    """
    doc = source.Document
    if "Touched" in source.State or "Invalid" in source.State:
        source.recompute()
    if refine is None:  # 0 means "not given" here, as in compute_shape
        refine = refines_by_default(spacing or None, samples or None)
    if result is None:
        try:
            result = compute_shape(Part.getShape(source), spacing or 0.0, samples or 0,
                                   theta, rho, source.Label, refine, min_feature or 0.0,
                                   simplify=float(simplify or 0.0))
        except Exception as error:
            App.Console.PrintError("Medial axis of %s: %s\n" % (source.Label, error))
            raise
    obj = doc.addObject("Mesh::FeaturePython", name)
    proxy = MedialAxis(obj)
    obj.Label = "%s medial axis" % source.Label
    obj.Source = source
    obj.Spacing = spacing or 0.0
    obj.Samples = 0 if spacing else int(samples or 0)
    obj.Theta = theta
    obj.Rho = rho
    obj.Refine = bool(refine)
    obj.MinFeature = min_feature or 0.0
    obj.Simplify = float(simplify or 0.0)
    proxy.pending = (parameters_of(obj), result)  # a MedialAxisResult or a StoredResult
    attach_view_provider(obj, MedialAxis.Type)
    doc.recompute([obj])  # unlike obj.recompute(), this also clears the object's Touched flag
    if shape:
        make_medial_shape(obj)
    return obj
