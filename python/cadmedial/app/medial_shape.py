"""The MedialShape document object: a Part::FeaturePython whose Shape is the medial surface of a
MedialAxis as a compound of planar faces, one per polygon. The compound is built in C++ and
arrives as BREP text: faces made one by one in Python take ~35 s per 1e5.

Saved inside .FCStd files, keep them: module ``cadmedial.app.medial_shape``, class ``MedialShape``.
"""

import FreeCAD as App
import Part

from .results import medial_result
from .registry import attach_view_provider, run_long


class MedialShape:
    Type = "MedialShape"

    def __init__(self, obj):
        obj.Proxy = self
        obj.addProperty("App::PropertyLink", "Base", "Medial Shape", "The MedialAxis object to build faces of")

    def __getstate__(self):
        return {"Type": self.Type}

    def __setstate__(self, state):
        return None

    dumps, loads = __getstate__, __setstate__

    def execute(self, obj):
        try:
            if obj.Base is None:
                raise ValueError("no Base: link a MedialAxis object")
            shape = Part.Shape()
            result = medial_result(obj.Base)
            # to_brep builds the faces in C++ without the GIL: in the GUI, in a thread.
            brep = run_long("Faces of %s" % obj.Base.Label, lambda progress: result.to_brep())
            shape.importBrepFromString(brep, False)
        except Exception as error:  # report, keep the last good shape
            App.Console.PrintError("%s: shape not updated: %s\n" % (obj.Label, error))
            raise RuntimeError("%s: %s" % (obj.Label, error)) from None  # FreeCAD's error mark
        obj.Shape = shape


def make_medial_shape(medial_axis, name="MedialShape"):
    """Adds a MedialShape of a MedialAxis object, computes it and returns it."""
    obj = medial_axis.Document.addObject("Part::FeaturePython", name)
    MedialShape(obj)
    obj.Label = "%s faces" % medial_axis.Label
    obj.Base = medial_axis
    attach_view_provider(obj, MedialShape.Type)
    obj.Document.recompute([obj])
    return obj
