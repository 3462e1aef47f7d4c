"""The MedialAxis and MedialShape document objects, headless (run inside freecadcmd)."""

import os

import numpy as np
import pytest

FreeCAD = pytest.importorskip("FreeCAD", reason="FreeCAD's lib folder is not on sys.path")
import Part  # noqa: E402

import cadmedial  # noqa: E402
import cadmedial.app as medial_app  # noqa: E402

SAMPLES = 3000


@pytest.fixture
def doc():
    yield FreeCAD.newDocument("MedialTest")
    for name in list(FreeCAD.listDocuments()):  # also the ones reopened by the test
        FreeCAD.closeDocument(name)


def add_box(doc, length=10.0, width=20.0, height=30.0):
    box = doc.addObject("Part::Box", "Box")
    box.Length, box.Width, box.Height = length, width, height
    doc.recompute()
    return box


def reopen(doc, tmp_path):
    path = str(tmp_path / "medial.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    return FreeCAD.openDocument(path)


def mesh_points(obj):
    return np.array([tuple(p.Vector) for p in obj.Mesh.Points])


def test_feature_holds_the_engine_result(doc):
    box = add_box(doc)
    feature = medial_app.make_medial_axis(box, samples=SAMPLES, simplify=0)  # the full axis
    expected = cadmedial.compute(box.Shape, samples=SAMPLES)
    assert feature.Status == "ok"
    assert feature.VertexCount == expected.num_vertices
    assert feature.FaceCount == expected.num_faces
    assert feature.SampleCount == expected.stats["samples"]
    assert feature.Mesh.CountPoints == expected.num_vertices
    # Every fan triangle is there, also at the non-manifold junctions of the medial surface.
    assert feature.Mesh.CountFacets == len(expected.triangles())
    assert len(feature.RadiusColors) == feature.Mesh.CountPoints
    # The mesh keeps the engine's vertex order (float32 in FreeCAD's mesh), as the per-vertex
    # colours need. (Another compute may order vertices differently: compare with this one.)
    own = medial_app.medial_result(feature)
    np.testing.assert_allclose(mesh_points(feature), own.vertices, atol=1e-4)
    assert feature.RadiusMax.Value == pytest.approx(expected.radius.max())
    assert feature.Timings and feature.ComputeTime > 0


def test_changing_the_box_recomputes_the_medial_axis(doc):
    box = add_box(doc)
    feature = medial_app.make_medial_axis(box, samples=SAMPLES)
    tol = 2 * feature.SpacingUsed.Value
    # A box's medial axis reaches all its edges: same bounding box; the largest radius is half
    # the smallest side.
    assert feature.Mesh.BoundBox.YLength == pytest.approx(20.0, abs=tol)
    assert feature.RadiusMax.Value == pytest.approx(5.0, abs=tol)
    box.Width = 40.0
    box.Length = 6.0
    doc.recompute()
    tol = 2 * feature.SpacingUsed.Value
    assert feature.Status == "ok"
    assert feature.Mesh.BoundBox.YLength == pytest.approx(40.0, abs=tol)
    assert feature.Mesh.BoundBox.XLength == pytest.approx(6.0, abs=tol)
    assert feature.RadiusMax.Value == pytest.approx(3.0, abs=tol)
    assert len(feature.RadiusColors) == feature.Mesh.CountPoints


def test_parameters_are_properties_that_recompute(doc):
    box = add_box(doc)
    feature = medial_app.make_medial_axis(box, samples=SAMPLES, simplify=0)
    feature.Spacing = 2.0
    doc.recompute()
    assert feature.Status == "ok"
    assert feature.SpacingUsed.Value == pytest.approx(2.0)
    assert feature.VertexCount == cadmedial.compute(box.Shape, spacing=2.0).num_vertices


def test_save_and_reopen_keeps_the_result_without_recomputing(doc, tmp_path):
    box = add_box(doc)
    feature = medial_app.make_medial_axis(box, samples=SAMPLES, shape=True)
    before = dict(points=mesh_points(feature), colors=list(feature.RadiusColors),
                  vertices=feature.VertexCount, faces=feature.Mesh.CountFacets,
                  shape_faces=len(doc.getObject("MedialShape").Shape.Faces))
    result = medial_app.medial_result(feature)

    doc = reopen(doc, tmp_path)
    feature = doc.getObject("MedialAxis")
    assert isinstance(feature.Proxy, medial_app.MedialAxis)
    assert feature.Proxy.result is None  # execute() did not run: it would have set it
    assert "Touched" not in feature.State
    assert feature.VertexCount == before["vertices"]
    assert feature.Mesh.CountFacets == before["faces"]
    np.testing.assert_array_equal(mesh_points(feature), before["points"])
    # Colours are saved as 8-bit RGBA.
    np.testing.assert_allclose(np.array(feature.RadiusColors), np.array(before["colors"]), atol=0.5 / 255)
    assert len(doc.getObject("MedialShape").Shape.Faces) == before["shape_faces"]
    reloaded = medial_app.medial_result(feature)  # from the PLY saved in the document
    np.testing.assert_array_equal(reloaded.vertices, result.vertices)
    np.testing.assert_array_equal(reloaded.faces.indices, result.faces.indices)

    # The link survives too: the reopened feature follows its source.
    doc.getObject("Box").Width = 50.0
    doc.recompute()
    assert feature.Mesh.BoundBox.YLength == pytest.approx(50.0, abs=2 * feature.SpacingUsed.Value)


def test_export_writes_every_format_after_reopening(doc, tmp_path):
    feature = medial_app.make_medial_axis(add_box(doc), samples=SAMPLES)
    count = feature.VertexCount
    doc = reopen(doc, tmp_path)
    feature = doc.getObject("MedialAxis")
    for ext in ("ply", "obj", "ma"):
        medial_app.export_medial_axis(feature, str(tmp_path / ("out." + ext)))
    assert cadmedial.load(tmp_path / "out.ply").num_vertices == count
    assert cadmedial.load(tmp_path / "out.obj").num_vertices == count


def test_part_shape_has_one_planar_face_per_polygon(doc):
    feature = medial_app.make_medial_axis(add_box(doc), samples=SAMPLES, shape=True)
    shape = doc.getObject("MedialShape").Shape
    faces = feature.FaceCount
    assert shape.ShapeType == "Compound"
    assert 0.9 * faces <= len(shape.Faces) <= faces  # degenerate polygons are skipped
    assert all(f.Surface.TypeId == "Part::GeomPlane" for f in shape.Faces)
    for a, b in ((shape.BoundBox.XMin, feature.Mesh.BoundBox.XMin),
                 (shape.BoundBox.YMax, feature.Mesh.BoundBox.YMax)):
        assert a == pytest.approx(b, abs=1e-4)


def test_torus_edges_are_counted_and_in_the_part_shape(doc):
    torus = doc.addObject("Part::Torus", "Torus")
    torus.Radius1, torus.Radius2 = 10.0, 3.0
    doc.recompute()
    feature = medial_app.make_medial_axis(torus, samples=SAMPLES, shape=True)
    result = medial_app.medial_result(feature)
    # The torus's axis is its core circle: there the engine's mesh has 1-D edges.
    assert result.num_edges > 0
    assert feature.EdgeCount == result.num_edges == result.stats["edges"]
    assert feature.getEditorMode("EdgeCount") == ["ReadOnly"]
    # The mesh cannot show them; the Part shape holds each as a free edge of its compound.
    shape = doc.getObject("MedialShape").Shape
    free = [child for child in shape.childShapes() if child.ShapeType == "Edge"]
    assert len(free) == result.num_edges
    ends = result.vertices[result.edges]
    assert sum(e.Length for e in free) == pytest.approx(
        float(np.linalg.norm(ends[:, 1] - ends[:, 0], axis=1).sum()), rel=1e-9)


def test_document_saved_before_edge_count_gets_it_on_reopening(doc, tmp_path):
    feature = medial_app.make_medial_axis(add_box(doc), samples=SAMPLES)
    feature.removeProperty("EdgeCount")  # as saved by a version without the property
    doc = reopen(doc, tmp_path)
    feature = doc.getObject("MedialAxis")
    assert feature.EdgeCount == 0  # such results had no edges
    assert feature.getEditorMode("EdgeCount") == ["ReadOnly"]
    assert "Touched" not in feature.State
    assert feature.Status == "ok"


def test_document_saved_before_refine_gets_it_off_on_reopening(doc, tmp_path):
    feature = medial_app.make_medial_axis(add_box(doc))
    assert feature.Refine  # no density given: refined where the topology is wrong
    feature.removeProperty("Refine")  # as saved by a version without the property
    feature.removeProperty("Refinements")
    doc = reopen(doc, tmp_path)
    feature = doc.getObject("MedialAxis")
    assert feature.Refine is False  # a recompute gives what that version gave
    assert feature.Refinements == 0
    assert "Touched" not in feature.State


def test_min_feature_is_a_property_that_limits_the_refinement_and_is_named(doc, capfd):
    # The 10-thick box at spacing 6: its walls are sampled finer, unless MinFeature is 12, which
    # keeps one spacing and says so in the report view. A document saved before the property
    # gets none (0) on reopening.
    box = add_box(doc)
    feature = medial_app.make_medial_axis(box, spacing=6.0)
    fine = feature.SampleCount
    capfd.readouterr()
    feature.MinFeature = 12.0
    doc.recompute()
    out, err = capfd.readouterr()
    assert feature.Status == "ok"
    assert feature.SampleCount < fine / 2
    assert "thinner than the minimum feature size given (12)" in out + err
    assert feature.SampleCount == medial_app.medial_result(feature).stats["samples"]


def test_document_saved_before_min_feature_gets_none_on_reopening(doc, tmp_path):
    feature = medial_app.make_medial_axis(add_box(doc), samples=SAMPLES)
    feature.removeProperty("MinFeature")
    doc = reopen(doc, tmp_path)
    feature = doc.getObject("MedialAxis")
    assert feature.MinFeature.Value == 0.0
    assert "Touched" not in feature.State


def test_refine_samples_thin_ribs_finer_until_the_axis_is_right(doc, capfd):
    # Six ribs 0.15 thick and 15 tall on a block: at 3000 samples their sheets come apart (the
    # axis in 2 pieces) even after the thin-wall refinement; the report view says so. With Refine
    # the feature samples the part again, finer, and its axis has the part's topology.
    shape = Part.makeBox(50, 50, 5)
    for k in range(6):
        shape = shape.fuse(Part.makeBox(0.15, 50, 15, FreeCAD.Vector(4 + 8 * k, 0, 5)))
    ribs = doc.addObject("Part::Feature", "Ribs")
    ribs.Shape = shape.removeSplitter()
    doc.recompute()
    capfd.readouterr()
    feature = medial_app.make_medial_axis(ribs, samples=SAMPLES)
    out, err = capfd.readouterr()
    assert feature.Refine is False  # a density was given
    assert feature.Refinements == 0
    # The topology warning (the label "Ribs medial axis" is in every line: look for its words).
    assert "Euler characteristic is" in out + err or "parts of the medial axis are missing" in out + err
    coarse = feature.SpacingUsed.Value
    feature.Refine = True
    doc.recompute()
    out, err = capfd.readouterr()
    assert feature.Status == "ok"
    assert feature.Refinements >= 1
    assert feature.SpacingUsed.Value < coarse
    assert "Euler characteristic is" not in out + err and "are missing" not in out + err
    solid = medial_app.medial_result(feature).stats["solids"][0]
    assert solid["euler_characteristic"] == solid["solid_euler_characteristic"] == 1
    assert solid["components"] == 1


def test_non_solid_source_raises_reports_and_adds_nothing(doc, capfd):
    plane = doc.addObject("Part::Plane", "Plane")
    doc.recompute()
    names = [o.Name for o in doc.Objects]
    with pytest.raises(cadmedial.InvalidInput):
        medial_app.make_medial_axis(plane)
    assert [o.Name for o in doc.Objects] == names
    out, err = capfd.readouterr()
    assert "Medial axis of Plane" in out + err


def test_failed_recompute_reports_and_keeps_the_last_result(doc, capfd):
    feature = medial_app.make_medial_axis(add_box(doc), samples=SAMPLES)
    points, colors = feature.Mesh.CountPoints, len(feature.RadiusColors)
    capfd.readouterr()
    feature.Theta = 95.0  # outside (0, 90)
    doc.recompute()
    assert feature.Status.startswith("failed") and "theta" in feature.Status
    assert (feature.Mesh.CountPoints, len(feature.RadiusColors)) == (points, colors)
    out, err = capfd.readouterr()
    assert "medial axis not updated" in out + err
    feature.Theta = 5.0
    doc.recompute()
    assert feature.Status == "ok"


def test_source_becoming_a_face_keeps_the_last_result(doc):
    feature = medial_app.make_medial_axis(add_box(doc), samples=SAMPLES)
    points = feature.Mesh.CountPoints
    plane = doc.addObject("Part::Plane", "Plane")
    doc.recompute()
    feature.Source = plane
    doc.recompute()
    assert feature.Status.startswith("failed")
    assert feature.Mesh.CountPoints == points


def test_compound_of_two_solids_gives_one_feature_with_both(doc, data):
    part = doc.addObject("Part::Feature", "TwoCubes")
    part.Shape = Part.read(data("two_cubes.brep"))
    feature = medial_app.make_medial_axis(part, samples=SAMPLES)
    result = medial_app.medial_result(feature)
    assert set(np.unique(result.face_solid)) == {0, 1}
    assert feature.Mesh.BoundBox.XLength == pytest.approx(30.0, abs=2 * feature.SpacingUsed.Value)


def test_given_result_is_used_as_is(doc):
    box = add_box(doc)
    result = cadmedial.compute(box.Shape, samples=SAMPLES)
    feature = medial_app.make_medial_axis(box, samples=SAMPLES, result=result, simplify=0)
    assert feature.Proxy.result is result
    assert feature.ComputeTime == pytest.approx(result.stats["timings"]["total"])


def test_freecadcmd_example_writes_a_document(tmp_path, data):
    import subprocess
    from conftest import REPO
    out = tmp_path / "box.FCStd"
    env = dict(os.environ, CADMEDIAL_INPUT=data("box_10x20x30.step"), CADMEDIAL_OUTPUT=str(out),
               CADMEDIAL_SAMPLES=str(SAMPLES))
    run = subprocess.run(["freecadcmd", os.path.join(REPO, "examples", "medial_axis_freecadcmd.py")],
                         env=env, capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stdout + run.stderr
    assert "vertices" in run.stdout
    doc = FreeCAD.openDocument(str(out))
    try:
        feature = doc.getObject("MedialAxis")
        assert feature.Status == "ok" and feature.Mesh.CountPoints == feature.VertexCount > 0
    finally:
        FreeCAD.closeDocument(doc.Name)


BAD_DATA = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, "data", "bad"))


