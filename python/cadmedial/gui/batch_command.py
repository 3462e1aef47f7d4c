"""The MedialAxis_Batch command ("Batch over a folder..."): shows the batch dialog, one for the
session (it keeps its last run's table). Registered by cadmedial.gui (one line there)."""

import FreeCADGui as Gui

from .icons import icon_path

COMMAND = "MedialAxis_Batch"
dialog = None  # the open dialog (tests reach it here)


class BatchCommand:
    def GetResources(self):
        return {"Pixmap": icon_path("MedialAxis_Create.svg"), "MenuText": "Batch over a folder...",
                "ToolTip": "The medial axis of every part of a folder, on Dask (local cores or a "
                           "cluster), with a summary table (cadmedial batch)"}

    def IsActive(self):
        return True  # needs no document or selection

    def Activated(self):
        global dialog
        if dialog is None:
            from .batch_dialog import BatchDialog
            dialog = BatchDialog(Gui.getMainWindow())
        dialog.show()
        dialog.raise_()
        dialog.activateWindow()


def register():
    Gui.addCommand(COMMAND, BatchCommand())
