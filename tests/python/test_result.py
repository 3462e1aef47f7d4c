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