@pytest.mark.parametrize("name, fragment", [
    ("open_shell.brep", "the shell is open"),
    ("nonmanifold_edge.brep", "non-manifold"),
    ("zero_volume.brep", "zero volume"),
    ("fuzz/segv_plane_zero_normal.brep", "face 3 has (no|a degenerate) surface"),
])
def test_bad_shape_is_refused_and_adds_nothing(doc, name, fragment):
    # The bad-input corpus (tests/data/bad/README.md) as a Part::Feature source: refused with the
    # engine's message, no document object left behind, FreeCAD still alive.
    part = doc.addObject("Part::Feature", "Bad")
    part.Shape = Part.read(os.path.join(BAD_DATA, name))
    doc.recompute()
    names = [o.Name for o in doc.Objects]
    with pytest.raises(cadmedial.InvalidInput, match=fragment):
        medial_app.make_medial_axis(part, samples=SAMPLES)
    assert [o.Name for o in doc.Objects] == names


def test_walls_thinner_than_two_spacings_are_reported_as_a_warning(doc, capfd):
    # The box is 0.8 thick (medial radius 0.4): the sampling adapts to thin walls down to a
    # quarter of the spacing, 0.5 at a spacing of 2 (too coarse: the warning says so), 0.25 at 1.
    box = add_box(doc, length=0.8)
    capfd.readouterr()
    coarse = medial_app.make_medial_axis(box, spacing=2.0)
    out, err = capfd.readouterr()
    assert coarse.Status == "ok"
    assert "thinner than two sample spacings" in out + err
    coarse.Spacing = 1.0
    doc.recompute()
    out, err = capfd.readouterr()
    assert coarse.Status == "ok"
    assert "thinner than two sample spacings" not in out + err


