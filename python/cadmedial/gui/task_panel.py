"""The task panel of the Medial Axis command: parameters, a live estimate of the sample count,
and a progress bar with Stop while the engine works in a background thread."""

import FreeCAD as App
import FreeCADGui as Gui
import Part
from PySide2 import QtCore, QtGui, QtWidgets

import cadmedial
from cadmedial.app import make_medial_axis
from cadmedial.app.compact_mesh import DEFAULT_PERCENT, MAX_PERCENT, STEP, simplify_of
from cadmedial.app.medial_axis import min_feature_of

from .color_range_rows import ColorRangeRows
from .icons import icon_path
from .worker import ComputeJob, Job

# The panel on screen, for tests and macros (None when closed).
active_panel = None
MODES = [("Automatic", "automatic"), ("Samples", "samples"), ("Spacing", "spacing")]
MAX_SAMPLES = 20_000_000  # the engine's limit
ESTIMATE_DELAY_MS = 300


def _wrapping(text):
    label = QtWidgets.QLabel(text)
    label.setWordWrap(True)
    label.setMinimumWidth(0)
    label.setSizePolicy(QtWidgets.QSizePolicy.Ignored, QtWidgets.QSizePolicy.Preferred)
    return label


def _form_layout(parent):
    rows = QtWidgets.QFormLayout(parent)
    rows.setRowWrapPolicy(QtWidgets.QFormLayout.WrapLongRows)
    rows.setFieldGrowthPolicy(QtWidgets.QFormLayout.AllNonFixedFieldsGrow)
    return rows


