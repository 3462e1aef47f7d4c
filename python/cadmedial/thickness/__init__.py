"""Wall thickness of solids from their medial axis (issue 34).

    from cadmedial.thickness import thickness
    t = thickness("part.step", min=0.8, max=4)
    t.points, t.values, t.thin_regions, t.statistics

The sphere thickness of a surface point is the diameter of the largest ball inside the solid that
contains it (see sphere.py); ``probe`` also gives the ray thickness. Needs FreeCAD's Part module
for the surface mesh and the rays (see shape_source.py).
"""

from .analysis import CORNER_POLICIES, ThicknessResult, check_settings, thickness
from .batch_hook import BATCH_COLUMNS, batch_result, batch_step
from .probe import probe

__all__ = ["thickness", "ThicknessResult", "probe", "check_settings", "CORNER_POLICIES",
           "batch_step", "batch_result", "BATCH_COLUMNS"]


import sys as _sys
import types as _types


class _CallableModule(_types.ModuleType):
    """cadmedial.thickness is this package and, called, the function thickness(): the package
    holds the CLI (python -m cadmedial.thickness) and the parts of the analysis."""

    def __call__(self, *args, **kwargs):
        return thickness(*args, **kwargs)


_sys.modules[__name__].__class__ = _CallableModule
