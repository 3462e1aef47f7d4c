# Runs inside the FreeCAD GUI under Xvfb (see test_batch_gui.py): writes three parts into a folder
# (two solids made with Part, one file that is not STEP), opens the batch dialog with its command,
# runs the batch from the Start button while a 10 ms QTimer measures the longest stall of the GUI,
# then reads the summary table, double-clicks a row and saves a picture of the dialog; last, a
# batch of two slow parts stopped a few seconds in.
# Writes $CADMEDIAL_GUI_OUT/batch.json and batch.png; exits with os._exit.
import multiprocessing.spawn
import os
import shutil
import subprocess
import time

import FreeCAD as App
import FreeCADGui as Gui
import Part
from PySide2 import QtCore, QtWidgets
import sys  # noqa: E402
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # gui_heartbeat beside this script
from gui_heartbeat import Heartbeat, run_and_report  # noqa: E402

OUT = os.environ["CADMEDIAL_GUI_OUT"]
EXAMPLES = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, os.pardir, "examples", "data")
report = {}


# The same 10 ms tick in a plain Python process beside FreeCAD, at its priority: the gaps it sees
# are the machine's (other jobs on its cores), not the GUI's. It prints its longest gap since the
# last line it read on stdin.
_OTHER = """
import sys, threading, time
longest, last = [0.0], [time.monotonic()]
def tick():
    while True:
        time.sleep(0.01)
        now = time.monotonic()
        longest[0] = max(longest[0], 1000.0 * (now - last[0]))
        last[0] = now
threading.Thread(target=tick, daemon=True).start()
for line in sys.stdin:
    print(round(longest[0], 1), flush=True)
    longest[0] = 0.0
"""


class MachineBeat:
    def __init__(self):
        self.child = subprocess.Popen(["/usr/bin/python3", "-c", _OTHER], stdin=subprocess.PIPE,
                                      stdout=subprocess.PIPE, text=True)

    def gap(self):
        # Read at a phase's start (resets it) and end; the value is the phase's longest gap.
        self.child.stdin.write("\n")
        self.child.stdin.flush()
        return float(self.child.stdout.readline())


def spin(condition, seconds):
    # Control goes back to the event loop between short waits, as with FreeCAD's own loop.
    end = time.monotonic() + seconds
    while not condition():
        if time.monotonic() > end:
            raise TimeoutError("waited %.0f s" % seconds)
        loop = QtCore.QEventLoop()
        QtCore.QTimer.singleShot(20, loop.quit)
        loop.exec_()


def make_parts(folder):
    os.makedirs(folder)
    Part.makeBox(10, 20, 30).exportBrep(os.path.join(folder, "box.brep"))
    Part.makeCylinder(5, 20).exportStep(os.path.join(folder, "cylinder.step"))
    with open(os.path.join(folder, "bad.step"), "w") as f:
        f.write("ISO-10303-21;\nthis is not a STEP file\n")


