"""Midpoints on B-spline faces put on the face by the engine's exact distance (surface_mesh's
``exact``): every mesh point lies on the B-rep, as with OpenCASCADE's per-point projection."""

import numpy as np
import pytest

from conftest import Part
from cadmedial import _core
from cadmedial.thickness.surface_mesh import surface_mesh


def nurbs_tube():
    """A tube (radii 3 and 5, 20 long) whose faces are all B-spline surfaces."""
    return Part.makeCylinder(5, 20).cut(Part.makeCylinder(3, 20)).toNurbs()


def off_brep(core, points):
    d, _, _, _ = _core.boundary_distance(core, points, np.full(len(points), np.inf))
    return d


def test_bspline_midpoints_lie_on_the_faces():
    shape = nurbs_tube()
    solid = shape.Solids[0]
    assert {type(f.Surface).__name__ for f in solid.Faces} == {"BSplineSurface"}
    core = _core.read_brep_string(solid.exportBrepToString())
    max_edge, deflection = 0.6, 0.05
    fast = surface_mesh(shape, [solid], max_edge, deflection, exact=[core])
    slow = surface_mesh(shape, [solid], max_edge, deflection)
    # Not the same mesh to the point: the two projections agree to about 1e-9 (their solvers'
    # tolerance), and a side within that of max_edge, or a flip's angle test, then goes the
    # other way (34,965 points against 35,859 here). The same kind of mesh, on the B-rep:
    assert abs(len(fast.points) - len(slow.points)) <= 0.05 * len(slow.points)
    for mesh in (fast, slow):
        assert off_brep(core, mesh.points).max() < 1e-7
        p, t = mesh.points, mesh.triangles
        sides = np.linalg.norm(p[t] - p[np.roll(t, 1, axis=1)], axis=2)
        assert sides.max() <= max_edge
    assert fast.triangle_areas().sum() == pytest.approx(slow.triangle_areas().sum(), rel=1e-5)
    # The chords' midpoints would not be (they sag up to 7e-4 here).
    a, b = fast.points[fast.triangles[:, 0]], fast.points[fast.triangles[:, 1]]
    assert off_brep(core, 0.5 * (a + b)).max() > 1e-4
