"""Every bad input becomes a Python exception of the documented class with the engine's message."""

import numpy as np
import pytest

import cadmedial
from cadmedial import _core


def test_exception_classes_fit_python_conventions():
    assert issubclass(cadmedial.InvalidInput, ValueError)
    assert issubclass(cadmedial.InvalidInput, cadmedial.Error)
    assert issubclass(cadmedial.GeometryError, RuntimeError)
    assert issubclass(cadmedial.GeometryError, cadmedial.Error)
    assert issubclass(cadmedial.Cancelled, cadmedial.Error)
    assert cadmedial.InvalidInput.__module__ == "cadmedial"


def test_missing_file_names_the_file(tmp_path):
    missing = str(tmp_path / "nowhere.step")
    with pytest.raises(cadmedial.InvalidInput, match="nowhere.step"):
        cadmedial.compute(missing)


def test_unknown_extension_is_invalid_input(tmp_path):
    path = tmp_path / "shape.txt"
    path.write_text("not a shape")
    with pytest.raises(cadmedial.InvalidInput):
        cadmedial.compute(str(path))


def test_broken_brep_text_is_invalid_input(box_brep_text):
    with pytest.raises(cadmedial.InvalidInput):
        cadmedial.compute(box_brep_text[: len(box_brep_text) // 2])


def test_a_face_is_not_a_solid(data):
    with pytest.raises(cadmedial.InvalidInput) as raised:
        cadmedial.compute(data("square_face.brep"))
    assert str(raised.value)  # the engine says what is wrong, not an empty message


@pytest.mark.parametrize("params, field", [
    ({"theta": 95.0}, "theta"),
    ({"theta": 0.0}, "theta"),
    ({"rho": -1.0}, "rho"),
    ({"spacing": -2.0}, "spacing"),
    ({"samples": -5}, "samples"),
    ({"samples": 2.5}, "samples"),
])
def test_bad_parameters_are_named(box_step, params, field):
    with pytest.raises(cadmedial.InvalidInput, match=field):
        cadmedial.compute(box_step, **params)


def test_spacing_and_samples_together_are_refused(box_step):
    with pytest.raises(cadmedial.InvalidInput):
        cadmedial.compute(box_step, spacing=1.0, samples=1000)


def test_wrong_source_type_is_a_type_error():
    with pytest.raises(TypeError, match="source"):
        cadmedial.compute(12345)


def test_progress_must_be_callable(box_step):
    with pytest.raises(TypeError, match="progress"):
        cadmedial.compute(box_step, progress="yes")


def test_saving_to_an_unknown_format_is_invalid_input(box_step, tmp_path):
    r = cadmedial.compute(box_step, samples=1000)
    with pytest.raises(cadmedial.InvalidInput):
        r.save(tmp_path / "out.xyz")
    with pytest.raises(cadmedial.InvalidInput):
        r.save(tmp_path / "no" / "such" / "folder" / "out.ply")


def test_loading_garbage_is_invalid_input(tmp_path):
    path = tmp_path / "bad.ply"
    path.write_bytes(b"ply\nformat nonsense\n")
    with pytest.raises(cadmedial.InvalidInput):
        cadmedial.load(path)


def good_arrays():
    return dict(vertices=np.zeros((4, 3)), radius=np.ones(4), face_start=[0, 3, 6],
                face_vertices=[0, 1, 2, 0, 2, 3], kind=[0, 1], solid=[0, 0])


@pytest.mark.parametrize("change, message", [
    ({"vertices": np.zeros((4, 2))}, r"vertices must have shape \(N, 3\), got \(4, 2\)"),
    ({"radius": np.ones(3)}, r"radius must have shape \(4,\)"),
    ({"face_start": [1, 3, 6]}, r"face_start\[0\] must be 0"),
    ({"face_start": [0, 3, 5]}, r"face_start\[-1\] must equal len\(face_vertices\)"),
    ({"face_vertices": [0, 1, 2, 0, 2, 9]}, r"face 1 refers to vertex 9"),
    ({"face_start": [0, 2, 6]}, r"face 0 has 2 vertices"),
    ({"kind": [0, 7]}, r"kind\[1\] must be 0 \(voronoi\), 1 \(edge\) or 2 \(corner\), got 7"),
    ({"solid": [0]}, r"solid must have shape \(2,\)"),
    ({"edges": [[0, 1]]}, r"edges and edge_solid must be given together"),
    ({"edges": [[0, 1, 2]], "edge_solid": [0]}, r"edges must have shape \(E, 2\), got \(1, 3\)"),
    ({"edges": [[0, 1]], "edge_solid": [0, 0]}, r"edge_solid must have shape \(1,\) \(one per edge\)"),
    ({"edges": [[0, 1], [2, 9]], "edge_solid": [0, 0]}, r"edge 1 refers to vertex 9"),
])
def test_mesh_from_arrays_checks_shapes_at_the_boundary(change, message):
    arrays = good_arrays()
    arrays.update(change)
    with pytest.raises(cadmedial.InvalidInput, match=message):
        _core.MedialMesh(**arrays)


def test_mesh_from_good_arrays_round_trips():
    mesh = _core.MedialMesh(**good_arrays())
    assert (mesh.num_vertices, mesh.num_faces) == (4, 2)
    np.testing.assert_array_equal(mesh.face_vertices, [0, 1, 2, 0, 2, 3])
    np.testing.assert_array_equal(mesh.kind, [0, 1])
