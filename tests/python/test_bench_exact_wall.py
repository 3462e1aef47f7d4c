"""bench/measures.exact_wall, the results page's check of the thin-wall warnings: twice the
radius of the largest ball in a solid that touches its boundary at a point, on solids whose
answer is known."""

import os
import sys

import pytest

sys.path.append("/usr/lib/freecad/lib")
FreeCAD = pytest.importorskip("FreeCAD")
Part = pytest.importorskip("Part")
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, os.pardir, "bench"))
import measures  # noqa: E402

TOL = 1e-7


def test_a_plate_is_as_thick_as_it_is_anywhere_on_its_faces():
    plate = Part.makeBox(30, 30, 1)
    for at in [(15, 15, 1), (15, 15, 0), (3, 25, 1)]:
        assert measures.exact_wall(plate, at, 1.0, TOL) == pytest.approx(1.0, rel=1e-5)


def test_a_cylinder_is_its_diameter_thick_on_its_side():
    cylinder = Part.makeCylinder(2, 10)
    assert measures.exact_wall(cylinder, (2, 0, 5), 3.0, TOL) == pytest.approx(4.0, rel=1e-5)


def test_no_ball_touches_a_convex_edge():
    assert measures.exact_wall(Part.makeBox(30, 30, 1), (0, 15, 1), 1.0, TOL) < 1e-5


def test_at_a_concave_edge_the_smaller_of_the_two_faces_balls():
    # An L of arms 2 and 3 thick: at its inner edge (3, 2) the ball along the thinner arm's face
    # normal has radius 1, along the other's 1.5.
    outline = [(0, 0, 0), (10, 0, 0), (10, 2, 0), (3, 2, 0), (3, 10, 0), (0, 10, 0), (0, 0, 0)]
    l_block = Part.Face(Part.makePolygon([FreeCAD.Vector(*p) for p in outline])).extrude(FreeCAD.Vector(0, 0, 5))
    assert measures.exact_wall(l_block, (3, 2, 2.5), 2.0, TOL) == pytest.approx(2.0, rel=1e-5)
    assert measures.exact_wall(l_block, (3, 6, 2.5), 3.0, TOL) == pytest.approx(3.0, rel=1e-5)


def test_a_point_off_the_boundary_has_no_answer():
    assert measures.exact_wall(Part.makeBox(30, 30, 1), (15, 15, 0.5), 1.0, TOL) is None
