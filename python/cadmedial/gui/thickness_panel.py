"""The Wall thickness task panel: process presets, minimum / maximum wall, the analysis in a
worker thread (never on the GUI thread), then the regions list (a click selects the region's
faces, zooms to them and draws the inscribed ball at its extreme), the legend range (recolours,
no analysis), the probe mode (thickness_probe.py) and the CSV / HTML files
(thickness_export.py)."""

import os
import threading

import FreeCADGui as Gui
import Part
from PySide2 import QtCore, QtWidgets

from cadmedial.app.thickness_object import analyse_shape, make_wall_thickness, region_line

from . import thickness_export
from .thickness_probe import ThicknessProbe, probe_message

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
        self.probe = None
        self._shape = None
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
        self.samples = QtWidgets.QSpinBox()
        self.samples.setRange(0, 50000000)
        self.samples.setSingleStep(10000)
        self.samples.setSpecialValueText("default")
        form.addRow("Medial axis samples", self.samples)
        self.run = QtWidgets.QPushButton("Analyse")
        self.run.clicked.connect(self.start)
        form.addRow(self.run)
        self.status = QtWidgets.QLabel("")
        self.status.setWordWrap(True)
        form.addRow(self.status)
        self.regions = QtWidgets.QListWidget()
        self.regions.itemClicked.connect(self._show_region)
        form.addRow(self.regions)
        # Colour range: recolours from the stored values (LegendMin / LegendMax), no analysis.
        self.legend_min = QtWidgets.QDoubleSpinBox()
        self.legend_max = QtWidgets.QDoubleSpinBox()
        for box in (self.legend_min, self.legend_max):
            box.setRange(0.0, 1e6)
            box.setDecimals(3)
            box.setSuffix(" mm")
            box.setEnabled(False)
            box.editingFinished.connect(self.apply_legend)
        form.addRow("Colours from", self.legend_min)
        form.addRow("Colours to", self.legend_max)
        self.probe_button = QtWidgets.QPushButton("Probe thickness")
        self.probe_button.setCheckable(True)
        self.probe_button.setEnabled(False)
        self.probe_button.setToolTip("Click the part: thickness by the sphere and the ray methods")
        self.probe_button.toggled.connect(self._toggle_probe)
        form.addRow(self.probe_button)
        self.probe_text = QtWidgets.QLabel("")
        self.probe_text.setWordWrap(True)
        form.addRow(self.probe_text)
        files = QtWidgets.QHBoxLayout()
        self.csv_button = QtWidgets.QPushButton("Export CSV")
        self.csv_button.setToolTip("Regions and faces, two CSV files")
        self.csv_button.clicked.connect(self._ask_csv)
        self.html_button = QtWidgets.QPushButton("HTML report")
        self.html_button.clicked.connect(self._ask_html)
        for button in (self.csv_button, self.html_button):
            button.setEnabled(False)
            files.addWidget(button)
        form.addRow(files)
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
        samples = self.samples.value() or None
        shape = Part.getShape(self.source).copy()
        self.status.setText("Analysing %s ..." % self.source.Label)
        self.run.setEnabled(False)
        self._outcome = None

        def work():  # the engine releases the GIL; no Qt or document access here
            try:
                self._outcome = ("ok", analyse_shape(shape, lo, hi, corners, samples))
            except Exception as error:
                self._outcome = ("error", error)

        self._settings = (lo, hi, corners, samples)
        self._analysed_shape = shape
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
        lo, hi, corners, samples = self._settings
        try:
            if self.obj is None:
                self.obj = make_wall_thickness(self.source, lo, hi, corners, samples, result=value)
            else:
                from cadmedial.app.thickness_object import parameters_of
                self.obj.MinWall, self.obj.MaxWall, self.obj.Corners = lo or 0.0, hi or 0.0, corners
                self.obj.Samples = int(samples or 0)
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
        self._shape = self._analysed_shape
        was_probing = self.probe is not None and self.probe.active
        self._close_probe()
        self.probe = ThicknessProbe(self._shape, value, self.source, self.obj, self._probed)
        from cadmedial.app.thickness_object import legend_range
        low, high = legend_range(self.obj)
        for box, x in ((self.legend_min, low), (self.legend_max, high)):
            box.blockSignals(True)
            box.setValue(x)
            box.blockSignals(False)
        for widget in (self.legend_min, self.legend_max, self.probe_button, self.csv_button,
                       self.html_button):
            widget.setEnabled(True)
        if was_probing:
            self._toggle_probe(True)

    def _show_region(self, item):
        g = (self.result.thin_regions + self.result.thick_regions)[self.regions.row(item)]
        Gui.Selection.clearSelection()
        for face in g["faces"]:
            Gui.Selection.addSelection(self.source, face)
        Gui.SendMsgToActiveView("ViewSelection")
        if self.probe is not None:  # the inscribed ball at the region's extreme
            self.probe.probe_at(g["at"])

    # Legend range
    def apply_legend(self):
        """Sets LegendMin / LegendMax from the boxes: the object recolours, nothing is analysed."""
        if self.obj is None:
            return
        low, high = self.legend_min.value(), self.legend_max.value()
        if not high > low:
            return
        self.obj.LegendMin, self.obj.LegendMax = low, high

    # Probe
    def _toggle_probe(self, on):
        if self.probe is None:
            return
        if on:
            view = Gui.ActiveDocument.ActiveView if Gui.ActiveDocument else None
            if view is None or not hasattr(view, "addEventCallbackPivy"):
                self.probe_button.setChecked(False)
                return
            self.probe.start(view)
            self.probe_text.setText("Click the part to read its thickness.")
        else:
            self.probe.stop()

    def _probed(self, hit):
        self.probe_text.setText(probe_message(hit) + "; ball radius %.4g mm" % hit["ball_radius"])

    def _close_probe(self):
        if self.probe is not None:
            self.probe.close()
            self.probe = None

    # Files
    def _base_name(self):
        return (self.source.Label or "part").replace(os.sep, "_")

    def _ask_csv(self):
        path = thickness_export.ask_path(self.form, "Export regions and faces (CSV)",
                                         self.source.Document, self._base_name() + "-regions.csv",
                                         "CSV (*.csv)")
        if path:
            self.export_csv(path)

    def export_csv(self, path):
        regions, faces = thickness_export.export_csv(self.result, path)
        self.status.setText("Wrote %s and %s" % (regions, faces))
        return regions, faces

    def _ask_html(self):
        path = thickness_export.ask_path(self.form, "HTML report", self.source.Document,
                                         self._base_name() + "-thickness.html", "HTML (*.html)")
        if path:
            self.export_html(path)

    def export_html(self, path):
        view = Gui.ActiveDocument.ActiveView if Gui.ActiveDocument else None
        thickness_export.export_html(self.result, path, self.source.Label, view)
        self.status.setText("Wrote %s" % path)
        return path

    def accept(self):
        self._close_probe()
        Gui.Control.closeDialog()
        return True

    def reject(self):
        self._close_probe()
        Gui.Control.closeDialog()
        return True

    def getStandardButtons(self):
        return int(QtWidgets.QDialogButtonBox.Close)
