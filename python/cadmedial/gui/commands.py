"""The workbench's commands: MedialAxis_Create, MedialAxis_Export, MedialAxis_MakeShape,
MedialAxis_ThinnestWall.
They gather the selection and call cadmedial.app; no geometry here."""

import os

import FreeCAD as App
import FreeCADGui as Gui
import Part
from PySide2 import QtCore, QtWidgets

import cadmedial
from cadmedial.app import export_medial_axis, is_medial_axis, make_medial_shape

from .icons import icon_path
from .wall_marker import marker


# The last message box shown (tests read and close it; it does not block).
last_message = None


def show_message(title, text, icon=QtWidgets.QMessageBox.Warning):
    """A message box that does not block the caller (tests and macros go on)."""
    global last_message
    box = QtWidgets.QMessageBox(icon, title, text, QtWidgets.QMessageBox.Ok, Gui.getMainWindow())
    box.setAttribute(QtCore.Qt.WA_DeleteOnClose)
    box.open()
    last_message = box
    return box


def why_not_a_source(obj):
    """None when obj's shape holds a solid the engine can read, else why not (the engine's
    words for a solid it refuses)."""
    try:
        shape = Part.getShape(obj)
    except Exception:
        shape = None
    if shape is None or shape.isNull():
        return "%s has no shape." % obj.Label
    if not shape.Solids:
        parts = shape.SubShapes if shape.ShapeType == "Compound" else [shape]
        kinds = sorted({part.ShapeType.lower() for part in parts}) or ["nothing"]
        return ("%s is not a solid (it is a %s): the medial axis needs a closed solid."
                % (obj.Label, " and a ".join(kinds)))
    try:
        cadmedial.read_shape(shape)
    except cadmedial.Error as error:
        return "%s cannot be used: %s" % (obj.Label, error)
    return None


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
        # Active with anything selected: a selection that cannot be used gets a message saying
        # why (a greyed button says nothing).
        return App.ActiveDocument is not None and bool(Gui.Selection.getSelection())

    def Activated(self):
        from .task_panel import TaskPanelMedialAxis
        selection = Gui.Selection.getSelection()
        reasons = [why for why in map(why_not_a_source, selection) if why]
        if reasons:
            show_message("Medial axis", "\n\n".join(reasons))
            App.Console.PrintWarning("Medial axis: %s\n" % " ".join(reasons))
            return
        if Gui.Control.activeDialog():
            show_message("Medial axis", "Close the open task panel first.")
            return
        try:
            Gui.Control.showDialog(TaskPanelMedialAxis(selection))
        except Exception as error:  # never a traceback: say it
            show_message("Medial axis", str(error))
            App.Console.PrintError("Medial axis: %s\n" % error)


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
        # Beside the document when it was saved, else in the home folder.
        folder = os.path.dirname(obj.Document.FileName) if obj.Document.FileName else ""
        start = os.path.join(folder or os.path.expanduser("~"), obj.Label.replace(" ", "_") + ".ply")
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
        try:
            for obj in objects:
                make_medial_shape(obj)
        except Exception as error:  # e.g. Stop in the progress dialog
            doc.abortTransaction()
            show_message("Medial surface as Part shape", str(error))
            return
        doc.commitTransaction()


class GoToThinnestWall:
    """Zooms the 3D view onto the thinnest wall (ThinnestWallAt) of the selected medial axis, or,
    with none selected, of the thinnest among the visible ones: one click. Marks the place."""

    def GetResources(self):
        return {"Pixmap": icon_path("MedialAxis_ThinnestWall.svg"),
                "MenuText": "Go to the thinnest wall",
                "ToolTip": "Zoom the view onto the thinnest wall the selected medial axis found "
                           "(none selected: the thinnest of the visible ones) and mark it"}

    def IsActive(self):
        if Gui.ActiveDocument is None:
            return False
        selected = selected_medial_axes()
        return len(selected) == 1 if selected else bool(walls_shown(App.ActiveDocument))

    def Activated(self):
        selected = selected_medial_axes()
        if selected:
            obj = selected[0]
        else:
            shown = walls_shown(App.ActiveDocument)
            if not shown:
                return
            obj = min(shown, key=lambda o: o.ThinnestWall.Value)
        thickness = obj.ThinnestWall.Value if "ThinnestWall" in obj.PropertiesList else 0.0
        if thickness <= 0:
            show_message("Thinnest wall", "%s found no wall thinner than two sample spacings."
                         % obj.Label, QtWidgets.QMessageBox.Information)
            return
        at = obj.ThinnestWallAt
        view = Gui.ActiveDocument.ActiveView
        zoom_onto(view, at, 40.0 * thickness)
        marker.show(view, (at.x, at.y, at.z), thickness, owner=obj)
        Gui.getMainWindow().statusBar().showMessage(
            "%s: thinnest wall %.4g mm at (%.4g, %.4g, %.4g)" % (obj.Label, thickness, at.x, at.y, at.z),
            15000)


def walls_shown(doc):
    """The visible MedialAxis objects of doc that found a thin wall."""
    return [obj for obj in (doc.Objects if doc is not None else [])
            if is_medial_axis(obj) and obj.ViewObject is not None and obj.ViewObject.Visibility
            and "ThinnestWall" in obj.PropertiesList and obj.ThinnestWall.Value > 0]


def zoom_onto(view, point, size):
    """Points an orthographic camera, in the view's current orientation, at point, showing a
    field `size` mm high."""
    rotation = view.getCameraOrientation()
    back = rotation.multVec(App.Vector(0, 0, 1))
    position = point + back * (10.0 * size)
    axis, angle = rotation.Axis, rotation.Angle
    view.setCamera("#Inventor V2.1 ascii\nOrthographicCamera {\n position %r %r %r\n "
                   "orientation %r %r %r %r\n nearDistance %r\n farDistance %r\n "
                   "focalDistance %r\n height %r\n}\n" % (
                       position.x, position.y, position.z, axis.x, axis.y, axis.z, angle,
                       0.1 * size, 100.0 * size, 10.0 * size, size))


COMMANDS = {"MedialAxis_Create": CreateMedialAxis, "MedialAxis_Export": ExportMedialAxis,
            "MedialAxis_MakeShape": MakeMedialShape, "MedialAxis_ThinnestWall": GoToThinnestWall}


def register(commands=None):
    """Registers COMMANDS (or the given {name: class}): another module adds its own with
    register({"MedialAxis_Thickness": ...}) and lists the name in InitGui's toolbar."""
    for name, command in (commands or COMMANDS).items():
        Gui.addCommand(name, command())
