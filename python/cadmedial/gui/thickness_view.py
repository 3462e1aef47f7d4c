"""View provider of the WallThickness object: the surface mesh coloured per vertex from the
object's ThicknessColors. Saved in .FCStd files, keep: module ``cadmedial.gui.thickness_view``,
class ``ViewProviderWallThickness``."""

from .icons import icon_path


class ViewProviderWallThickness:
    def __init__(self, vobj):
        vobj.Proxy = self
        vobj.Coloring = True

    def attach(self, vobj):
        self.Object = vobj.Object

    def getIcon(self):
        return icon_path("MedialAxis_Create.svg")

    def updateData(self, obj, prop):
        if prop == "ThicknessColors" and obj.ViewObject is not None:
            # Off and on, so that the new colour list is applied to the new mesh.
            obj.ViewObject.Coloring = False
            obj.ViewObject.Coloring = True

    def __getstate__(self):
        return None

    def __setstate__(self, state):
        return None

    dumps, loads = __getstate__, __setstate__
