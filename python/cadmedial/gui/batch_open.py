"""Opens one part of a batch in FreeCAD (a double-click on its row): a new document with the
part's input and, when it succeeded, its medial mesh from OUTDIR/parts, read by cadmedial.load
(FreeCAD's own PLY reader misreads the faces' extra properties). Runs in the GUI thread: a part
of a million faces takes a few seconds."""

import os

import FreeCAD as App
import FreeCADGui as Gui

from cadmedial.batch import outputs

_STEP_IGES = (".step", ".stp", ".iges", ".igs")
_BREP = (".brep", ".brp")


def open_part(record, out_dir, fmt):
    """The document opened for ``record`` (a summary row); raises on a file FreeCAD cannot read."""
    path = record.get("input") or ""
    suffix = os.path.splitext(path)[1].lower()
    if suffix == ".fcstd":
        doc = App.openDocument(path)
    else:
        doc = App.newDocument(_document_name(record["part"]))
        if suffix in _STEP_IGES:
            import Import
            Import.insert(path, doc.Name)
        elif suffix in _BREP:
            import Part
            Part.insert(path, doc.Name)
    mesh = outputs.mesh_path(out_dir, record["part"], fmt)
    if record.get("status") == "ok" and os.path.isfile(mesh):
        import cadmedial
        from cadmedial.app.results import prepare_result
        stored = prepare_result(cadmedial.load(mesh))
        stored.discard()  # its PLY copy: the batch's file is the one kept
        axis = doc.addObject("Mesh::Feature", "MedialAxis")
        axis.Mesh = stored.mesh
        for obj in doc.Objects:  # the input seen through its medial axis
            if obj.isDerivedFrom("Part::Feature") and obj.ViewObject is not None:
                obj.ViewObject.DisplayMode = "Wireframe"
    doc.recompute()
    Gui.SendMsgToActiveView("ViewFit")
    return doc


def _document_name(part):
    # A document name is an identifier: letters, digits and underscores.
    name = "".join(c if c.isalnum() else "_" for c in os.path.basename(part))
    return name if name and not name[0].isdigit() else "Part_" + name
