"""Analytic solids of the thickness bench (known wall thickness noted beside each)."""

import FreeCAD
import Part

V = FreeCAD.Vector


def plate():  # 2 thick
    return Part.makeBox(40, 30, 2)


def tilted_slab():  # 2 thick along its normal, 2.31 along z
    s = Part.makeBox(40, 30, 2)
    s.rotate(V(0, 0, 0), V(0, 1, 0), 30)
    return s


def tube():  # wall 2
    return Part.makeCylinder(5, 20).cut(Part.makeCylinder(3, 20))


def spherical_shell():  # wall 2
    return Part.makeSphere(6).cut(Part.makeSphere(4))


def rib_on_plate():  # plate 4, rib 1
    plate = Part.makeBox(40, 40, 4)
    rib = Part.makeBox(1, 40, 10, V(19.5, 0, 4))
    return plate.fuse(rib).removeSplitter()


def filleted_corner():  # an L of walls 2 thick, inner corner filleted with radius 3
    outer = Part.makeBox(20, 20, 10)
    inner = Part.makeBox(18, 18, 10, V(2, 2, 0))
    l_shape = outer.cut(inner)
    edges = [e for e in l_shape.Edges
             if abs(e.BoundBox.XMin - 2) < 1e-9 and abs(e.BoundBox.XMax - 2) < 1e-9
             and abs(e.BoundBox.YMin - 2) < 1e-9 and abs(e.BoundBox.YMax - 2) < 1e-9]
    return l_shape.makeFillet(3, edges)


MAKERS = {"plate": plate, "tilted_slab": tilted_slab, "tube": tube,
          "spherical_shell": spherical_shell, "rib_on_plate": rib_on_plate,
          "filleted_corner": filleted_corner}
NAMES = list(MAKERS)


def make(name):
    return MAKERS[name]()