def run():
    from cadmedial.batch.programs import find_cli
    from cadmedial.gui import batch_command
    from cadmedial.gui.batch_table import COLUMNS, rows_shown
    Gui.activateWorkbench("MedialAxisWorkbench")
    toolbar = [t for t in Gui.getMainWindow().findChildren(QtWidgets.QToolBar) if t.windowTitle() == "Medial Axis"]
    report["toolbar"] = [a.text() for t in toolbar for a in t.actions()]
    report["cli"] = find_cli()
    folder = os.path.join(OUT, "parts")
    make_parts(folder)

    beat = Heartbeat()
    machine = MachineBeat()
    machine.gap()
    end = time.monotonic() + 3.0  # the same wait with nothing running: the machine's own stalls
    spin(lambda: time.monotonic() > end, 10)
    report["idle_stall_ms"] = beat.gap()
    report["idle_machine_ms"] = machine.gap()
    Gui.runCommand("MedialAxis_Batch")
    dialog = batch_command.dialog
    report["dialog_visible"] = dialog.isVisible()
    dialog.inputs.setText(folder)
    report["default_output"] = dialog.output.text()
    dialog.jobs.setValue(2)
    dialog.samples.setValue(3000)
    spin(lambda: True, 0.5)
    beat.reset()
    machine.gap()
    started = time.monotonic()
    dialog.start_button.click()
    report["running_after_click"] = dialog.running
    events = report["events"] = []
    dialog.runner.progressed.connect(lambda u: events.append((round(time.monotonic() - started, 2), u.message)))
    report["click_ms"] = round(1000.0 * (time.monotonic() - started), 1)
    spin(lambda: not dialog.running, 600)
    report["batch_seconds"] = round(time.monotonic() - started, 2)
    end = time.monotonic() + 1.0  # the table filling and the cluster's last messages
    spin(lambda: time.monotonic() > end, 10)
    report["stall_ms"] = beat.gap()
    report["machine_ms"] = machine.gap()
    report["gaps"] = beat.gaps
    report["collections"] = beat.collections
    report["spawn_executable"] = os.fsdecode(multiprocessing.spawn.get_executable())
    report["status_text"] = dialog.status.text()
    report["headers"] = [c[0] for c in COLUMNS]
    dialog.table.sortByColumn(0, QtCore.Qt.AscendingOrder)  # by part name
    report["rows"] = rows_shown(dialog.table)
    dialog.table.sortByColumn([c[0] for c in COLUMNS].index("Time s"), QtCore.Qt.DescendingOrder)
    report["times_sorted"] = [row[[c[0] for c in COLUMNS].index("Time s")] for row in rows_shown(dialog.table)]
    report["summary_button"] = dialog.summary_button.isEnabled()
    out_dir = dialog.output.text()
    report["outputs"] = sorted(os.path.relpath(os.path.join(root, f), out_dir)
                               for root, _, files in os.walk(out_dir) for f in files)

    # A double-click on the box's row opens it, with its medial mesh, in a new document.
    dialog.table.sortByColumn(0, QtCore.Qt.AscendingOrder)
    box_row = [r[0] for r in rows_shown(dialog.table)].index("parts/box.brep")
    before = set(App.listDocuments())
    dialog.table.doubleClicked.emit(dialog.proxy.index(box_row, 0))
    spin(lambda: True, 0.5)
    opened = [App.getDocument(n) for n in App.listDocuments() if n not in before]
    report["opened"] = [sorted(o.TypeId for o in d.Objects) for d in opened]
    report["opened_faces"] = [o.Mesh.CountFacets for d in opened for o in d.Objects if o.TypeId == "Mesh::Feature"]
    for d in opened:  # its 3D view, drawn by software OpenGL here, would be in the next phase's stalls
        App.closeDocument(d.Name)

    dialog.raise_()
    dialog.activateWindow()
    spin(lambda: True, 0.5)
    dialog.grab().save(os.path.join(OUT, "batch.png"))

    # Stop: two parts that take long at 400000 samples, one worker; Stop a few seconds in.
    slow = os.path.join(OUT, "slow")
    os.makedirs(slow)
    for name in ("nist_ftc_11_asme1_rb.stp", "sg1-c5-214.stp"):
        shutil.copy(os.path.join(EXAMPLES, name), slow)
    dialog.inputs.setText(slow)
    dialog.jobs.setValue(1)
    dialog.samples.setValue(400000)
    beat.reset()
    machine.gap()
    dialog.start_button.click()
    end = time.monotonic() + 4.0
    spin(lambda: time.monotonic() > end, 10)
    report["running_before_stop"] = dialog.running
    stopped_at = time.monotonic()
    dialog.stop_button.click()
    spin(lambda: not dialog.running, 300)
    report["stop_seconds"] = round(time.monotonic() - stopped_at, 2)
    report["stop_stall_ms"] = beat.gap()
    report["stop_machine_ms"] = machine.gap()
    report["stop_gaps"] = beat.gaps
    report["stop_collections"] = beat.collections
    report["stopped_rows"] = rows_shown(dialog.table)


def main():
    run_and_report(run, report, os.path.join(OUT, "batch.json"))


QtCore.QTimer.singleShot(1500, main)
