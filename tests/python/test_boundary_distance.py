"""_core.boundary_distance: the engine's exact distance from points to a solid's B-rep (the
thickness refinement's), with the nearest point, its face and the face's outward normal."""

import numpy as np
import pytest

import cadmedial
from cadmedial import _core


@pytest.fixture
def box_solid(box_step):
    return _core.extract_solids(cadmedial.read_shape(box_step))[0]


def test_box_distances_feet_and_outward_normals(box_solid):
    # The box is [0, 10] x [0, 20] x [0, 30].
    points = np.array([[5, 10, 15], [1, 10, 15], [5, 10, 31], [12, 23, 15]], float)
    d, foot, face, normal = _core.boundary_distance(box_solid, points, np.full(4, np.inf))
    np.testing.assert_allclose(d, [5, 1, 1, np.hypot(2, 3)], atol=1e-12)
    np.testing.assert_allclose(foot[1], [0, 10, 15], atol=1e-12)
    np.testing.assert_allclose(normal[1], [-1, 0, 0], atol=1e-12)  # outward
    np.testing.assert_allclose(normal[2], [0, 0, 1], atol=1e-12)
    assert face[1] >= 0 and face[2] >= 0
    # The nearest point of the last is on the vertical edge x = 10, y = 20: no face, no normal.
    np.testing.assert_allclose(foot[3], [10, 20, 15], atol=1e-12)
    assert face[3] == -1 and not normal[3].any()


def test_random_points_inside_read_the_distance_to_the_nearest_side(box_solid):
    rng = np.random.default_rng(5)
    p = rng.uniform([0, 0, 0], [10, 20, 30], size=(400, 3))
    want = np.minimum(p, [10, 20, 30] - p).min(axis=1)
    d, foot, _, _ = _core.boundary_distance(box_solid, p, np.full(len(p), np.inf))
    np.testing.assert_allclose(d, want, atol=1e-9)
    np.testing.assert_allclose(np.linalg.norm(foot - p, axis=1), d, atol=1e-9)


def test_a_bound_below_the_distance_is_returned_with_no_face(box_solid):
    d, _, face, _ = _core.boundary_distance(box_solid, np.array([[5.0, 10, 15]]), np.array([2.0]))
    assert d[0] == pytest.approx(2.0) and face[0] == -1


def test_boundary_distance_checks_its_arguments(box_solid, data):
    with pytest.raises(cadmedial.InvalidInput, match=r"points must have shape \(N, 3\)"):
        _core.boundary_distance(box_solid, np.zeros((4, 2)), np.zeros(4))
    with pytest.raises(cadmedial.InvalidInput, match="bound"):
        _core.boundary_distance(box_solid, np.zeros((4, 3)), np.zeros(3))
    with pytest.raises(cadmedial.InvalidInput, match="solid"):
        _core.boundary_distance(cadmedial.read_shape(data("square_face.brep")), np.zeros((1, 3)),
                                np.zeros(1))
