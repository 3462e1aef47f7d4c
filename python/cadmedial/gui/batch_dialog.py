"""The "Batch over a folder" dialog: inputs, output folder and limits, Start / Stop, a progress
bar of the parts done and failed, then the summary as a sortable table (double-click: open the
part in FreeCAD). The batch itself runs in batch_runner's thread; this file only shows it."""

import os

from PySide2 import QtCore, QtGui, QtWidgets

from cadmedial.batch.discover import CAD_SUFFIXES, LIST_SUFFIXES

from .batch_runner import BatchRunner
from .batch_table import SortProxy, SummaryModel

MAX_COLUMN_WIDTH = 260  # pixels; a cell's whole text is in its tooltip (parts, messages)
OUTPUT_NAME = "medial_axis"  # the default output folder, beside (in) the input folder
_FILTER = "CAD files and lists (%s)" % " ".join("*" + s for s in CAD_SUFFIXES + LIST_SUFFIXES)


def default_output(inputs):
    """<folder>/medial_axis for a folder, else beside the first file."""
    if not inputs:
        return ""
    first = os.path.abspath(inputs[0])
    return os.path.join(first if os.path.isdir(first) else os.path.dirname(first), OUTPUT_NAME)


def _spin(kind, low, high, value, special=None, decimals=None, suffix=""):
    box = kind()
    box.setRange(low, high)
    if decimals is not None:
        box.setDecimals(decimals)
    box.setValue(value)
    if special:
        box.setSpecialValueText(special)  # shown at the minimum: 0 means none
    box.setSuffix(suffix)
    return box


