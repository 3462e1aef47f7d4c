"""The Wall thickness task panel: process presets, minimum / maximum wall, the analysis in a
worker thread (never on the GUI thread), then the regions list: a click selects the region's
faces and zooms to them."""

import threading

import FreeCAD as App
import FreeCADGui as Gui
import Part
from PySide2 import QtCore, QtWidgets

from cadmedial.app.thickness_object import analyse_shape, make_wall_thickness, region_line

# Stated as presets, editable: common rules of thumb for the nominal wall, not material data.
PRESETS = [
    ("Custom", None, None),
    ("Injection moulding, ABS (1.2 to 3.5 mm)", 1.2, 3.5),
    ("Injection moulding, PP (0.8 to 3.8 mm)", 0.8, 3.8),
    ("FDM printing, 0.4 mm nozzle (0.8 mm min)", 0.8, None),
    ("SLA printing (0.6 mm min)", 0.6, None),
    ("Die casting, aluminium (1.0 to 5.0 mm)", 1.0, 5.0),
    ("Sheet metal / machined (0.5 mm min)", 0.5, None),
]


class TaskPanelWallThickness:
    def __init__(self, source):
        self.source = source
        self.result = None
        self.obj = None
        self._thread = None
        w = QtWidgets.QWidget()
        w.setWindowTitle("Wall thickness")
        form = QtWidgets.QFormLayout(w)
        self.preset = QtWidgets.QComboBox()
        self.preset.addItems([p[0] for p in PRESETS])
        self.preset.currentIndexChanged.connect(self._apply_preset)
        form.addRow("Process", self.preset)
        self.min_wall = QtWidgets.QDoubleSpinBox()
        self.max_wall = QtWidgets.QDoubleSpinBox()
        for box in (self.min_wall, self.max_wall):
            box.setRange(0.0, 1e6)
            box.setDecimals(3)
            box.setSpecialValueText("none")
        self.min_wall.setValue(1.0)
        form.addRow("Minimum wall", self.min_wall)
        form.addRow("Maximum wall", self.max_wall)
        self.corners = QtWidgets.QComboBox()
        self.corners.addItems(["exclude", "zero"])
        form.addRow("Convex edges", self.corners)
        self.run = QtWidgets.QPushButton("Analyse")
        self.run.clicked.connect(self.start)
        form.addRow(self.run)
        self.status = QtWidgets.QLabel("")
        self.status.setWordWrap(True)
        form.addRow(self.status)
        self.regions = QtWidgets.QListWidget()
        self.regions.itemClicked.connect(self._show_region)
        form.addRow(self.regions)
        self.form = w

    def _apply_preset(self, index):
        _, lo, hi = PRESETS[index]
        if lo is not None or hi is not None:
            self.min_wall.setValue(lo or 0.0)
            self.max_wall.setValue(hi or 0.0)

    def start(self):
        if self._thread is not None:
            return
        lo, hi = self.min_wall.value() or None, self.max_wall.value() or None
        corners = self.corners.currentText()
        shape = Part.getShape(self.source).copy()
        self.status.setText("Analysing %s ..." % self.source.Label)
        self.run.setEnabled(False)
        self._outcome = None

        def work():  # the engine releases the GIL; no Qt or document access here
            try:
                self._outcome = ("ok", analyse_shape(shape, lo, hi, corners))
            except Exception as error:
                self._outcome = ("error", error)

        self._settings = (lo, hi, corners)
        self._thread = threading.Thread(target=work, daemon=True)
        self._thread.start()
        self._timer = QtCore.QTimer()
        self._timer.timeout.connect(self._poll)
        self._timer.start(100)

    def _poll(self):
        if self._thread.is_alive():
            return
        self._timer.stop()
        self._thread = None
        self.run.setEnabled(True)
        kind, value = self._outcome
        if kind == "error":
            self.status.setText("Not analysed: %s" % value)
            return
        lo, hi, corners = self._settings
        try:
            if self.obj is None:
                self.obj = make_wall_thickness(self.source, lo, hi, corners, result=value)
            else:
                from cadmedial.app.thickness_object import parameters_of
                self.obj.MinWall, self.obj.MaxWall, self.obj.Corners = lo or 0.0, hi or 0.0, corners
                self.obj.Proxy.pending = (parameters_of(self.obj), value)
                self.obj.Document.recompute([self.obj])  # takes the pending result: no compute
        except Exception as error:
            self.status.setText("Not analysed: %s" % error)
            return
        self.result = value
        st = value.statistics
        self.status.setText("%s: thickness %.4g to %.4g, mean %.4g; %d thin, %d thick region(s)"
                            % ("PASS" if value.passed else "FAIL", st["min"] or 0, st["max"] or 0,
                               st["mean"] or 0, len(value.thin_regions), len(value.thick_regions)))
        self.regions.clear()
        for g in value.thin_regions + value.thick_regions:
            self.regions.addItem(region_line(g))

    def _show_region(self, item):
        g = (self.result.thin_regions + self.result.thick_regions)[self.regions.row(item)]
        Gui.Selection.clearSelection()
        for face in g["faces"]:
            Gui.Selection.addSelection(self.source, face)
        Gui.SendMsgToActiveView("ViewSelection")

    def accept(self):
        Gui.Control.closeDialog()
        return True

    def reject(self):
        Gui.Control.closeDialog()
        return True

    def getStandardButtons(self):
        return int(QtWidgets.QDialogButtonBox.Close)
