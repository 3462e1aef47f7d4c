"""The closed-form projections onto cones and tori (both senses of a cone's semi-angle, tilted
axes) land where OpenCASCADE's own projection does, from points scattered around the faces."""

import numpy as np
import pytest

from conftest import V, Part
from cadmedial.thickness.surface_projection import CLOSED_FORMS, project_on_surface

SHAPES = {
    "narrowing_cone": lambda: Part.makeCone(5, 2, 10),
    "tilted_cone": lambda: Part.makeCone(1, 4, 6, V(1, 2, 3), V(1, 1, 0)),
    "torus": lambda: Part.makeTorus(10, 3),
    "tilted_torus": lambda: Part.makeTorus(6, 2, V(1, 0, 2), V(0, 1, 1)),
    "tilted_cylinder": lambda: Part.makeCylinder(3, 5, V(0, 0, 0), V(1, 2, 3)),
}


@pytest.mark.parametrize("name", list(SHAPES))
def test_closed_forms_equal_occ_projection(name):
    rng = np.random.default_rng(5)
    checked = set()
    for face in SHAPES[name]().Faces:
        surface = face.Surface
        kind = type(surface).__name__
        assert kind in CLOSED_FORMS
        pts, _ = face.tessellate(0.05)
        p = np.array([tuple(q) for q in pts]) + rng.normal(0.0, 0.05, (len(pts), 3))
        ours = project_on_surface(surface, p)
        occ = np.array([tuple(surface.value(*surface.parameter(V(*q)))) for q in p])
        assert np.abs(ours - occ).max() < 1e-9
        checked.add(kind)
    assert checked - {"Plane"}  # the curved face was checked
