"""Solids with known wall thickness, and exact medial balls for some of them, for the thickness
tests. Run with /usr/bin/python3 (FreeCAD's); ctest sets PYTHONPATH and CADMEDIAL_CORE_DIR."""

import math
import sys

import numpy as np
import pytest

sys.path.append("/usr/lib/freecad/lib")
FreeCAD = pytest.importorskip("FreeCAD", reason="FreeCAD's Part module is needed for thickness")
import Part  # noqa: E402

import cadmedial  # noqa: E402
from cadmedial import _core  # noqa: E402

V = FreeCAD.Vector
TILT_DEGREES = 30.0


def tilted_slab():
    """A 40 x 30 x 2 plate turned 30 degrees about y: 2 thick along its normal."""
    s = Part.makeBox(40, 30, 2)
    s.rotate(V(0, 0, 0), V(0, 1, 0), TILT_DEGREES)
    return s


def slab_normal():
    a = math.radians(TILT_DEGREES)
    return np.array([math.sin(a), 0.0, math.cos(a)])  # the plate's +z after the turn


def tube():
    """Inner radius 3, outer 5, 20 long: a wall 2 thick."""
    return Part.makeCylinder(5, 20).cut(Part.makeCylinder(3, 20))


def spherical_shell():
    """Inner radius 4, outer 6: a wall 2 thick."""
    return Part.makeSphere(6).cut(Part.makeSphere(4))


RIB = {"plate": 4.0, "width": 1.0, "height": 10.0, "x": 19.5}


def rib_on_plate():
    """A 40 x 40 x 4 plate with a rib 1 wide and 10 tall along y at x in [19.5, 20.5]."""
    plate = Part.makeBox(40, 40, RIB["plate"])
    rib = Part.makeBox(RIB["width"], 40, RIB["height"], V(RIB["x"], 0, RIB["plate"]))
    return plate.fuse(rib).removeSplitter()


def medial(vertices, radius, spacing):
    """A MedialAxisResult of bare balls (no faces), with the spacing the analysis reads."""
    vertices = np.ascontiguousarray(vertices, dtype=np.float64)
    mesh = _core.MedialMesh(vertices, np.asarray(radius, dtype=np.float64),
                            np.zeros(1, np.int32), np.zeros(0, np.int32),
                            np.zeros(0, np.uint8), np.zeros(0, np.int32))
    return cadmedial.MedialAxisResult(mesh, {"spacing": spacing})


def grid(xs, ys):
    x, y = np.meshgrid(xs, ys, indexing="ij")
    return x.ravel(), y.ravel()


def slab_balls(step=0.5):
    """The tilted slab's exact medial balls on its mid-plane (radius 1), inset by 1."""
    x, y = grid(np.arange(1.0, 39.0 + 1e-9, step), np.arange(1.0, 29.0 + 1e-9, step))
    p = np.column_stack([x, y, np.ones_like(x)])
    a = math.radians(TILT_DEGREES)
    # FreeCAD's rotation about +y by a: x' = x cos a + z sin a, z' = -x sin a + z cos a.
    rot = np.array([[math.cos(a), 0, math.sin(a)], [0, 1, 0], [-math.sin(a), 0, math.cos(a)]])
    return medial(p @ rot.T, np.ones(len(p)), step)


def tube_balls(step=0.25):
    """The tube's medial cylinder (radius 4, balls of radius 1), z in [1, 19]."""
    t, z = grid(np.arange(0, 2 * math.pi, step / 4.0), np.arange(1.0, 19.0 + 1e-9, step))
    return medial(np.column_stack([4 * np.cos(t), 4 * np.sin(t), z]), np.ones(len(t)), step)


def shell_balls(count=6000):
    """The shell's medial sphere (radius 5, balls of radius 1): a Fibonacci lattice."""
    i = np.arange(count) + 0.5
    phi = np.arccos(1 - 2 * i / count)
    theta = math.pi * (1 + 5 ** 0.5) * i
    p = 5 * np.column_stack([np.cos(theta) * np.sin(phi), np.sin(theta) * np.sin(phi), np.cos(phi)])
    return medial(p, np.ones(count), 5 * math.sqrt(4 * math.pi / count))


def rib_balls(step=0.25):
    """The plate's mid-plane balls (radius 2) and the rib's (radius 0.5)."""
    x, y = grid(np.arange(2.0, 38.0 + 1e-9, step), np.arange(2.0, 38.0 + 1e-9, step))
    plate = np.column_stack([x, y, np.full_like(x, 2.0)])
    z, y2 = grid(np.arange(4.5, 13.5 + 1e-9, step), np.arange(0.5, 39.5 + 1e-9, step))
    rib = np.column_stack([np.full_like(z, 20.0), y2, z])
    return medial(np.vstack([plate, rib]),
                  np.concatenate([np.full(len(plate), 2.0), np.full(len(rib), 0.5)]), step)


def faces_on_plane(shape, axis, value, tol=1e-6):
    """Names of the planar faces of ``shape`` lying in the plane coordinate[axis] == value."""
    names = []
    for i, f in enumerate(shape.Faces):
        box = f.BoundBox
        lo, hi = [(box.XMin, box.XMax), (box.YMin, box.YMax), (box.ZMin, box.ZMax)][axis]
        if abs(lo - value) < tol and abs(hi - value) < tol:
            names.append("Face%d" % (i + 1))
    return names
