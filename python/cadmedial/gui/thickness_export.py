"""The task panel's files: regions and faces CSV (thickness/writers.py) and the HTML report
(thickness/report.py) with a picture of the 3D view; file dialogs open in the document's
folder."""

import os
import tempfile

from PySide2 import QtWidgets

from cadmedial.thickness.report import write_report
from cadmedial.thickness.writers import write_faces_csv, write_regions_csv

PICTURE_SIZE = (1000, 750)


def document_folder(doc):
    """The folder of doc's file, or the home folder for a document not saved yet."""
    name = getattr(doc, "FileName", "") if doc is not None else ""
    return os.path.dirname(name) if name else os.path.expanduser("~")


def faces_path_of(regions_path):
    """The faces CSV written beside a regions CSV: part-regions.csv -> part-faces.csv."""
    stem, ext = os.path.splitext(regions_path)
    stem = stem[:-len("-regions")] if stem.endswith("-regions") else stem
    return stem + "-faces" + (ext or ".csv")


def export_csv(result, regions_path):
    """Writes the regions CSV at regions_path and the faces CSV beside it; returns both paths."""
    faces_path = faces_path_of(regions_path)
    write_regions_csv(result, regions_path)
    write_faces_csv(result, faces_path)
    return regions_path, faces_path


def view_png(view, size=PICTURE_SIZE):
    """PNG bytes of a 3D view (view.saveImage through a temporary file), or None without one."""
    if view is None or not hasattr(view, "saveImage"):
        return None
    fd, tmp = tempfile.mkstemp(suffix=".png")
    os.close(fd)
    try:
        view.saveImage(tmp, size[0], size[1], "White")
        with open(tmp, "rb") as f:
            data = f.read()
        return data or None
    finally:
        os.remove(tmp)


def export_html(result, path, title, view):
    """Writes the HTML report with the view's picture (the mesh's own picture without a view)."""
    write_report(result, path, title, png=view_png(view))
    return path


def ask_path(parent, caption, doc, name, pattern):
    """A save dialog in doc's folder proposing ``name``; the chosen path or None."""
    path, _ = QtWidgets.QFileDialog.getSaveFileName(
        parent, caption, os.path.join(document_folder(doc), name), pattern)
    return path or None
