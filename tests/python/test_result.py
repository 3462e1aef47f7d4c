"""MedialAxisResult and Faces: views, triangulation, saving and loading."""

import gc

import numpy as np
import pytest

import cadmedial
from cadmedial import _core
from conftest import SAMPLES


@pytest.fixture(scope="module")
def box_result():
    import os
    from conftest import DATA
    return cadmedial.compute(os.path.join(DATA, "box_10x20x30.step"), samples=SAMPLES)


def test_triangulate_fans_each_polygon_from_its_first_vertex():
    mesh = _core.MedialMesh(np.zeros((7, 3)), np.zeros(7), [0, 4, 7, 12],
                            [0, 1, 2, 3, 4, 5, 6, 0, 2, 4, 6, 1], [0, 1, 0], [0, 0, 0])
    triangles, face = cadmedial.MedialAxisResult(mesh, {}).faces.triangulate()
    np.testing.assert_array_equal(triangles, [[0, 1, 2], [0, 2, 3], [4, 5, 6],
                                              [0, 2, 4], [0, 4, 6], [0, 6, 1]])
    np.testing.assert_array_equal(face, [0, 0, 1, 2, 2, 2])


def test_triangle_count_is_sum_of_sizes_minus_two(box_result):
    triangles = box_result.triangles()
    assert len(triangles) == int((box_result.faces.sizes() - 2).sum())
    assert triangles.max() < box_result.num_vertices


def test_faces_behave_as_a_sequence(box_result):
    faces = box_result.faces
    assert len(list(faces)) == len(faces)
    np.testing.assert_array_equal(faces[-1], list(faces)[-1])
    with pytest.raises(IndexError):
        faces[len(faces)]


def test_arrays_are_read_only_views(box_result):
    with pytest.raises(ValueError):
        box_result.vertices[0, 0] = 1.0
    with pytest.raises(ValueError):
        box_result.radius[0] = 1.0


def test_arrays_keep_the_mesh_alive(box_step):
    r = cadmedial.compute(box_step, samples=SAMPLES)
    vertices, expected = r.vertices, r.vertices.copy()
    del r
    gc.collect()
    np.testing.assert_array_equal(vertices, expected)


def test_ply_round_trip_keeps_everything(box_result, tmp_path):
    box_result.save(tmp_path / "m.ply")
    back = cadmedial.load(tmp_path / "m.ply")
    np.testing.assert_array_equal(back.vertices, box_result.vertices)
    np.testing.assert_array_equal(back.radius, box_result.radius)
    np.testing.assert_array_equal(back.faces.offsets, box_result.faces.offsets)
    np.testing.assert_array_equal(back.faces.indices, box_result.faces.indices)
    np.testing.assert_array_equal(back.face_kind, box_result.face_kind)
    np.testing.assert_array_equal(back.face_solid, box_result.face_solid)


def test_obj_has_one_v_line_per_vertex(box_result, tmp_path):
    box_result.save(tmp_path / "m.obj")
    lines = (tmp_path / "m.obj").read_text().splitlines()
    assert sum(1 for line in lines if line.startswith("v ")) == box_result.num_vertices
    assert sum(1 for line in lines if line.startswith("f ")) == box_result.num_faces


def test_ma_counts_vertices_and_triangles(box_result, tmp_path):
    box_result.save(tmp_path / "m.ma")
    lines = [line for line in (tmp_path / "m.ma").read_text().splitlines() if line.strip()]
    nv, ne, nf = (int(word) for word in lines[0].split()[:3])
    assert nv == box_result.num_vertices
    assert nf == len(box_result.triangles())
    assert sum(1 for line in lines if line.startswith("v ")) == nv


def test_brep_export_reads_back_as_a_compound(box_result):
    text = box_result.to_brep()
    assert "CASCADE Topology" in text[:100]
    assert cadmedial.read_shape(text).shape_type == "compound"


# ---- 1-D edges: segments of the axis that no face carries -----------------------------------

