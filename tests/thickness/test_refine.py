"""The exact refinement (thickness/refine.py): from the medial reading to the largest ball tangent
at each point, on the B-rep. Values are the true thickness to 0.5 %, and every refined ball lies
inside the solid."""

import math

import numpy as np
import pytest

from conftest import (Part, V, medial, rib_balls, rib_on_plate, slab_balls, tilted_slab, tube,
                      tube_balls)
from cadmedial import _core
from cadmedial.thickness import thickness

EXACT_RTOL = 0.005
CONE_SHIFT = 4.0  # the inner cone is the outer one moved down the axis by this


def cone_wall():
    """Two cones of the same half-angle (radius 10 to 2 over 16 high), the inner moved down the
    axis: a conical wall CONE_SHIFT * sin(half-angle) thick (1.789) along its normal."""
    outer = Part.makeCone(10, 2, 16)
    inner = Part.makeCone(10, 2, 16, V(0, 0, -CONE_SHIFT))
    return outer.cut(inner)


def cone_thickness():
    return CONE_SHIFT * math.sin(math.atan2(10 - 2, 16))


def torus_shell():
    """A torus of minor radius 3 less its core of minor radius 1: 2 thick everywhere."""
    return Part.makeTorus(10, 3).cut(Part.makeTorus(10, 1))


def refined_counted(t):
    pick = t.counted & t.refined
    assert pick.sum() > 0.95 * t.counted.sum()  # nearly every counted point is refined
    return pick


def test_tilted_slab_reads_exactly_2():
    t = thickness(tilted_slab(), refine_budget=math.inf)
    v = t.values[refined_counted(t)]
    assert len(v) > 0.4 * len(t.values)
    np.testing.assert_allclose(v, 2.0, rtol=EXACT_RTOL)


def test_tilted_slab_from_rough_balls_reads_exactly_2():
    # Balls 10 % too small start the shrinking below the answer: it grows first.
    balls = slab_balls()
    t = thickness(tilted_slab(), medial=medial(balls.vertices, 0.9 * balls.radius, 0.5),
                  refine_budget=math.inf)
    np.testing.assert_allclose(t.values[refined_counted(t)], 2.0, rtol=EXACT_RTOL)


def test_tube_wall_reads_exactly_2():
    t = thickness(tube(), medial=tube_balls(), refine_budget=math.inf)
    np.testing.assert_allclose(t.values[refined_counted(t)], 2.0, rtol=EXACT_RTOL)


def test_cone_wall_reads_its_normal_thickness():
    shape = cone_wall()
    t = thickness(shape, refine_budget=math.inf)
    pick = refined_counted(t)
    z = t.points[:, 2]
    # Below the inner cone's top (z = 12), where the wall is the two cones only.
    mid = pick & (z > 1.5) & (z < 9)
    assert mid.sum() > 1000
    np.testing.assert_allclose(t.values[mid], cone_thickness(), rtol=EXACT_RTOL)


def test_torus_shell_reads_exactly_2():
    t = thickness(torus_shell(), refine_budget=math.inf)
    assert t.counted.all()  # no convex edge
    np.testing.assert_allclose(t.values[refined_counted(t)], 2.0, rtol=EXACT_RTOL)


def _balls_inside(shape, t):
    """(distance of each refined ball's centre to the boundary / its radius, inside?) per
    refined point, the balls rebuilt from the exact foot and normal of each point."""
    solid = _core.read_brep_string(shape.Solids[0].exportBrepToString())
    pick = np.nonzero(t.refined)[0]
    p = t.points[pick]
    _, foot, face, normal = _core.boundary_distance(solid, p, np.full(len(p), np.inf))
    on_face = face >= 0  # points on a seam or tangent edge: normal from the mesh's side
    r = t.values[pick][on_face] / 2.0
    centre = foot[on_face] - r[:, None] * normal[on_face]
    d, _, _, _ = _core.boundary_distance(solid, centre, np.full(len(centre), np.inf))
    inside = _core.classify_points(solid, centre, 1e-7 * shape.BoundBox.DiagonalLength)
    return d / r, inside, on_face.sum()


@pytest.mark.parametrize("make", [rib_on_plate, cone_wall, torus_shell],
                         ids=["rib", "cone", "torus"])
def test_no_refined_ball_sticks_out_of_the_solid(make):
    shape = make()
    t = thickness(shape, medial=rib_balls() if make is rib_on_plate else None,
                  refine_budget=math.inf)
    ratio, inside, checked = _balls_inside(shape, t)
    assert checked > 0.9 * t.refined.sum()
    assert np.all(ratio >= 1.0 - 1e-5)  # the boundary is no closer to the centre than r
    assert np.all(inside == 1)          # and the centre is inside: the ball is


def test_zero_budget_keeps_the_medial_reading():
    shape = rib_on_plate()
    balls = rib_balls()
    medial_only = thickness(shape, medial=balls, refine_budget=0)
    assert not medial_only.refined.any()
    full = thickness(shape, medial=balls, refine_budget=math.inf)
    changed = np.abs(full.values - medial_only.values) > 1e-9
    assert not np.any(changed & ~full.refined)  # an unrefined point keeps its reading
    assert full.settings["refined"] == int(full.refined.sum())
