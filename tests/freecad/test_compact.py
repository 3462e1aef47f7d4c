"""The compact mesh of a MedialAxis object (its Simplify property, app/compact_mesh.py), headless
inside freecadcmd: the Mesh holds the simplified axis with the full axis's topology, a new
Simplify simplifies again without the engine, a saved document reopens in a fresh freecadcmd with
the same mesh and colours, documents saved before the property keep the full axis, and the compact
document is smaller and opens faster."""

import json
import os
import subprocess

import numpy as np
import pytest

FreeCAD = pytest.importorskip("FreeCAD", reason="FreeCAD's lib folder is not on sys.path")
import Part  # noqa: E402

import cadmedial  # noqa: E402
import cadmedial.app as medial_app  # noqa: E402
from cadmedial.app.compact_mesh import DEFAULT_PERCENT  # noqa: E402

SAMPLES = 3000
HERE = os.path.dirname(os.path.abspath(__file__))
Y_ROD = os.path.normpath(os.path.join(HERE, os.pardir, os.pardir, os.pardir, "shared", "data",
                                      "models", "freecad", "Y_Rod_Mount.brep"))


@pytest.fixture
def doc():
    yield FreeCAD.newDocument("CompactTest")
    for name in list(FreeCAD.listDocuments()):
        FreeCAD.closeDocument(name)


def add_box(doc):
    box = doc.addObject("Part::Box", "Box")
    box.Length, box.Width, box.Height = 10.0, 20.0, 30.0
    doc.recompute()
    return box


def euler_of(mesh):
    """V - E + F of a FreeCAD mesh, counted on its points and facets (an edge shared by several
    facets, as at the junctions of medial sheets, counts once)."""
    points, facets = mesh.Topology
    f = np.array(facets, dtype=np.int64).reshape(-1, 3)
    edges = np.sort(np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]]), axis=1)
    return len(points) - len(np.unique(edges, axis=0)) + len(f)


def figures(obj):
    return obj.Mesh.CountFacets, len(obj.RadiusColors)


def open_fresh(path, tmp_path, simplify=None):
    """The report of compact_reopen.py on path, run in a new freecadcmd process."""
    out = tmp_path / ("reopen-%s.json" % os.path.basename(path))
    env = dict(os.environ, CADMEDIAL_DOC=str(path), CADMEDIAL_OUT=str(out))
    if simplify is not None:
        env["CADMEDIAL_SIMPLIFY"] = repr(float(simplify))
    run = subprocess.run(["freecadcmd", os.path.join(HERE, "compact_reopen.py")], env=env,
                         capture_output=True, text=True, timeout=600)
    assert out.exists(), run.stdout[-3000:] + run.stderr[-3000:]
    report = json.loads(out.read_text())
    assert "exception" not in report, report["exception"]
    return report


def test_compact_mesh_is_the_simplified_axis_with_the_full_axis_topology(doc):
    feature = medial_app.make_medial_axis(add_box(doc), samples=SAMPLES, simplify=0.5)
    simple = medial_app.medial_result(feature).stats["simplify"]
    full = feature.Proxy.full
    assert feature.Status == "ok"
    assert feature.Mesh.CountFacets == simple["faces_after"] == feature.FaceCount
    assert 5 * feature.Mesh.CountFacets <= full.num_faces == simple["faces_before"]
    assert len(feature.RadiusColors) == feature.Mesh.CountPoints == feature.VertexCount
    assert feature.Simplified.startswith("{:,} faces from {:,}".format(
        simple["faces_after"], full.num_faces))
    # Every point is a vertex of the full axis, moved onto the exact axis by at most the snap's
    # largest move (FreeCAD keeps points as float32).
    snap = medial_app.medial_result(feature).stats["snap"]
    assert snap["snapped"] > 0
    points = np.array([tuple(p.Vector) for p in feature.Mesh.Points])
    gaps = np.sqrt(((points[:, None, :] - full.vertices[None, :, :]) ** 2).sum(axis=2)).min(axis=1)
    assert gaps.max() < snap["max_move"] + 1e-4
    # The same Euler characteristic as the full axis, both counted on the FreeCAD meshes.
    compact_euler = euler_of(feature.Mesh)
    assert full.num_edges == 0  # a box's axis has no 1-D edges: the meshes hold all of it
    assert compact_euler == simple["euler_before"] == simple["euler_after"]
    feature.Simplify = 0.0
    doc.recompute()
    assert feature.Mesh.CountFacets == len(full.triangles())
    assert euler_of(feature.Mesh) == compact_euler
    assert feature.Simplified == ""