class BatchDialog(QtWidgets.QDialog):
    def __init__(self, parent=None):
        super().__init__(parent)
        self.setWindowTitle("Medial axis batch")
        self.runner = None
        self.result = None
        self._auto_output = True
        form = QtWidgets.QFormLayout()
        self.inputs = QtWidgets.QLineEdit()
        self.inputs.setPlaceholderText("a folder, or files separated by ;")
        self.inputs.textChanged.connect(self._inputs_changed)
        pick_folder, pick_files = QtWidgets.QPushButton("Folder..."), QtWidgets.QPushButton("Files...")
        pick_folder.clicked.connect(self._choose_folder)
        pick_files.clicked.connect(self._choose_files)
        form.addRow("Inputs", self._row(self.inputs, pick_folder, pick_files))
        self.output = QtWidgets.QLineEdit()
        self.output.textEdited.connect(lambda _text: setattr(self, "_auto_output", False))
        pick_output = QtWidgets.QPushButton("...")
        pick_output.clicked.connect(self._choose_output)
        form.addRow("Output folder", self._row(self.output, pick_output))
        self.jobs = _spin(QtWidgets.QSpinBox, 1, 256, os.cpu_count() or 1)
        form.addRow("Jobs (local workers)", self.jobs)
        self.timeout = _spin(QtWidgets.QDoubleSpinBox, 0, 1e7, 3600, "no limit", 0, " s")
        form.addRow("Timeout per part", self.timeout)
        self.memory = _spin(QtWidgets.QDoubleSpinBox, 0, 1e4, 8, "no limit", 1, " GB")
        form.addRow("Memory per part", self.memory)
        self.samples = _spin(QtWidgets.QSpinBox, 0, 50000000, 0, "automatic")
        self.samples.setSingleStep(1000)
        form.addRow("Samples", self.samples)
        self.thickness = QtWidgets.QCheckBox("Wall thickness, minimum")
        self.min_wall = _spin(QtWidgets.QDoubleSpinBox, 0, 1e6, 1.0, None, 3, " mm")
        self.min_wall.setEnabled(False)
        self.thickness.toggled.connect(self.min_wall.setEnabled)
        form.addRow(self.thickness, self.min_wall)
        self.scheduler = QtWidgets.QLineEdit()
        self.scheduler.setPlaceholderText("empty: a local cluster (tcp://host:8786 for a running one)")
        form.addRow("Dask scheduler", self.scheduler)

        self.bar = QtWidgets.QProgressBar()
        self.bar.setFormat("%v / %m parts")
        self.status = QtWidgets.QLabel("")
        self.status.setWordWrap(True)
        self.status.setTextInteractionFlags(QtCore.Qt.TextSelectableByMouse)
        self.model = SummaryModel(self)
        self.proxy = SortProxy(self)
        self.proxy.setSourceModel(self.model)
        self.table = QtWidgets.QTableView()
        self.table.setModel(self.proxy)
        self.table.setSortingEnabled(True)
        self.table.setSelectionBehavior(QtWidgets.QAbstractItemView.SelectRows)
        self.table.setEditTriggers(QtWidgets.QAbstractItemView.NoEditTriggers)
        self.table.horizontalHeader().setStretchLastSection(True)
        self.table.setTextElideMode(QtCore.Qt.ElideLeft)  # the reason is at a message's end
        self.table.doubleClicked.connect(self._open_row)

        self.start_button = QtWidgets.QPushButton("Start")
        self.stop_button = QtWidgets.QPushButton("Stop")
        self.summary_button = QtWidgets.QPushButton("Open summary")
        close = QtWidgets.QPushButton("Close")
        self.start_button.clicked.connect(self.start)
        self.stop_button.clicked.connect(self.stop)
        self.summary_button.clicked.connect(self.open_summary)
        close.clicked.connect(self.close)
        buttons = QtWidgets.QHBoxLayout()
        for b in (self.start_button, self.stop_button, self.summary_button):
            buttons.addWidget(b)
        buttons.addStretch(1)
        buttons.addWidget(close)
        layout = QtWidgets.QVBoxLayout(self)
        layout.addLayout(form)
        layout.addWidget(self.bar)
        layout.addWidget(self.status)
        layout.addWidget(self.table, 1)
        layout.addLayout(buttons)
        self.resize(1100, 700)
        self._set_running(False)

    @staticmethod
    def _row(*widgets):
        w = QtWidgets.QWidget()
        h = QtWidgets.QHBoxLayout(w)
        h.setContentsMargins(0, 0, 0, 0)
        for i, widget in enumerate(widgets):
            h.addWidget(widget, 1 if i == 0 else 0)
        return w

    def input_paths(self):
        return [p.strip() for p in self.inputs.text().split(";") if p.strip()]

    def options(self):
        """The keyword arguments of cadmedial.batch this dialog stands for."""
        opts = {"jobs": self.jobs.value(), "timeout": self.timeout.value(), "memory": self.memory.value()}
        if self.samples.value():
            opts["samples"] = self.samples.value()
        if self.thickness.isChecked():
            opts["thickness"] = {"min": self.min_wall.value() or None, "max": None}
        if self.scheduler.text().strip():
            opts["scheduler"] = self.scheduler.text().strip()
            del opts["jobs"]
        return opts

    def start(self):
        inputs, out_dir = self.input_paths(), self.output.text().strip()
        if not inputs or not out_dir:
            self._say("Choose the inputs and the output folder first.", error=True)
            return
        self.result = None
        self.model.set_records([])
        self.bar.setRange(0, 0)  # busy until the parts are counted
        self._say("Starting: finding the parts and the Dask workers...")
        self.runner = BatchRunner(inputs, out_dir, self.options(), self)
        self.runner.progressed.connect(self._progressed, QtCore.Qt.QueuedConnection)
        self.runner.finished.connect(self._finished, QtCore.Qt.QueuedConnection)
        self._set_running(True)
        self.runner.start()

    def stop(self):
        if self.runner is not None:
            self.runner.stop()
            self.stop_button.setEnabled(False)
            self._say("Stopping: the parts running are cancelled, the finished ones kept...")

    @property
    def running(self):
        return self.runner is not None

    def _progressed(self, update):
        self.bar.setRange(0, max(1, update.total))
        self.bar.setValue(update.done)
        if update.record is not None:
            self.model.add_record(update.record)
        text = "%d of %d parts done, %d failed" % (update.done, update.total, update.failed)
        self._say(text + (": " + update.message if update.message else ""))

    def _finished(self, result, error):
        self.runner = None
        self._set_running(False)
        if result is None:
            self.bar.setRange(0, 1)
            self._say(error, error=True)
            return
        self.result = result
        self.model.set_records(result.records)
        self.table.resizeColumnsToContents()
        for column in range(self.model.columnCount()):  # a long message must not hide the numbers
            self.table.setColumnWidth(column, min(self.table.columnWidth(column), MAX_COLUMN_WIDTH))
        self.bar.setRange(0, max(1, len(result.records)))
        self.bar.setValue(sum(1 for r in result.records if r["status"] != "stopped"))
        self._say(result.text.replace("\n", "<br>"))

    def _say(self, text, error=False):
        self.status.setText('<span style="color:#c02020">%s</span>' % text if error else text)

    def _set_running(self, running):
        self.start_button.setEnabled(not running)
        self.stop_button.setEnabled(running)
        self.summary_button.setEnabled(not running and self._summary_file() is not None)

    def _summary_file(self):
        path = os.path.join(self.output.text().strip(), "summary.csv")
        return path if self.output.text().strip() and os.path.isfile(path) else None

    def open_summary(self):
        path = self._summary_file()
        if path:
            QtGui.QDesktopServices.openUrl(QtCore.QUrl.fromLocalFile(path))

    def _open_row(self, index):
        from .batch_open import open_part
        record = self.model.record(self.proxy.mapToSource(index).row())
        try:
            open_part(record, self.output.text().strip(), "ply")  # the format the dialog asks for
        except Exception as error:
            self._say("%s: %s" % (record.get("input"), error), error=True)

    def _inputs_changed(self, _text):
        if self._auto_output:
            self.output.setText(default_output(self.input_paths()))
        self._set_running(self.running)

    def _choose_folder(self):
        folder = QtWidgets.QFileDialog.getExistingDirectory(self, "Folder of parts", self._start_folder())
        if folder:
            self.inputs.setText(folder)

    def _choose_files(self):
        files, _ = QtWidgets.QFileDialog.getOpenFileNames(self, "Parts", self._start_folder(), _FILTER)
        if files:
            self.inputs.setText("; ".join(files))

    def _choose_output(self):
        folder = QtWidgets.QFileDialog.getExistingDirectory(self, "Output folder", self.output.text())
        if folder:
            self._auto_output = False
            self.output.setText(folder)

    def _start_folder(self):
        paths = self.input_paths()
        return os.path.dirname(os.path.abspath(paths[0])) if paths else os.path.expanduser("~")

    def closeEvent(self, event):
        # Closing while it runs stops the batch; what finished is kept (and a rerun resumes).
        if self.runner is not None:
            self.runner.stop()
        super().closeEvent(event)
