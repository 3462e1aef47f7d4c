"""The MedialAxis_WallThickness command: opens the Wall thickness task panel for the selected
solid. Registered by cadmedial.gui (one line there)."""

import FreeCAD as App
import FreeCADGui as Gui
import Part

from cadmedial.app import view_provider_factories

from .icons import icon_path
from .thickness_view import ViewProviderWallThickness

COMMAND = "MedialAxis_WallThickness"


def _solid_source():
    sel = Gui.Selection.getSelection()
    if len(sel) != 1:
        return None
    try:
        return sel[0] if Part.getShape(sel[0]).Solids else None
    except Exception:  # not a shape-bearing object
        return None


class WallThicknessCommand:
    def GetResources(self):
        return {"Pixmap": icon_path("MedialAxis_Create.svg"), "MenuText": "Wall thickness",
                "ToolTip": "The selected solid coloured by wall thickness, thin and thick "
                           "regions listed (sphere method, from the medial axis)"}

    def IsActive(self):
        return App.ActiveDocument is not None and _solid_source() is not None

    def Activated(self):
        from .thickness_panel import TaskPanelWallThickness
        source = _solid_source()
        if source is not None:
            Gui.Control.showDialog(TaskPanelWallThickness(source))


def register():
    view_provider_factories["WallThickness"] = ViewProviderWallThickness
    Gui.addCommand(COMMAND, WallThicknessCommand())