def test_a_loose_face_beside_the_solid_is_skipped_with_a_warning(doc, capfd):
    # A compound of a box and a construction face above it (as NIST CTC 02 and 04 have): the
    # axis is the box's alone, and the report view says what was left out.
    box = Part.makeBox(10, 20, 30)
    face = Part.makePlane(5, 5, FreeCAD.Vector(0, 0, 40))
    part = doc.addObject("Part::Feature", "WithFace")
    part.Shape = Part.makeCompound([box, face])
    doc.recompute()
    capfd.readouterr()
    feature = medial_app.make_medial_axis(part, samples=SAMPLES)
    out, err = capfd.readouterr()
    assert feature.Status == "ok"
    assert feature.Label + ": skipped 1 loose face" in out + err
    points = mesh_points(feature)
    assert len(points) > 0
    assert points[:, 2].max() <= 30.0 + 1e-9


@pytest.mark.parametrize("name, fragment, solids", [
    ("reversed_face.brep", "healed by ShapeFix", 1),
    ("assembly_with_empty_solid.brep", "solid 3: has no shell (an empty solid); skipped", 3),
])
def test_healed_or_skipped_solid_is_reported_as_a_warning(doc, capfd, name, fragment, solids):
    # What the engine heals or skips (tests/data/bad/README.md) reaches the report view, and the
    # axis is computed from what is left.
    part = doc.addObject("Part::Feature", "Healable")
    part.Shape = Part.read(os.path.join(BAD_DATA, name))
    doc.recompute()
    capfd.readouterr()
    feature = medial_app.make_medial_axis(part, samples=SAMPLES)
    out, err = capfd.readouterr()
    assert feature.Status == "ok"
    assert fragment in out + err
    assert len(medial_app.medial_result(feature).stats["solids"]) == solids


