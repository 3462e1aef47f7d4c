"""View providers: the MedialAxis mesh coloured per vertex by medial radius, with the legend.

Saved inside .FCStd files, keep them: module ``cadmedial.gui.view_provider``, classes
``ViewProviderMedialAxis`` and ``ViewProviderMedialShape``.
"""

import FreeCADGui as Gui
from PySide2 import QtCore

from . import legend
from .icons import icon_path
from .wall_marker import marker


class _StatelessProxy:
    """What both view providers share: nothing to save in the document, the object at hand."""

    def attach(self, vobj):
        self.Object = vobj.Object
        self.attached(vobj)

    def attached(self, vobj):
        pass

    def __getstate__(self):
        return None

    def __setstate__(self, state):
        return None

    dumps, loads = __getstate__, __setstate__


class ViewProviderMedialAxis(_StatelessProxy):
    """Per-vertex colours come from the object's RadiusColors (App::PropertyColorList): the mesh
    view provider uses them while its Coloring property is on."""

    def __init__(self, vobj):
        vobj.Proxy = self
        vobj.Lighting = "Two side"  # the medial surface is open: both sides are seen
        vobj.Coloring = True

    def getIcon(self):
        return icon_path("MedialAxis_Create.svg")

    def attached(self, vobj):
        # Also runs when a saved document is reopened. There the mesh view provider has read
        # Coloring = True before the colours reached its node, and shows grey: apply them again
        # once the document is loaded.
        obj = vobj.Object

        def recolour(tries=20):
            try:
                if obj.ViewObject is not None and obj.ViewObject.Coloring:
                    obj.ViewObject.Coloring = False
                    obj.ViewObject.Coloring = True
                # The 3D view of a document being opened comes after its objects: wait for it.
                if not legend.refresh(obj.Document) and tries > 0:
                    QtCore.QTimer.singleShot(100, lambda: recolour(tries - 1))
            except Exception:  # closed or deleted in between: nothing to colour
                pass
        QtCore.QTimer.singleShot(0, recolour)

    def updateData(self, obj, prop):
        if prop == "RadiusColors" and obj.ViewObject is not None:
            # Switch colouring off and on so that the new colour list is applied to the new mesh.
            # New colours for the same mesh (a new colour range) need it too: without it the
            # view kept the old colours (tests/freecad/test_color_range_gui.py).
            obj.ViewObject.Coloring = False
            obj.ViewObject.Coloring = True
        if prop in ("RadiusColors", "VertexCount", "RadiusMin", "RadiusMax", "Label",
                    "AutoColorRange", "ColorRangeMin", "ColorRangeMax"):
            _refresh_later(obj.Document)

    def onChanged(self, vobj, prop):
        if prop == "Visibility":
            _refresh_later(vobj.Object.Document)

    def onDelete(self, vobj, subelements):
        legend.refresh(vobj.Object.Document, leaving=vobj.Object)
        if marker.owner is vobj.Object:  # its thinnest wall's mark goes with it
            marker.clear()
        return True

    def setEdit(self, vobj, mode=0):
        if mode != 0:
            return None  # transform and other modes: FreeCAD's own
        from .task_panel import TaskPanelMedialAxis
        Gui.Control.showDialog(TaskPanelMedialAxis([vobj.Object.Source], edit=vobj.Object))
        return True

    def unsetEdit(self, vobj, mode=0):
        if mode != 0:
            return None
        Gui.Control.closeDialog()
        return True

    def doubleClicked(self, vobj):
        Gui.ActiveDocument.setEdit(vobj.Object.Name)
        return True


class ViewProviderMedialShape(_StatelessProxy):
    """The Part feature of planar faces: default Part display, our icon. Hidden at first: it
    lies exactly on the coloured mesh (Space shows it)."""

    def __init__(self, vobj):
        vobj.Proxy = self
        vobj.Visibility = False

    def getIcon(self):
        return icon_path("MedialAxis_MakeShape.svg")


def _refresh_later(doc):
    # After the current recompute or property change has finished: the views may not exist yet
    # while a document is being opened.
    def refresh():
        try:
            legend.refresh(doc)
        except Exception:  # the document was closed in between: nothing to show
            pass
    QtCore.QTimer.singleShot(0, refresh)
