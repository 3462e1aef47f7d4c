"""thickness.probe at one point: the least-power candidates found by a linear scan are the
KD-tree's, and a probe told its face reads what the search over all faces reads."""

import math

import numpy as np
import pytest

from conftest import slab_balls, slab_normal, tilted_slab
from cadmedial.thickness import probe
from cadmedial.thickness.probe import least_power_balls
from cadmedial.thickness.sphere import sphere_thickness


def test_least_power_candidates_give_the_kd_trees_thickness():
    rng = np.random.default_rng(7)
    centres = rng.uniform(-10, 10, (5000, 3))
    radii = rng.uniform(0.1, 3.0, 5000)
    points = rng.uniform(-10, 10, (200, 3))
    whole, _, ball = sphere_thickness(points, centres, radii, reach=0.3)
    for p, value, b in zip(points, whole, ball):
        near = least_power_balls(p, centres, radii)
        assert len(near) == 24
        one, _, nb = sphere_thickness(p[None, :], centres[near], radii[near], reach=0.3)
        assert one[0] == value and near[nb[0]] == b


def test_a_probe_told_its_face_reads_the_same():
    shape = tilted_slab()
    medial = slab_balls()
    a = math.radians(30)
    rot = np.array([[math.cos(a), 0, math.sin(a)], [0, 1, 0], [-math.sin(a), 0, math.cos(a)]])
    on_top = rot @ np.array([20.0, 15.0, 1.0]) + slab_normal()
    searched = probe(shape, on_top, medial, reach=0.5)
    told = probe(shape, on_top, medial, face=searched["face"], reach=0.5)
    assert told == searched
    assert told["sphere"] == pytest.approx(2.0, rel=0.01)  # exact balls: the slab's 2
    assert told["ray"] == pytest.approx(2.0, rel=1e-6)
    assert 2 * told["ball_radius"] == pytest.approx(told["sphere"])