def mesh_with_edges():
    """A triangle, and a path of two edges hanging off it (vertex 0 -> 3 -> 4), of solid 2."""
    vertices = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [0, 0, 2.5]]
    return _core.MedialMesh(np.array(vertices, float), np.arange(5) / 7, [0, 3], [0, 1, 2], [0], [2],
                            edges=[[0, 3], [3, 4]], edge_solid=[2, 2])


def test_edges_are_int32_views_with_a_solid_each():
    r = cadmedial.MedialAxisResult(mesh_with_edges(), {})
    assert r.num_edges == 2
    assert r.edges.shape == (2, 2) and r.edges.dtype == np.int32
    assert r.edge_solid.shape == (2,) and r.edge_solid.dtype == np.int32
    np.testing.assert_array_equal(r.edges, [[0, 3], [3, 4]])
    np.testing.assert_array_equal(r.edge_solid, [2, 2])
    with pytest.raises(ValueError):
        r.edges[0, 0] = 1


def test_a_mesh_without_edges_has_empty_edge_arrays():
    mesh = _core.MedialMesh(np.zeros((3, 3)), np.zeros(3), [0, 3], [0, 1, 2], [0], [0])
    r = cadmedial.MedialAxisResult(mesh, {})
    assert r.num_edges == 0
    assert r.edges.shape == (0, 2) and r.edge_solid.shape == (0,)


@pytest.mark.parametrize("ext, keeps_solid", [("ply", True), ("obj", False), ("ma", False)])
def test_edges_round_trip_through_every_format(tmp_path, ext, keeps_solid):
    r = cadmedial.MedialAxisResult(mesh_with_edges(), {})
    r.save(tmp_path / ("m." + ext))
    back = cadmedial.load(tmp_path / ("m." + ext))
    np.testing.assert_array_equal(back.vertices, r.vertices)
    np.testing.assert_array_equal(back.edges, r.edges)
    # OBJ and .ma have no place for the solid: read back as 0, like the faces'.
    np.testing.assert_array_equal(back.edge_solid, r.edge_solid if keeps_solid else [0, 0])
    assert back.num_faces == 1


@pytest.fixture(scope="module")
def torus_result():
    from conftest import DATA
    import os
    return cadmedial.compute(os.path.join(DATA, "torus_10_3.brep"), samples=SAMPLES)


def test_torus_edge_count_agrees_with_the_stats(torus_result):
    r = torus_result
    # The torus's axis is its core circle: the 1-D edges there are what these tests are about.
    assert r.num_edges > 0
    assert r.stats["edges"] == r.num_edges == len(r.edges) == len(r.edge_solid)
    assert sum(s["edges"] for s in r.stats["solids"]) == r.num_edges
    assert "bare_edges" not in r.stats["solids"][0]
    assert r.edges.min() >= 0 and r.edges.max() < r.num_vertices
    np.testing.assert_array_equal(r.edge_solid, np.zeros(r.num_edges))


def test_torus_edges_lie_on_the_core_circle(torus_result):
    # Ends of the 1-D edges are medial vertices near the circle of radius 10 in z = 0, with a
    # radius near the tube's 3; within two spacings (radii are distances to samples).
    r = torus_result
    tol = 2 * r.stats["spacing"]
    ends = r.vertices[r.edges.ravel()]
    assert np.abs(np.hypot(ends[:, 0], ends[:, 1]) - 10).max() <= tol
    assert np.abs(ends[:, 2]).max() <= tol
    assert np.abs(r.radius[r.edges.ravel()] - 3).max() <= tol


@pytest.mark.parametrize("ext", ["ply", "obj", "ma"])
def test_torus_edges_round_trip(torus_result, tmp_path, ext):
    torus_result.save(tmp_path / ("m." + ext))
    back = cadmedial.load(tmp_path / ("m." + ext))
    np.testing.assert_array_equal(back.edges, torus_result.edges)
    assert back.num_edges == torus_result.stats["edges"]


def test_brep_export_holds_the_edges():
    r = cadmedial.MedialAxisResult(mesh_with_edges(), {})
    text = r.to_brep()
    # One BREP edge record per distinct edge: the triangle's three sides and the two free edges.
    assert text.count("\nEd\n") == 5
    assert cadmedial.read_shape(text).shape_type == "compound"
