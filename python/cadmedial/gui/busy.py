"""Long work started from the GUI thread (a recompute from the property view, the Part shape)
runs in a thread while a modal progress dialog with Stop keeps the GUI drawn and answering.
Plugged into cadmedial.app as ``registry.background_runner`` (app stays free of Qt)."""

import time

import FreeCADGui as Gui
from PySide2 import QtCore, QtWidgets

from .worker import Job

# Show the dialog only for work that lasts: a 50 ms recompute should not flash a window.
SHOW_AFTER_MS = 400


def run_with_progress(text, work):
    """Runs work(progress) in a thread and returns its value (raises its error). The GUI thread
    meanwhile handles events; the dialog's Stop cancels (cadmedial.Cancelled is raised)."""
    job = Job(work)
    job.start()
    dialog = QtWidgets.QProgressDialog(text, "Stop", 0, 1000, Gui.getMainWindow())
    dialog.setWindowTitle("Medial axis")
    dialog.setWindowModality(QtCore.Qt.ApplicationModal)  # no second recompute meanwhile
    dialog.setMinimumDuration(SHOW_AFTER_MS)
    dialog.setAutoClose(False)
    dialog.setAutoReset(False)
    dialog.canceled.connect(job.cancel)
    loop = QtCore.QEventLoop()
    timer = QtCore.QTimer()
    timer.setInterval(20)

    def poll():
        if job.done:
            loop.quit()
            return
        stage, fraction = job.progress
        dialog.setValue(min(999, int(1000 * fraction)))
        if stage:
            dialog.setLabelText("%s: %s" % (text, stage))

    timer.timeout.connect(poll)
    timer.start()
    try:
        if not job.done:
            loop.exec_()
    finally:
        timer.stop()
        dialog.close()
        dialog.deleteLater()
    while not job.done:  # the loop quits only when done; this is a guard, not a wait
        time.sleep(0.01)
    if job.error is not None:
        raise job.error
    return job.value


def breathe():
    """Lets the GUI draw and run its timers, not take user input (called inside a recompute)."""
    QtWidgets.QApplication.processEvents(QtCore.QEventLoop.ExcludeUserInputEvents, 20)
