# FreeCAD runs this file when its GUI starts: it registers the Medial Axis workbench.
# Importing cadmedial.gui registers the commands and the view providers (so that
# cadmedial.app.make_medial_axis() in the Python console shows colours without activating the
# workbench). A missing or broken compiled module is reported, never fatal to FreeCAD.
import FreeCAD
import FreeCADGui


class MedialAxisWorkbench(FreeCADGui.Workbench):
    MenuText = "Medial Axis"
    ToolTip = "Medial axis of CAD solids (CAD_MEDIAL, Dey & Zhao), coloured by medial radius"

    def __init__(self):
        try:
            from cadmedial.gui.icons import icon_path
            self.__class__.Icon = icon_path("MedialAxisWorkbench.svg")
        except Exception:
            pass

    def Initialize(self):
        import cadmedial.gui  # noqa: F401  (registers the commands)
        # Another module's commands register themselves (cadmedial.gui.commands.register) and
        # are listed here.
        commands = ["MedialAxis_Create", "MedialAxis_Export", "MedialAxis_MakeShape",
                    "MedialAxis_ThinnestWall", "MedialAxis_WallThickness", "MedialAxis_Batch"]
        self.appendToolbar("Medial Axis", commands)
        self.appendMenu("&Medial Axis", commands)

    def GetClassName(self):
        return "Gui::PythonWorkbench"


try:
    import cadmedial.gui  # noqa: F401
except Exception as _error:
    FreeCAD.Console.PrintError("MedialAxis addon: cannot load cadmedial: %s\n" % _error)

FreeCADGui.addWorkbench(MedialAxisWorkbench())
