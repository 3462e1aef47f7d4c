"""FreeCAD document objects of cadmedial. Imports FreeCAD, Part and Mesh, never FreeCADGui.

    import cadmedial.app
    feature = cadmedial.app.make_medial_axis(App.ActiveDocument.Box, samples=20000)

The GUI attaches its view providers through ``view_provider_factories`` (filled by
``cadmedial.gui`` when it is imported), so that this package stays free of GUI code.
"""

from .medial_axis import MedialAxis, make_medial_axis
from .medial_shape import MedialShape, make_medial_shape
from .results import StoredResult, medial_result, prepare_result, store_result
from .registry import is_medial_axis, view_provider_factories
from .thickness_object import WallThickness, is_wall_thickness, make_wall_thickness


def export_medial_axis(obj, path):
    """Writes the result of a MedialAxis object to path (.ply, .obj or .ma, by extension)."""
    medial_result(obj).save(path)


__all__ = ["MedialAxis", "MedialShape", "make_medial_axis", "make_medial_shape", "medial_result",
           "export_medial_axis", "is_medial_axis", "view_provider_factories", "StoredResult",
           "prepare_result", "store_result", "WallThickness", "make_wall_thickness",
           "is_wall_thickness"]
