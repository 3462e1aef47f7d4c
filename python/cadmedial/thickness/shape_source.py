"""The B-rep behind a thickness analysis, as FreeCAD Part shapes.

The surface points and the rays need OpenCASCADE's tessellation and intersections, which the
compiled core does not expose; FreeCAD's Part module (0.20) does, so this package needs it.
"""

import os
import sys

from .. import _core

_FREECAD_LIB = "/usr/lib/freecad/lib"


def import_part():
    """FreeCAD's Part module (FreeCAD imported first, as Part requires), or InvalidInput saying
    how to get it."""
    if "Part" not in sys.modules and _FREECAD_LIB not in sys.path and os.path.isdir(_FREECAD_LIB):
        sys.path.append(_FREECAD_LIB)
    try:
        import FreeCAD  # noqa: F401
        import Part
    except ImportError as error:
        raise _core.InvalidInput("wall thickness needs FreeCAD's Part module (apt-get install "
                                 "freecad): %s" % error) from None
    return Part


def _read_file(Part, path):
    if not os.path.isfile(path):
        raise _core.InvalidInput("%s: no such file" % path)
    if path.lower().endswith(".fcstd"):
        raise _core.InvalidInput("%s: FreeCAD documents are not read here; open it in FreeCAD "
                                 "and pass the object's Shape" % path)
    shape = Part.Shape()
    try:
        shape.read(path)
    except Exception as error:  # Part raises plain Exception/Part.OCCError on unreadable files
        raise _core.InvalidInput("%s: cannot read the file: %s" % (path, error)) from None
    return shape


def solids_of(source):
    """(shape, solids): the Part.Shape of ``source`` (a file path, BREP text or a Part.Shape)
    and its closed solids, in the order of shape.Solids (closed shells made solids when the
    shape holds no solid). Raises InvalidInput when there is no closed solid."""
    Part = import_part()
    if isinstance(source, os.PathLike):
        source = os.fspath(source)
    if hasattr(source, "exportBrepToString"):
        shape = source
    elif isinstance(source, str) and source.lstrip().startswith(("CASCADE Topology",
                                                                  "DBRep_DrawableShape")):
        shape = Part.Shape()
        try:
            shape.importBrepFromString(source)
        except Exception as error:
            raise _core.InvalidInput("cannot read the BREP text: %s" % error) from None
    elif isinstance(source, str):
        shape = _read_file(Part, source)
    else:
        raise TypeError("source must be a file path, BREP text or a Part.Shape, got "
                        + type(source).__name__)
    if shape.isNull():
        raise _core.InvalidInput("the shape is empty")
    solids = list(shape.Solids)
    if not solids:
        solids = [Part.Solid(shell) for shell in shape.Shells if shell.isClosed()]
    solids = [solid for solid in solids if solid.Volume > 0]
    if not solids:
        raise _core.InvalidInput("the shape holds no closed solid (%d faces, %d shells): wall "
                                 "thickness is measured inside solids"
                                 % (len(shape.Faces), len(shape.Shells)))
    return shape, solids
