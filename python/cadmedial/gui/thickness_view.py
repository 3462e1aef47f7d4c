"""View provider of the WallThickness object: the surface mesh coloured per vertex from the
object's ThicknessColors, with the thickness legend over the 3D view. Saved in .FCStd files,
keep: module ``cadmedial.gui.thickness_view``, class ``ViewProviderWallThickness``."""

from PySide2 import QtCore

from . import thickness_legend
from .icons import icon_path


class ViewProviderWallThickness:
    def __init__(self, vobj):
        vobj.Proxy = self
        vobj.Coloring = True

    def attach(self, vobj):
        self.Object = vobj.Object

    def attached(self, vobj):
        # Also on reopening: the colours reach the node after Coloring was read; apply them again.
        obj = vobj.Object

        def recolour():
            try:
                if obj.ViewObject is not None and obj.ViewObject.Coloring:
                    obj.ViewObject.Coloring = False
                    obj.ViewObject.Coloring = True
            except Exception:  # closed or deleted in between
                pass
        QtCore.QTimer.singleShot(0, recolour)
        thickness_legend.refresh_later(obj.Document)

    def getIcon(self):
        return icon_path("MedialAxis_Create.svg")

    def updateData(self, obj, prop):
        if prop == "ThicknessColors" and obj.ViewObject is not None:
            # Off and on, so that the new colour list is applied to the new mesh.
            obj.ViewObject.Coloring = False
            obj.ViewObject.Coloring = True
        if prop in ("ThicknessColors", "Label", "MinWall", "MaxWall"):
            thickness_legend.refresh_later(obj.Document)

    def onChanged(self, vobj, prop):
        if prop == "Visibility":
            thickness_legend.refresh_later(vobj.Object.Document)

    def onDelete(self, vobj, subelements):
        thickness_legend.refresh(vobj.Object.Document, leaving=vobj.Object)
        return True

    def __getstate__(self):
        return None

    def __setstate__(self, state):
        return None

    dumps, loads = __getstate__, __setstate__
