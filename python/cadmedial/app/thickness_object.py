"""The WallThickness document object: a parametric Mesh::FeaturePython holding the surface of its
Source coloured by sphere wall thickness, with thin (below MinWall) and thick (above MaxWall)
regions highlighted and listed.

Saved inside .FCStd files, keep them: module ``cadmedial.app.thickness_object``, class
``WallThickness``, object type ``Mesh::FeaturePython``, the property names below.

What the document keeps (reopening needs no recompute): Mesh (the surface mesh, points in the
analysis's order), Values (thickness per point), ThicknessColors (per-vertex colours), Counted
(per point, 0 where the corner band is left out), the statistics and the Regions lines.
Imports no GUI code.
"""

import time

import FreeCAD as App
import Mesh
import Part

import numpy as np

from cadmedial.colormap import colors_of
from cadmedial.thickness import CORNER_POLICIES, check_settings, thickness

from .registry import attach_view_provider

INPUTS = "Wall thickness"
OUTPUTS = "Result"
READ_ONLY, HIDDEN = 1, 2
THIN_COLOUR = (0.85, 0.1, 0.1)
THICK_COLOUR = (0.9, 0.3, 0.9)
EXCLUDED_COLOUR = (0.6, 0.6, 0.6)


class WallThickness:
    """Proxy of the WallThickness feature. execute() analyses; a failure is reported in the report
    view and in Status, and the last good result stays."""

    Type = "WallThickness"

    def __init__(self, obj):
        obj.Proxy = self
        self.pending = None
        add = obj.addProperty
        add("App::PropertyLink", "Source", INPUTS, "The solid to analyse")
        add("App::PropertyLength", "MinWall", INPUTS, "Minimum wall: thinner areas are thin regions (0: none)")
        add("App::PropertyLength", "MaxWall", INPUTS, "Maximum wall: thicker areas are thick regions, e.g. sink marks (0: none)")
        add("App::PropertyEnumeration", "Corners", INPUTS,
            "exclude: leave the band next to convex edges out of statistics and regions; "
            "zero: count it, the thickness going to zero at the edge")
        obj.Corners = list(CORNER_POLICIES)
        add("App::PropertyInteger", "Samples", INPUTS, "Medial axis samples; 0: the default density")
        add("App::PropertyLength", "LegendMin", INPUTS, "Colour range low end; LegendMin = LegendMax: the values' range")
        add("App::PropertyLength", "LegendMax", INPUTS, "Colour range high end")
        for kind, name, doc in [
                ("App::PropertyFloatList", "Values", "Sphere thickness at each mesh point"),
                ("App::PropertyIntegerList", "Counted", "1 where the point counts, 0 in the corner band"),
                ("App::PropertyColorList", "ThicknessColors", "Per-vertex colours"),
                ("App::PropertyLength", "ThicknessMin", "Thinnest counted wall"),
                ("App::PropertyLength", "ThicknessMax", "Thickest counted wall"),
                ("App::PropertyLength", "ThicknessMean", "Area-weighted mean thickness"),
                ("App::PropertyFloat", "ShareBelowMin", "Share of the counted area below MinWall"),
                ("App::PropertyStringList", "Regions",
                 "Thin and thick regions: kind, extreme, place, faces, area"),
                ("App::PropertyStringList", "Histogram", "Area per thickness range"),
                ("App::PropertyFloat", "ComputeTime", "Seconds of the last analysis"),
                ("App::PropertyString", "Status", "'pass', 'fail', or why the last analysis failed")]:
            add(kind, name, OUTPUTS, doc)
            obj.setEditorMode(name, READ_ONLY)
        for name in ("Values", "Counted", "ThicknessColors"):
            obj.setEditorMode(name, HIDDEN)
        legend_is_output(obj)

    def __getstate__(self):
        return None

    def __setstate__(self, state):
        self.pending = None
        self.result = None

    dumps, loads = __getstate__, __setstate__

    def onDocumentRestored(self, obj):
        self.pending = None
        self.result = None
        legend_is_output(obj)

    def onChanged(self, obj, prop):
        if prop in ("LegendMin", "LegendMax") and _restored(obj):
            recolour(obj)

    def execute(self, obj):
        started = time.perf_counter()
        try:
            result = self._take_pending(obj) or analyse(obj)
        except Exception as error:  # report it, keep the last good result
            obj.Status = "failed: %s" % error
            App.Console.PrintError("%s: wall thickness not updated: %s\n" % (obj.Label, error))
            return
        self.result = result
        store_result(obj, result)
        obj.ComputeTime = result.timings.get("total", time.perf_counter() - started)

    def _take_pending(self, obj):
        pending, self.pending = getattr(self, "pending", None), None
        if pending is not None and pending[0] == parameters_of(obj):
            return pending[1]
        return None


def parameters_of(obj):
    """(shape, min, max, corners, samples) as analyse() passes them."""
    lo, hi = float(obj.MinWall.Value), float(obj.MaxWall.Value)
    return (obj.Source.Name if obj.Source else None, lo or None, hi or None, obj.Corners,
            int(obj.Samples) or None)


def analyse_shape(shape, minimum=None, maximum=None, corners="exclude", samples=None):
    """cadmedial.thickness on a Part shape (what a worker thread runs)."""
    return thickness(shape, min=minimum, max=maximum, corners=corners, samples=samples)


def analyse(obj):
    if obj.Source is None:
        raise ValueError("no Source")
    _, lo, hi, corners, samples = parameters_of(obj)
    return analyse_shape(Part.getShape(obj.Source), lo, hi, corners, samples)


