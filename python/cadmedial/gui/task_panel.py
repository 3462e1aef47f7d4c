"""The task panel of the Medial Axis command: parameters, a live estimate of the sample count,
and a progress bar with Stop while the engine works in a background thread."""

import FreeCAD as App
import FreeCADGui as Gui
import Part
from PySide2 import QtCore, QtGui, QtWidgets

import cadmedial
from cadmedial.app import make_medial_axis

from .icons import icon_path
from .worker import ComputeJob

# The panel on screen, for tests and macros (None when closed).
active_panel = None


class TaskPanelMedialAxis:
    """Creates one MedialAxis per source (edit=None), or edits the parameters of `edit`."""

    def __init__(self, sources, edit=None):
        global active_panel
        self.sources = list(sources)
        self.edit = edit
        self.job = None
        self.shapes = [cadmedial.read_shape(Part.getShape(s)) for s in self.sources]
        self.form = self._build_form()
        self.timer = QtCore.QTimer()
        self.timer.setInterval(100)
        self.timer.timeout.connect(self._poll)
        self._load_parameters()
        self.update_preview()
        active_panel = self

    # -- form -------------------------------------------------------------------------------
    def _build_form(self):
        form = QtWidgets.QWidget()
        form.setWindowTitle("Medial axis")
        form.setWindowIcon(QtGui.QIcon(icon_path("MedialAxis_Create.svg")))
        layout = QtWidgets.QVBoxLayout(form)
        names = ", ".join(s.Label for s in self.sources)
        layout.addWidget(QtWidgets.QLabel("<b>Solids:</b> %s" % names))

        density = QtWidgets.QGroupBox("Boundary sampling")
        grid = QtWidgets.QGridLayout(density)
        self.by_samples = QtWidgets.QRadioButton("Samples")
        self.by_spacing = QtWidgets.QRadioButton("Spacing")
        self.samples = QtWidgets.QSpinBox()
        self.samples.setRange(100, 50_000_000)
        self.samples.setSingleStep(1000)
        self.samples.setGroupSeparatorShown(True)
        self.samples.setToolTip("Approximate number of boundary samples of each source")
        self.spacing = QtWidgets.QDoubleSpinBox()
        self.spacing.setRange(1e-4, 1e6)
        self.spacing.setDecimals(4)
        self.spacing.setSuffix(" mm")
        self.spacing.setToolTip("Distance between boundary samples")
        self.preview = QtWidgets.QLabel()
        grid.addWidget(self.by_samples, 0, 0)
        grid.addWidget(self.samples, 0, 1)
        grid.addWidget(self.by_spacing, 1, 0)
        grid.addWidget(self.spacing, 1, 1)
        grid.addWidget(self.preview, 2, 0, 1, 2)
        self.refine = QtWidgets.QCheckBox("Sample finer where the axis's topology is wrong")
        self.refine.setToolTip("Where a solid's medial axis has holes or extra loops (its Euler "
                               "characteristic is not the solid's), sample it again with 2.5 "
                               "times the samples, at most twice")
        grid.addWidget(self.refine, 3, 0, 1, 2)
        layout.addWidget(density)

        selection = QtWidgets.QGroupBox("Selection of medial faces")
        grid = QtWidgets.QGridLayout(selection)
        self.theta = QtWidgets.QDoubleSpinBox()
        self.theta.setRange(0.1, 89.9)
        self.theta.setSuffix(" °")
        self.theta.setToolTip("Angle condition: keep a Voronoi facet whose dual Delaunay edge "
                              "subtends more than this angle (paper, section 3)")
        self.rho = QtWidgets.QDoubleSpinBox()
        self.rho.setRange(0.01, 1000.0)
        self.rho.setToolTip("Ratio condition: keep a facet whose circumradius exceeds rho times "
                            "its dual edge's length (paper, section 3)")
        grid.addWidget(QtWidgets.QLabel("Theta"), 0, 0)
        grid.addWidget(self.theta, 0, 1)
        grid.addWidget(QtWidgets.QLabel("Rho"), 1, 0)
        grid.addWidget(self.rho, 1, 1)
        layout.addWidget(selection)

        self.make_shape = QtWidgets.QCheckBox("Also make a Part shape of planar faces")
        layout.addWidget(self.make_shape)
        self.make_shape.setVisible(self.edit is None)

        run = QtWidgets.QHBoxLayout()
        self.progress = QtWidgets.QProgressBar()
        self.progress.setRange(0, 1000)
        self.progress.setTextVisible(False)
        self.stop = QtWidgets.QPushButton("Stop")
        self.stop.setEnabled(False)
        self.stop.clicked.connect(self.cancel)
        run.addWidget(self.progress)
        run.addWidget(self.stop)
        layout.addLayout(run)
        self.stage = QtWidgets.QLabel()
        self.stage.setWordWrap(True)
        layout.addWidget(self.stage)
        layout.addStretch(1)

        for widget in (self.samples, self.spacing):
            widget.valueChanged.connect(self.update_preview)
        self.by_samples.toggled.connect(self._mode_changed)
        return form

    def _load_parameters(self):
        source = self.edit
        spacing = source.Spacing.Value if source is not None else 0.0
        samples = source.Samples if source is not None else 0
        self.theta.setValue(source.Theta if source is not None else 5.0)
        self.rho.setValue(source.Rho if source is not None else 8.0)
        self.refine.setChecked(bool(source.Refine) if source is not None else True)
        self.samples.setValue(samples or 20000)
        if spacing > 0:
            self.spacing.setValue(spacing)
            self.by_spacing.setChecked(True)
        else:
            self.spacing.setValue(self._planned_spacing(None, self.samples.value()))
            self.by_samples.setChecked(True)
        self._mode_changed()

    def _mode_changed(self, *_):
        self.samples.setEnabled(self.by_samples.isChecked())
        self.spacing.setEnabled(self.by_spacing.isChecked())
        self.update_preview()

    def parameters(self):
        """Keyword arguments of cadmedial.compute from the form."""
        by_spacing = self.by_spacing.isChecked()
        return {"spacing": self.spacing.value() if by_spacing else None,
                "samples": None if by_spacing else self.samples.value(),
                "theta": self.theta.value(), "rho": self.rho.value(),
                "refine": self.refine.isChecked()}

    def _planned_spacing(self, spacing, samples):
        plans = [cadmedial.plan_sampling(s, spacing=spacing, samples=samples) for s in self.shapes]
        return max(p.spacing for p in plans) if plans else 1.0

    def update_preview(self, *_):
        p = self.parameters()
        try:
            plans = [cadmedial.plan_sampling(s, spacing=p["spacing"], samples=p["samples"])
                     for s in self.shapes]
        except cadmedial.Error as error:
            self.preview.setText("<span style='color:#b00'>%s</span>" % error)
            return
        total = sum(plan.estimated_samples for plan in plans)
        low = min(plan.spacing for plan in plans)
        high = max(plan.spacing for plan in plans)
        spacing = "%.4g mm" % low if abs(high - low) <= 1e-9 * high else "%.4g–%.4g mm" % (low, high)
        self.preview.setText("≈ {:,} samples, spacing {}".format(total, spacing))

    # -- FreeCAD task dialog interface ------------------------------------------------------
    def getStandardButtons(self):
        return int(QtWidgets.QDialogButtonBox.Ok | QtWidgets.QDialogButtonBox.Cancel)

    def accept(self):
        if self.job is not None:
            return False  # already computing
        try:
            p = self.parameters()
            cadmedial._core.check_params(p["spacing"] or 0.0, p["samples"] or 0, p["theta"], p["rho"])
        except cadmedial.Error as error:
            self._show_error(error)
            return False
        if self.edit is not None:
            return self._apply_edit(p)
        self.job = ComputeJob(self.shapes, p)
        self._set_running(True)
        self.job.start()
        self.timer.start()
        return False  # the dialog closes itself when the job is done

    def reject(self):
        if self.job is not None:
            self.cancel()
            return False
        self._close()
        return True

    def cancel(self):
        if self.job is not None:
            self.job.cancel()
            self.stage.setText("Stopping…")

    # -- running ----------------------------------------------------------------------------
    def _set_running(self, running):
        for widget in (self.samples, self.spacing, self.by_samples, self.by_spacing, self.theta,
                       self.rho, self.refine, self.make_shape):
            widget.setEnabled(not running)
        if not running:
            self._mode_changed()
        self.stop.setEnabled(running)
        self.progress.setValue(0)

    def _poll(self):
        job = self.job
        index, stage, _fraction = job.progress
        self.progress.setValue(int(1000 * job.overall_fraction))
        if stage:
            self.stage.setText("%s: %s" % (self.sources[index].Label, stage))
        if not job.done:
            return
        self.timer.stop()
        self.job = None
        self._set_running(False)
        if job.error is not None:
            if isinstance(job.error, cadmedial.Cancelled):
                self.stage.setText("Stopped: nothing was added.")
            else:
                self._show_error(job.error)
            return
        self._add_objects(job.results, job.params)

    def _add_objects(self, results, params):
        try:
            doc = self.sources[0].Document
        except Exception as error:  # the source was deleted while the engine worked
            self._show_error(error)
            return
        doc.openTransaction("Medial axis")
        try:
            for source, result in zip(self.sources, results):
                make_medial_axis(source, result=result, shape=self.make_shape.isChecked(), **params)
                if source.ViewObject is not None and "Wireframe" in source.ViewObject.listDisplayModes():
                    source.ViewObject.DisplayMode = "Wireframe"  # the medial axis is inside it
        except Exception as error:
            doc.abortTransaction()
            self._show_error(error)
            return
        doc.commitTransaction()
        self._close()

    def _apply_edit(self, p):
        obj = self.edit
        obj.Spacing = p["spacing"] or 0.0
        obj.Samples = p["samples"] or 0
        obj.Theta = p["theta"]
        obj.Rho = p["rho"]
        obj.Refine = p["refine"]
        obj.Document.recompute()
        if obj.Status != "ok":
            self._show_error(obj.Status)
            return False
        self._close()
        return True

    def _show_error(self, error):
        App.Console.PrintError("Medial axis: %s\n" % error)
        self.stage.setText("<span style='color:#b00'>%s</span>" % error)

    def _close(self):
        global active_panel
        active_panel = None
        if self.edit is not None:
            Gui.ActiveDocument.resetEdit()
        else:
            Gui.Control.closeDialog()