MODELS = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, os.pardir, os.pardir,
                                      "shared", "data", "models"))


def test_engine_block_example_whose_spline_edge_defeats_arc_length_search_computes(doc):
    # FreeCAD's own example document (../shared/data/models/freecad, CC-BY-SA, read in place).
    # Its "Common" solid is bounded by a periodic B-spline on which OpenCASCADE's arc-length
    # search (GCPnts_AbscissaPoint) throws "no result": the edge sampling refused the whole part.
    path = os.path.join(MODELS, "freecad", "EngineBlock.FCStd")
    if not os.path.isfile(path):
        pytest.skip("../shared/data/models is not beside the repository")
    head = FreeCAD.openDocument(path).getObject("Common")
    feature = medial_app.make_medial_axis(head, samples=SAMPLES)
    assert feature.Status == "ok"
    result = medial_app.medial_result(feature)
    # Facts of the medial axis at 60 of its vertices: inside the solid, and the radius is the
    # distance to the boundary (never less; at most a spacing more, the sampling's gaps).
    solid = head.Shape.Solids[0]
    boundary = Part.Compound(solid.Faces)
    h = feature.SpacingUsed.Value
    picks = np.random.default_rng(7).choice(result.num_vertices, 60, replace=False)
    for i in picks:
        p = FreeCAD.Vector(*map(float, result.vertices[i]))
        assert solid.isInside(p, 1e-6 * solid.BoundBox.DiagonalLength, True), i
        d = boundary.distToShape(Part.Vertex(p))[0]
        assert d <= result.radius[i] + 1e-6 and result.radius[i] <= d + h, (i, d, result.radius[i])


