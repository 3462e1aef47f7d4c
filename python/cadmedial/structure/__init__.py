"""The medial axis as a structure (issue 35, item 1): sheets, seams, junctions, rims and curves.

    import cadmedial
    axis = cadmedial.compute("part.step")
    s = cadmedial.structure(axis)          # or cadmedial.structure.structure(axis)
    s.face_sheet                           # (F,) sheet id of each face (-1: a tube's face)
    s.sheets, s.seams, s.junctions, s.rims, s.free, s.curves   # lists of dicts
    s.to_dict()                            # plain data for JSON

Plain numpy and scipy over a MedialAxisResult; no FreeCAD. See docs/structure.md.
"""

from .analysis import AxisStructure, structure
from .edge_kinds import FREE, INSIDE, RIM, SEAM, TUBE

__all__ = ["structure", "AxisStructure", "INSIDE", "SEAM", "RIM", "FREE", "TUBE"]


import sys as _sys
import types as _types


class _CallableModule(_types.ModuleType):
    """cadmedial.structure is this package and, called, the function structure()."""

    def __call__(self, *args, **kwargs):
        return structure(*args, **kwargs)


_sys.modules[__name__].__class__ = _CallableModule