def region_line(g):
    return "%s %.4g at (%.6g, %.6g, %.6g) on %s, area %.4g" % (
        g["kind"], g["extreme"], g["at"][0], g["at"][1], g["at"][2], " ".join(g["faces"]), g["area"])


def legend_is_output(obj):
    # A new legend range recolours from the stored values at once (onChanged): as output
    # properties the range and the colours do not mark the object for a recompute, which would
    # analyse the part again.
    for name in ("LegendMin", "LegendMax", "ThicknessColors"):
        if name in obj.PropertiesList:
            obj.setPropertyStatus(name, "Output")


def _restored(obj):
    # While a document loads, properties arrive one by one: colours are loaded, not made.
    return "Restore" not in obj.State and not getattr(obj.Document, "Restoring", False)


def legend_range(obj, low=None, high=None):
    """(low, high) of the colour map: LegendMin..LegendMax, or the counted values' range
    (ThicknessMin..ThicknessMax, or low/high given) when LegendMax is not above LegendMin."""
    lo, hi = float(obj.LegendMin.Value), float(obj.LegendMax.Value)
    if hi > lo:
        return lo, hi
    lo = float(obj.ThicknessMin.Value) if low is None else low
    hi = float(obj.ThicknessMax.Value) if high is None else high
    return (lo, hi) if hi > lo else (lo, lo + 1.0)


def thickness_colours(values, counted, low, high, minimum=None, maximum=None):
    """(N, 3) colours of (N,) values: viridis over low..high, the counted points below minimum
    red and above maximum magenta (the thin and thick regions: every such point is in one),
    the points left out (counted False) grey."""
    values = np.asarray(values, dtype=np.float64)
    counted = np.asarray(counted, dtype=bool)
    rgb = colors_of(values, low, high).astype(np.float64)
    rgb[~counted] = EXCLUDED_COLOUR
    if minimum:
        rgb[counted & (values < minimum)] = THIN_COLOUR
    if maximum:
        rgb[counted & (values > maximum)] = THICK_COLOUR
    return rgb


def colours_for(obj, result):
    """(N, 3) colours of a ThicknessResult with obj's legend range and walls."""
    st = result.statistics
    lo, hi = legend_range(obj, st["min"] or 0.0, st["max"] or 1.0)
    s = result.settings
    return thickness_colours(result.values, result.counted, lo, hi, s["min"], s["max"])


def recolour(obj):
    """Colours from the stored Values and Counted for the current legend range, no analysis."""
    if "Counted" not in obj.PropertiesList or not obj.Values or len(obj.Counted) != len(obj.Values):
        return  # still being built, or nothing analysed
    lo, hi = legend_range(obj)
    rgb = thickness_colours(obj.Values, obj.Counted, lo, hi, float(obj.MinWall.Value) or None,
                            float(obj.MaxWall.Value) or None)
    obj.ThicknessColors = [tuple(c) for c in rgb.tolist()]


def store_result(obj, result):
    """Puts a ThicknessResult into obj's Mesh, values, colours, statistics and regions."""
    mesh = Mesh.Mesh()
    points = [App.Vector(*p) for p in result.points.tolist()]
    mesh.addFacets((points, [tuple(t) for t in result.triangles.tolist()]), False)
    obj.Mesh = mesh
    obj.Values = result.values.tolist()
    obj.Counted = result.counted.astype(int).tolist()
    st = result.statistics
    obj.ThicknessMin = st["min"] or 0.0
    obj.ThicknessMax = st["max"] or 0.0
    obj.ThicknessMean = st["mean"] or 0.0
    obj.ShareBelowMin = st["share_below_min"] or 0.0
    obj.Regions = [region_line(g) for g in result.thin_regions + result.thick_regions]
    e, a = st["histogram"]["edges"], st["histogram"]["area"]
    obj.Histogram = ["%.4g to %.4g: %.4g" % (e[i], e[i + 1], a[i]) for i in range(len(a))]
    obj.ThicknessColors = [tuple(c) for c in colours_for(obj, result).tolist()]
    obj.Status = "pass" if result.passed else "fail"


def make_wall_thickness(source, min_wall=None, max_wall=None, corners="exclude", samples=None,
                        result=None, name="WallThickness"):
    """Adds a WallThickness feature for ``source`` (a document object holding a solid) and
    analyses it. ``result``: a ThicknessResult already computed with these settings (the GUI
    analyses in a thread first). Raises cadmedial.InvalidInput on bad settings or a source
    without a solid, and adds nothing to the document then."""
    check_settings(min_wall, max_wall, corners)
    shape = Part.getShape(source)
    if not shape.Solids and not any(s.isClosed() for s in shape.Shells):
        from cadmedial import InvalidInput
        raise InvalidInput("%s holds no closed solid: wall thickness is measured inside solids"
                           % source.Label)
    if result is None:
        result = analyse_shape(shape, min_wall, max_wall, corners, samples)
    doc = source.Document
    obj = doc.addObject("Mesh::FeaturePython", name)
    proxy = WallThickness(obj)
    obj.Label = "%s wall thickness" % source.Label
    obj.Source = source
    obj.MinWall = min_wall or 0.0
    obj.MaxWall = max_wall or 0.0
    obj.Corners = corners
    obj.Samples = int(samples or 0)
    proxy.pending = (parameters_of(obj), result)
    attach_view_provider(obj, WallThickness.Type)
    doc.recompute([obj])
    return obj


def is_wall_thickness(obj):
    return getattr(getattr(obj, "Proxy", None), "Type", None) == WallThickness.Type
