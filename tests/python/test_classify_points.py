"""_core.classify_points: OpenCASCADE's solid classifier over many points (used by bench/measures.py
for leakage and edge convexity): 1 inside, 2 on the boundary within tol, 0 outside."""

import numpy as np
import pytest

import cadmedial
from cadmedial import _core


@pytest.fixture
def box_solid(box_step):
    return _core.extract_solids(cadmedial.read_shape(box_step))[0]


def test_classify_points_the_box_outside_and_on_its_boundary(box_solid):
    # The box is [0, 10] x [0, 20] x [0, 30].
    points = np.array([[5, 10, 15], [0.001, 0.001, 0.001], [-0.001, 10, 15], [11, 10, 15],
                       [5, 10, 30], [10, 20, 30], [5, 10, 30 + 1e-9]], float)
    inside = _core.classify_points(box_solid, points, 1e-7)
    assert inside.dtype == np.uint8 and inside.shape == (7,)
    # On the boundary, or within tol of it: 2.
    assert inside.tolist() == [1, 1, 0, 0, 2, 2, 2]


def test_classify_points_agrees_with_the_box_on_random_points(box_solid):
    rng = np.random.default_rng(3)
    points = rng.uniform([-5, -5, -5], [15, 25, 35], size=(500, 3))
    expected = ((points >= 0) & (points <= [10, 20, 30])).all(axis=1).astype(np.uint8)
    assert (_core.classify_points(box_solid, points, 1e-9) == expected).all()


def test_classify_points_checks_its_arguments(box_solid, data):
    with pytest.raises(cadmedial.InvalidInput, match=r"points must have shape \(N, 3\), got \(4, 2\)"):
        _core.classify_points(box_solid, np.zeros((4, 2)), 1e-7)
    with pytest.raises(cadmedial.InvalidInput, match="tol"):
        _core.classify_points(box_solid, np.zeros((1, 3)), 0.0)
    with pytest.raises(cadmedial.InvalidInput, match="solid"):
        _core.classify_points(cadmedial.read_shape(data("square_face.brep")), np.zeros((1, 3)), 1e-7)
