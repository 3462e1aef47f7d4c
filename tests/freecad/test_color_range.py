"""The colour range of a MedialAxis object (app/color_range.py), headless inside freecadcmd:
radii outside a range set by hand get the end colours, the middle radius the middle colour, with
no engine run; the automatic range comes back; reopening and recomputing keep it; documents
saved before the properties get the automatic range."""

import numpy as np
import pytest

FreeCAD = pytest.importorskip("FreeCAD", reason="FreeCAD's lib folder is not on sys.path")

import cadmedial.app as medial_app  # noqa: E402
from cadmedial.colormap import STOPS  # noqa: E402

SAMPLES = 3000
# Colours are kept as 8-bit channels (FreeCAD's packed colours, also in saved files).
COLOUR_TOL = 0.5 / 255 + 1e-6
MIDDLE = STOPS[len(STOPS) // 2]  # 11 stops: the middle of the map is a stop


@pytest.fixture
def doc():
    yield FreeCAD.newDocument("ColorRangeTest")
    for name in list(FreeCAD.listDocuments()):
        FreeCAD.closeDocument(name)


@pytest.fixture
def feature(doc):
    # A 10 x 20 x 30 box: radii from 0 at its edges to 5 on the middle sheet.
    box = doc.addObject("Part::Box", "Box")
    box.Length, box.Width, box.Height = 10.0, 20.0, 30.0
    doc.recompute()
    return medial_app.make_medial_axis(box, samples=SAMPLES)


def colours(obj):
    return np.array(obj.RadiusColors)[:, :3]


def radii(obj):
    return np.asarray(medial_app.medial_result(obj).radius)


def set_range_around(obj, share=0.3, half_width=0.5):
    """Sets ColorRangeMin/Max to a vertex's radius (the one nearest share * RadiusMax) -/+
    half_width; returns (that vertex, low, high)."""
    r = radii(obj)
    middle = int(np.argmin(np.abs(r - share * obj.RadiusMax.Value)))
    low, high = r[middle] - half_width, r[middle] + half_width
    obj.ColorRangeMin = low
    obj.ColorRangeMax = high
    return middle, low, high


def assert_coloured_for(obj, middle, low, high):
    r, c = radii(obj), colours(obj)
    below, above = r < low - 1e-9, r > high + 1e-9
    assert below.sum() > 10 and above.sum() > 10  # both ends are really exercised
    np.testing.assert_allclose(c[below], np.broadcast_to(STOPS[0], c[below].shape), atol=COLOUR_TOL)
    np.testing.assert_allclose(c[above], np.broadcast_to(STOPS[-1], c[above].shape), atol=COLOUR_TOL)
    np.testing.assert_allclose(c[middle], MIDDLE, atol=COLOUR_TOL)


def test_new_object_spans_its_radii(feature):
    assert feature.AutoColorRange is True
    assert (feature.ColorRangeMin.Value, feature.ColorRangeMax.Value) == (
        feature.RadiusMin.Value, feature.RadiusMax.Value)
    r, c = radii(feature), colours(feature)
    np.testing.assert_allclose(c[np.argmin(r)], STOPS[0], atol=COLOUR_TOL)
    np.testing.assert_allclose(c[np.argmax(r)], STOPS[-1], atol=COLOUR_TOL)


def test_a_set_range_clamps_to_the_end_colours_without_a_recompute(feature):
    compute_time = feature.ComputeTime
    automatic = colours(feature)
    middle, low, high = set_range_around(feature)
    # The middle vertex, at 0.3 of the radii, is far from the middle colour in the automatic range.
    assert np.abs(automatic[middle] - MIDDLE).max() > 0.05
    assert feature.AutoColorRange is False  # a range typed in turns the automatic one off
    assert "Touched" not in feature.State  # the engine need not run again
    assert_coloured_for(feature, middle, low, high)
    feature.Document.recompute()
    assert feature.ComputeTime == compute_time
    assert_coloured_for(feature, middle, low, high)


def test_automatic_range_comes_back(feature):
    before = colours(feature)
    set_range_around(feature)
    feature.AutoColorRange = True
    assert (feature.ColorRangeMin.Value, feature.ColorRangeMax.Value) == (
        feature.RadiusMin.Value, feature.RadiusMax.Value)
    np.testing.assert_allclose(colours(feature), before, atol=COLOUR_TOL)


def test_an_empty_range_spans_the_radii(feature):
    before = colours(feature)
    feature.ColorRangeMin = 3.0
    feature.ColorRangeMax = 2.0
    assert feature.AutoColorRange is False
    np.testing.assert_allclose(colours(feature), before, atol=COLOUR_TOL)


def test_a_recompute_colours_the_new_radii_for_the_set_range(feature):
    feature.ColorRangeMin, feature.ColorRangeMax = 1.0, 2.0
    box = feature.Source
    box.Length = 14.0  # radii up to 7 now
    feature.Document.recompute()
    assert feature.Status == "ok" and feature.RadiusMax.Value > 6.0
    assert (feature.ColorRangeMin.Value, feature.ColorRangeMax.Value) == (1.0, 2.0)
    r = radii(feature)
    middle = int(np.argmin(np.abs(r - 1.5)))
    assert abs(r[middle] - 1.5) < 0.05
    c = colours(feature)
    np.testing.assert_allclose(c[r < 1.0], np.broadcast_to(STOPS[0], c[r < 1.0].shape), atol=COLOUR_TOL)
    np.testing.assert_allclose(c[r > 2.0], np.broadcast_to(STOPS[-1], c[r > 2.0].shape), atol=COLOUR_TOL)
    # Within 0.05 of 1.5 the colour is within 5 % of the map from the middle.
    assert np.abs(c[middle] - MIDDLE).max() < 0.05


def test_a_reopened_document_keeps_its_range_and_recolours_from_its_file(feature, doc, tmp_path):
    middle, low, high = set_range_around(feature)
    path = str(tmp_path / "range.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    feature = FreeCAD.openDocument(path).getObject("MedialAxis")
    assert feature.AutoColorRange is False
    assert (feature.ColorRangeMin.Value, feature.ColorRangeMax.Value) == pytest.approx((low, high))
    assert "Touched" not in feature.State
    assert_coloured_for(feature, middle, low, high)
    # A new range after reopening: the radii come from the saved PLY.
    feature.ColorRangeMax = high + 1.0
    top = colours(feature)[radii(feature) > high + 1.0]
    assert len(top) > 0  # some vertices above the new top (7 on the compact mesh of the default Simplify)
    np.testing.assert_allclose(top, np.broadcast_to(STOPS[-1], top.shape), atol=COLOUR_TOL)
    assert np.abs(colours(feature)[middle] - MIDDLE).max() > 0.05


def test_document_saved_before_the_range_gets_the_automatic_one(feature, doc, tmp_path):
    before = colours(feature)
    for name in ("AutoColorRange", "ColorRangeMin", "ColorRangeMax"):
        feature.removeProperty(name)  # as saved by a version without them
    path = str(tmp_path / "old.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    feature = FreeCAD.openDocument(path).getObject("MedialAxis")
    assert feature.AutoColorRange is True
    assert (feature.ColorRangeMin.Value, feature.ColorRangeMax.Value) == (
        feature.RadiusMin.Value, feature.RadiusMax.Value)
    assert "Touched" not in feature.State
    np.testing.assert_allclose(colours(feature), before, atol=COLOUR_TOL)
    middle, low, high = set_range_around(feature)
    assert_coloured_for(feature, middle, low, high)
