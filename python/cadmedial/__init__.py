"""cadmedial: the medial axis of CAD solids (CAD_MEDIAL, Dey & Zhao, 2003) from Python.

Plain Python over the compiled module ``cadmedial._core``; FreeCAD is not needed::

    import cadmedial
    result = cadmedial.compute("part.step", samples=20000)
    result.vertices, result.radius      # (V, 3) and (V,) numpy arrays
    result.save("part_medial.ply")
    s = cadmedial.structure(result)     # sheets, seams, junctions, rims, curves (docs/structure.md)
    small = cadmedial.simplify(result, "0.5%")   # the compact mesh (docs/compact.md)

``cadmedial.app`` (FreeCAD document objects) and ``cadmedial.gui`` (the workbench) build on it.
"""

import os as _os


def _find_core():
    # The compiled module normally sits beside this file (installed addon). From a source checkout
    # it is in the build tree: CADMEDIAL_CORE_DIR names that folder, else <repo>/build is tried.
    from importlib.machinery import EXTENSION_SUFFIXES
    here = _os.path.dirname(_os.path.abspath(__file__))
    if any(_os.path.exists(_os.path.join(here, "_core" + suffix)) for suffix in EXTENSION_SUFFIXES):
        return
    candidates = [_os.environ.get("CADMEDIAL_CORE_DIR", ""),
                  _os.path.join(here, _os.pardir, _os.pardir, "build", "python", "cadmedial")]
    for folder in candidates:
        if folder and _os.path.isdir(folder):
            __path__.append(_os.path.abspath(folder))
            return


_find_core()

from ._core import Cancelled, Error, GeometryError, InvalidInput  # noqa: E402
from .api import SamplingPlan, compute, load, plan_sampling, read_shape  # noqa: E402
from .result import FaceKind, Faces, MedialAxisResult  # noqa: E402
from .compact import simplify  # noqa: E402
from . import batch  # noqa: E402  (callable: cadmedial.batch(inputs, out_dir, ...); Dask loads on use)

__version__ = "0.1.0"


def __getattr__(name):
    # cadmedial.thickness (a callable subpackage) pulls in scipy and FreeCAD's Part, and
    # cadmedial.structure (callable too: structure(result)) scipy: only on use.
    if name in ("thickness", "structure"):
        import importlib
        return importlib.import_module(__name__ + "." + name)
    raise AttributeError("module 'cadmedial' has no attribute %r" % name)

__all__ = [
    "compute", "plan_sampling", "load", "read_shape", "batch", "simplify",
    "MedialAxisResult", "Faces", "FaceKind", "SamplingPlan",
    "Error", "InvalidInput", "GeometryError", "Cancelled", "thickness", "structure",
]