def test_failed_recompute_puts_the_error_mark_on_the_object(doc):
    feature = medial_app.make_medial_axis(add_box(doc), samples=SAMPLES)
    assert "Invalid" not in feature.State
    feature.Theta = 95.0
    doc.recompute()
    assert "Invalid" in feature.State  # FreeCAD's error mark in the tree
    feature.Theta = 5.0
    doc.recompute()
    assert "Invalid" not in feature.State and feature.Status == "ok"


def test_thinnest_wall_is_a_property_with_its_place(doc):
    plate = doc.addObject("Part::Box", "Plate")
    plate.Length, plate.Width, plate.Height = 40.0, 40.0, 1.0
    doc.recompute()
    feature = medial_app.make_medial_axis(plate, samples=2000)
    assert feature.ThinnestWall.Value == pytest.approx(1.0, rel=0.05)
    at = feature.ThinnestWallAt
    assert at.z == pytest.approx(0.0, abs=1e-6) or at.z == pytest.approx(1.0, abs=1e-6)
    assert 0.0 <= at.x <= 40.0 and 0.0 <= at.y <= 40.0


def test_no_density_given_is_stored_as_automatic(doc):
    feature = medial_app.make_medial_axis(add_box(doc))
    assert (feature.Spacing.Value, feature.Samples) == (0.0, 0)
    assert feature.Status == "ok" and feature.SampleCount > 0


def test_runs_from_the_package_it_should(doc):
    # tools/check_deb.sh runs these tests from the unpacked .deb and names where cadmedial must be.
    expected = os.environ.get("CADMEDIAL_EXPECT_PACKAGE")
    if not expected:
        pytest.skip("CADMEDIAL_EXPECT_PACKAGE not set (only tools/check_deb.sh sets it)")
    assert os.path.dirname(os.path.abspath(cadmedial.__file__)) == os.path.abspath(expected)
    assert os.path.dirname(os.path.abspath(cadmedial._core.__file__)) == os.path.abspath(expected)
