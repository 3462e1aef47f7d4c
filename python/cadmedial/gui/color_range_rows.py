"""The Colours group of the task panel when it edits a MedialAxis: its colour range (AutoColorRange,
ColorRangeMin, ColorRangeMax), applied as soon as a box is left: the object recolours from its
radii, the engine does not run (app/color_range.py)."""

from PySide2 import QtWidgets

from cadmedial.app.color_range import color_range, quiet
from cadmedial.app.results import recolour


class ColorRangeRows:
    """``group``: the QGroupBox to put in the panel; binds its boxes to ``obj``."""

    def __init__(self, obj, form_layout):
        self.obj = obj
        self.group = QtWidgets.QGroupBox("Colours")
        rows = form_layout(self.group)
        self.automatic = QtWidgets.QCheckBox("From the radii")
        self.automatic.setToolTip("Colours span the smallest to the largest medial radius")
        self.low = QtWidgets.QDoubleSpinBox()
        self.high = QtWidgets.QDoubleSpinBox()
        for box, tip in ((self.low, "Radius of the first (violet) colour; smaller radii get it too"),
                         (self.high, "Radius of the last (yellow) colour; larger radii get it too")):
            box.setRange(0.0, 1e6)
            box.setDecimals(4)
            box.setSuffix(" mm")
            box.setMinimumWidth(60)
            box.setSizePolicy(QtWidgets.QSizePolicy.Expanding, QtWidgets.QSizePolicy.Fixed)
            box.setToolTip(tip)
            box.editingFinished.connect(self.apply)
        rows.addRow(self.automatic)
        rows.addRow("From", self.low)
        rows.addRow("To", self.high)
        self.load()
        self.automatic.toggled.connect(self._automatic_toggled)

    def load(self):
        """The boxes from the object (the range in use: the radii's when automatic)."""
        low, high = color_range(self.obj)
        self.automatic.blockSignals(True)
        self.automatic.setChecked(bool(self.obj.AutoColorRange))
        self.automatic.blockSignals(False)
        self.low.setValue(low)
        self.high.setValue(high)
        self._enable()

    def _enable(self):
        for box in (self.low, self.high):
            box.setEnabled(not self.automatic.isChecked())

    def _automatic_toggled(self, on):
        if on:
            self.obj.AutoColorRange = True
            self.load()
        else:
            self._enable()
            self.apply()

    def apply(self):
        """Sets the object's range from the boxes, when it is not empty and differs, and
        recolours once."""
        if self.automatic.isChecked():
            return
        low, high = self.low.value(), self.high.value()
        obj = self.obj
        unchanged = (not obj.AutoColorRange
                     and (obj.ColorRangeMin.Value, obj.ColorRangeMax.Value) == (low, high))
        if not high > low or unchanged:
            return
        with quiet(obj):  # three properties, one recolour
            obj.AutoColorRange = False
            obj.ColorRangeMin, obj.ColorRangeMax = low, high
        recolour(obj)