class TaskPanelMedialAxis:
    """Creates one MedialAxis per source (edit=None), or edits the parameters of `edit`."""

    def __init__(self, sources, edit=None):
        global active_panel
        self.sources = list(sources)
        self.edit = edit
        self.job = None
        self.shapes = [cadmedial.read_shape(Part.getShape(s)) for s in self.sources]
        self.estimate = None
        self.estimate_stale = False
        self.close_when_stopped = False
        self.estimate_timer = QtCore.QTimer()
        self.estimate_timer.setSingleShot(True)
        self.estimate_timer.setInterval(ESTIMATE_DELAY_MS)
        self.estimate_timer.timeout.connect(self._start_estimate)
        self.estimate_poll = QtCore.QTimer()
        self.estimate_poll.setInterval(30)
        self.estimate_poll.timeout.connect(self._poll_estimate)
        self.form = self._build_form()
        self.timer = QtCore.QTimer()
        self.timer.setInterval(100)
        self.timer.timeout.connect(self._poll)
        self._load_parameters()
        active_panel = self

    # -- form -------------------------------------------------------------------------------
    def _build_form(self):
        # Sized for FreeCAD's default Combo View (about 240 px) and 200 % scaling: one column,
        # short labels, texts that wrap, every button on a row of its own.
        form = QtWidgets.QWidget()
        form.setWindowTitle("Medial axis")
        form.setWindowIcon(QtGui.QIcon(icon_path("MedialAxis_Create.svg")))
        form.setMinimumWidth(0)
        layout = QtWidgets.QVBoxLayout(form)
        names = ", ".join(s.Label for s in self.sources)
        layout.addWidget(_wrapping("<b>Solids:</b> %s" % names))
        # Progress and Stop first: seen without scrolling, even at 200 % scaling.
        self.progress = QtWidgets.QProgressBar()
        self.progress.setRange(0, 1000)
        self.progress.setTextVisible(False)
        layout.addWidget(self.progress)
        self.stop = QtWidgets.QPushButton("Stop")
        self.stop.setEnabled(False)
        self.stop.clicked.connect(self.cancel)
        layout.addWidget(self.stop)
        self.stage = _wrapping("")
        layout.addWidget(self.stage)

        density = QtWidgets.QGroupBox("Sampling")
        rows = _form_layout(density)
        self.mode = QtWidgets.QComboBox()
        for text, key in MODES:
            self.mode.addItem(text, key)
        self.mode.setToolTip("Automatic: as dense as the part needs. Samples: about this many "
                             "boundary samples. Spacing: this distance between samples.")
        self.samples = QtWidgets.QSpinBox()
        self.samples.setRange(100, MAX_SAMPLES)
        self.samples.setSingleStep(1000)
        self.samples.setGroupSeparatorShown(True)
        self.samples.setToolTip("Approximate number of boundary samples of each source")
        self.spacing = QtWidgets.QDoubleSpinBox()
        self.spacing.setRange(1e-4, 1e6)
        self.spacing.setDecimals(4)
        self.spacing.setSuffix(" mm")
        self.spacing.setToolTip("Distance between boundary samples")
        self.min_feature = QtWidgets.QDoubleSpinBox()
        self.min_feature.setRange(0.0, 1e6)
        self.min_feature.setDecimals(4)
        self.min_feature.setSuffix(" mm")
        self.min_feature.setSpecialValueText("none")  # 0: no minimum
        self.min_feature.setToolTip("Walls thinner than this are not sampled finer than it needs "
                                    "(a warning names the thinnest and where); none: no minimum")
        for box in (self.mode, self.samples, self.spacing, self.min_feature):
            box.setMinimumWidth(60)
            box.setSizePolicy(QtWidgets.QSizePolicy.Expanding, QtWidgets.QSizePolicy.Fixed)
        self.preview = _wrapping("")
        rows.addRow("Density", self.mode)
        rows.addRow("Samples", self.samples)
        rows.addRow("Spacing", self.spacing)
        rows.addRow("Min feature", self.min_feature)
        rows.addRow(self.preview)
        self.refine = QtWidgets.QCheckBox("Refine where needed")
        self.refine.setToolTip("Sample finer where the axis's topology is wrong: where a solid's medial axis has holes or extra loops (its Euler "
                               "characteristic is not the solid's), sample it again with 2.5 "
                               "times the samples, at most twice")
        rows.addRow(self.refine)
        layout.addWidget(density)

        selection = QtWidgets.QGroupBox("Medial faces")
        rows = _form_layout(selection)
        self.theta = QtWidgets.QDoubleSpinBox()
        self.theta.setRange(0.1, 89.9)
        self.theta.setSuffix(" °")
        self.theta.setToolTip("Angle condition: keep a Voronoi facet whose dual Delaunay edge "
                              "subtends more than this angle (paper, section 3)")
        self.rho = QtWidgets.QDoubleSpinBox()
        self.rho.setRange(0.01, 1000.0)
        self.rho.setToolTip("Ratio condition: keep a facet whose circumradius exceeds rho times "
                            "its dual edge's length (paper, section 3)")
        for box in (self.theta, self.rho):
            box.setMinimumWidth(60)
        rows.addRow("Theta", self.theta)
        rows.addRow("Rho", self.rho)
        self.simplify = QtWidgets.QDoubleSpinBox()
        self.simplify.setRange(0.0, MAX_PERCENT)
        self.simplify.setSingleStep(STEP)
        self.simplify.setDecimals(2)
        self.simplify.setSuffix(" %")
        self.simplify.setSpecialValueText("full axis")  # 0: no simplification
        self.simplify.setMinimumWidth(60)
        self.simplify.setToolTip("Compact mesh: every ball of the full axis within this share of "
                                 "the part's diagonal (centre plus radius); full axis: every face")
        rows.addRow("Simplify", self.simplify)
        layout.addWidget(selection)

        if self.edit is not None:  # a result to recolour: its colour range
            self.colors = ColorRangeRows(self.edit, _form_layout)
            layout.addWidget(self.colors.group)

        self.make_shape = QtWidgets.QCheckBox("Also make a Part shape")
        self.make_shape.setToolTip("A Part object of planar faces, one per medial polygon")
        layout.addWidget(self.make_shape)
        self.make_shape.setVisible(self.edit is None)

        layout.addStretch(1)

        for widget in (self.samples, self.spacing, self.min_feature):
            widget.valueChanged.connect(self.update_preview)
        self.mode.currentIndexChanged.connect(self._mode_changed)
        return form

    def _load_parameters(self):
        source = self.edit
        spacing = source.Spacing.Value if source is not None else 0.0
        samples = source.Samples if source is not None else 0
        self.theta.setValue(source.Theta if source is not None else 5.0)
        self.rho.setValue(source.Rho if source is not None else 8.0)
        self.refine.setChecked(bool(source.Refine) if source is not None else True)
        self.min_feature.setValue(min_feature_of(source) if source is not None else 0.0)
        self.simplify.setValue(simplify_of(source) if source is not None else DEFAULT_PERCENT)
        self.samples.setValue(samples or 20000)
        if spacing > 0:
            self.spacing.setValue(spacing)
            self.choose_mode("spacing")
        elif samples > 0:
            self.choose_mode("samples")
        else:
            self.choose_mode("automatic")
        self._mode_changed()

    def choose_mode(self, key):
        """Density mode: "automatic", "samples" or "spacing"."""
        self.mode.setCurrentIndex([k for _text, k in MODES].index(key))

    def mode_key(self):
        return self.mode.currentData()

    def _mode_changed(self, *_):
        running = self.job is not None
        self.samples.setEnabled(self.mode_key() == "samples" and not running)
        self.spacing.setEnabled(self.mode_key() == "spacing" and not running)
        self.update_preview()

    def parameters(self):
        """Keyword arguments of cadmedial.compute from the form (Automatic gives neither
        spacing nor samples: the engine picks the density)."""
        key = self.mode_key()
        return {"spacing": self.spacing.value() if key == "spacing" else None,
                "samples": self.samples.value() if key == "samples" else None,
                "theta": self.theta.value(), "rho": self.rho.value(),
                "refine": self.refine.isChecked(),
                "min_feature": self.min_feature.value() or None,
                "simplify": self.simplify.value()}

    def update_preview(self, *_):
        """Asks for a new estimate, EstimateDelay ms after the last change: typing 3000000 key
        by key makes one estimate, and it runs in a thread (the engine plans without the GIL)."""
        self.preview.setText("estimating…")
        self.estimate_timer.start()

    def _start_estimate(self):
        if self.estimate is not None and not self.estimate.done:
            self.estimate_stale = True  # the one running is for older values: run again after
            return
        p = self.parameters()
        shapes = list(self.shapes)
        self.estimate_stale = False
        self.estimate = Job(lambda progress: [
            cadmedial.plan_sampling(s, spacing=p["spacing"], samples=p["samples"],
                                    min_feature=p["min_feature"]) for s in shapes])
        self.estimate.mode = self.mode_key()
        self.estimate.start()
        self.estimate_poll.start()

    def _poll_estimate(self):
        job = self.estimate
        if job is None or not job.done:
            return
        self.estimate_poll.stop()
        if self.estimate_stale:
            self._start_estimate()
            return
        if job.error is not None:
            self.preview.setText("<span style='color:#b00'>%s</span>" % job.error)
            return
        plans = job.value
        total = sum(plan.estimated_samples for plan in plans)
        low = min((plan.spacing for plan in plans), default=0.0)
        high = max((plan.spacing for plan in plans), default=0.0)
        spacing = "%.4g mm" % low if abs(high - low) <= 1e-9 * high else "%.4g–%.4g mm" % (low, high)
        self.preview.setText("≈ {:,} samples, spacing {}".format(total, spacing))
        if job.mode != "spacing" and high > 0:
            # The spacing box shows the spacing the other modes give, never a stale one.
            self.spacing.blockSignals(True)
            self.spacing.setValue(high)
            self.spacing.blockSignals(False)

    def estimate_idle(self):
        """True when no estimate is pending or running (for tests)."""
        return (not self.estimate_timer.isActive()
                and (self.estimate is None or (self.estimate.done and not self.estimate_poll.isActive())))

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
        self.stage.setText("")
        self._set_running(True)
        self.job.start()
        self.timer.start()
        return False  # the dialog closes itself when the job is done

    def reject(self):
        if self.job is not None:  # one Cancel: stop, and close once the engine has stopped
            self.close_when_stopped = True
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
        for widget in (self.mode, self.min_feature, self.theta, self.rho, self.refine,
                       self.simplify, self.make_shape):
            widget.setEnabled(not running)
        self.samples.setEnabled(False)
        self.spacing.setEnabled(False)
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
        if self.close_when_stopped:
            for stored in job.results:
                stored.discard()
            self._close()
            return
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
        obj.MinFeature = p["min_feature"] or 0.0
        obj.Simplify = p["simplify"]
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
        self.estimate_timer.stop()
        self.estimate_poll.stop()
        if self.edit is not None:
            Gui.ActiveDocument.resetEdit()
        else:
            Gui.Control.closeDialog()
