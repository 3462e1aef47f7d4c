"""The workbench's commands: MedialAxis_Create, MedialAxis_Export, MedialAxis_MakeShape.
They gather the selection and call cadmedial.app; no geometry here."""

import os

import FreeCAD as App
import FreeCADGui as Gui
import Part
from PySide2 import QtWidgets

from cadmedial.app import export_medial_axis, is_medial_axis, make_medial_shape

from .icons import icon_path


def solid_sources():
    """Selected objects whose shape holds at least one solid."""
    sources = []
    for obj in Gui.Selection.getSelection():
        try:
            if Part.getShape(obj).Solids:
                sources.append(obj)
        except Exception:  # not a shape-bearing object
            continue
    return sources


def selected_medial_axes():
    return [obj for obj in Gui.Selection.getSelection() if is_medial_axis(obj)]


class CreateMedialAxis:
    def GetResources(self):
        return {"Pixmap": icon_path("MedialAxis_Create.svg"),
                "MenuText": "Medial axis",
                "ToolTip": "Medial axis of the selected solids, coloured by medial radius "
                           "(one parametric object per selected object)"}

    def IsActive(self):
        return App.ActiveDocument is not None and bool(solid_sources())

    def Activated(self):
        from .task_panel import TaskPanelMedialAxis
        sources = solid_sources()
        if sources:
            Gui.Control.showDialog(TaskPanelMedialAxis(sources))


class ExportMedialAxis:
    FILTERS = "PLY with radius (*.ply);;Wavefront OBJ (*.obj);;Medial axis, Q-MAT (*.ma)"

    def GetResources(self):
        return {"Pixmap": icon_path("MedialAxis_Export.svg"),
                "MenuText": "Export medial axis…",
                "ToolTip": "Write the selected medial axis to PLY (with radius), OBJ or .ma"}

    def IsActive(self):
        return len(selected_medial_axes()) == 1

    def Activated(self):
        obj = selected_medial_axes()[0]
        start = os.path.join(os.path.expanduser("~"), obj.Label.replace(" ", "_") + ".ply")
        path, chosen = QtWidgets.QFileDialog.getSaveFileName(
            Gui.getMainWindow(), "Export medial axis", start, self.FILTERS)
        if not path:
            return
        if not os.path.splitext(path)[1]:
            path += chosen[chosen.index("*") + 1:chosen.index(")")]
        try:
            export_medial_axis(obj, path)
        except Exception as error:
            App.Console.PrintError("Export of %s failed: %s\n" % (obj.Label, error))
            QtWidgets.QMessageBox.critical(Gui.getMainWindow(), "Export medial axis", str(error))
            return
        App.Console.PrintMessage("Medial axis written to %s\n" % path)


class MakeMedialShape:
    def GetResources(self):
        return {"Pixmap": icon_path("MedialAxis_MakeShape.svg"),
                "MenuText": "Medial surface as Part shape",
                "ToolTip": "A Part object of planar faces (one per medial polygon) for each "
                           "selected medial axis"}

    def IsActive(self):
        return bool(selected_medial_axes())

    def Activated(self):
        objects = selected_medial_axes()
        doc = objects[0].Document
        doc.openTransaction("Medial surface as Part shape")
        for obj in objects:
            make_medial_shape(obj)
        doc.commitTransaction()


COMMANDS = {"MedialAxis_Create": CreateMedialAxis, "MedialAxis_Export": ExportMedialAxis,
            "MedialAxis_MakeShape": MakeMedialShape}


def register():
    for name, command in COMMANDS.items():
        Gui.addCommand(name, command())