def test_a_new_simplify_simplifies_again_without_the_engine(doc, monkeypatch, capfd):
    box = add_box(doc)
    feature = medial_app.make_medial_axis(box, samples=SAMPLES)
    full = feature.Proxy.full
    at_default = feature.Mesh.CountFacets

    def engine(*args, **kwargs):
        raise AssertionError("the medial axis was computed again")
    monkeypatch.setattr(cadmedial, "compute", engine)
    capfd.readouterr()
    feature.Simplify = 2.0
    doc.recompute()
    assert feature.Status == "ok" and feature.Proxy.full is full
    # Snapped onto the box's exact axis first, as compute(simplify=) does.
    assert feature.Mesh.CountFacets == cadmedial.simplify(full, "2%", source=box.Shape).num_faces < at_default
    out, err = capfd.readouterr()  # the report view: what it gave, and that the axis was kept
    assert "%s: compact: %s (the axis not computed again)" % (feature.Label, feature.Simplified) in out + err
    assert len(feature.RadiusColors) == feature.Mesh.CountPoints
    feature.Simplify = 0.0
    doc.recompute()
    assert feature.Mesh.CountFacets == len(full.triangles())
    monkeypatch.undo()
    box.Width = 25.0  # a new shape: the engine runs
    doc.recompute()
    assert feature.Proxy.full is not full
    assert feature.Mesh.BoundBox.YLength == pytest.approx(25.0, abs=2 * feature.SpacingUsed.Value)


def test_saved_compact_reopens_in_a_fresh_process_and_simplifies_again(doc, tmp_path):
    feature = medial_app.make_medial_axis(add_box(doc), samples=SAMPLES)  # the default Simplify
    assert DEFAULT_PERCENT > 0 and feature.Simplify == pytest.approx(DEFAULT_PERCENT)
    before = figures(feature)
    expected = cadmedial.simplify(feature.Proxy.full, "2%", source=feature.Source.Shape).num_faces  # what 2 % gives
    path = tmp_path / "compact.FCStd"
    doc.saveAs(str(path))
    report = open_fresh(path, tmp_path, simplify=2.0)  # more than the default: fewer faces
    opened, changed = report["opened"], report["changed"]
    assert (opened["facets"], opened["colors"]) == before
    assert opened["points"] == opened["vertex_count"] == opened["colors"]
    assert opened["simplify"] == pytest.approx(DEFAULT_PERCENT) and "Touched" not in opened["state"]
    assert opened["full_in_memory"] is False  # the document keeps the compact mesh alone
    # Not in memory, the full axis is computed again (the engine is deterministic): then 2 %.
    assert changed["status"] == "ok"
    assert changed["facets"] == expected < before[0]
    assert changed["colors"] == changed["points"]
    assert changed["simplified"].startswith("{:,} faces".format(expected))


def test_document_saved_before_simplify_reopens_as_the_full_axis(doc, tmp_path):
    feature = medial_app.make_medial_axis(add_box(doc), samples=SAMPLES, simplify=0)
    before = figures(feature)
    feature.removeProperty("Simplify")  # as saved by a version without the compact mesh
    feature.removeProperty("Simplified")
    path = str(tmp_path / "old.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    doc = FreeCAD.openDocument(path)
    feature = doc.getObject("MedialAxis")
    assert feature.Simplify == 0.0 and feature.Simplified == ""
    assert "Touched" not in feature.State
    assert figures(feature) == before
    feature.touch()
    doc.recompute()  # a recompute gives what that version gave: the full axis
    assert feature.Status == "ok" and figures(feature) == before


@pytest.mark.skipif(not os.path.isfile(Y_ROD), reason="../shared/data/models is not beside the repository")
def test_compact_document_is_ten_times_smaller_than_the_full_one(doc, tmp_path):
    # FreeCAD's Y-rod mount at the automatic density: 54,436 polygons, 140,212 triangles.
    part = doc.addObject("Part::Feature", "YRodMount")
    part.Shape = Part.read(Y_ROD)
    doc.recompute()
    feature = medial_app.make_medial_axis(part)
    compact = tmp_path / "compact.FCStd"
    doc.saveAs(str(compact))
    feature.Simplify = 0.0
    doc.recompute()  # the full axis from memory
    full = tmp_path / "full.FCStd"
    doc.saveAs(str(full))
    sizes = compact.stat().st_size, full.stat().st_size
    opened = [open_fresh(path, tmp_path) for path in (compact, full)]
    print("compact %d bytes, opened in %.3f s; full %d bytes, opened in %.3f s" % (
        sizes[0], opened[0]["open_seconds"], sizes[1], opened[1]["open_seconds"]))
    assert 10 * sizes[0] <= sizes[1]
    assert opened[0]["opened"]["facets"] * 10 <= opened[1]["opened"]["facets"]
