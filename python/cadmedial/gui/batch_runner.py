"""Runs a batch for the dialog: cadmedial.batch() in its own /usr/bin/python3 process
(cadmedial.batch.pipe), watched by a Python thread that hands its progress and its end back to
the GUI thread as Qt signals (queued: the slots run in the GUI thread).

Why a process and not batch() in a thread of FreeCAD: Dask's imports, its scheduler and their
garbage would live in FreeCAD's process, and each full garbage collection of FreeCAD's heap (some
150000 objects) holds the GIL, and so the GUI, for about 0.1 s; local workers would be spawned with
sys.executable, which is the freecad program. Here the GUI thread only starts the thread and
receives signals; the thread only waits on a pipe.
"""

import json
import os
import shutil
import subprocess
import sys
import tempfile
import threading

from PySide2 import QtCore

from cadmedial.batch.progress import Update
from cadmedial.batch.run import BatchResult

NICE = 5  # the batch's processes below FreeCAD's priority: on a laptop's few cores the GUI comes first
_PACKAGE_ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def python_program():
    """The Python the compiled module is built for: this version, as FreeCAD embeds it."""
    if os.path.basename(sys.executable or "").startswith("python"):
        return sys.executable
    for python in ("/usr/bin/python%d.%d" % sys.version_info[:2], "/usr/bin/python3"):
        if os.access(python, os.X_OK):
            return python
    return "python3"


def _command():
    nice = shutil.which("nice")
    return ([nice, "-n", str(NICE)] if nice else []) + [python_program(), "-m", "cadmedial.batch.pipe"]


def _child_environment():
    env = dict(os.environ)
    paths = [p for p in env.get("PYTHONPATH", "").split(os.pathsep) if p]
    env["PYTHONPATH"] = os.pathsep.join([_PACKAGE_ROOT] + [p for p in paths if p != _PACKAGE_ROOT])
    import cadmedial._core as core  # where this process found it (CADMEDIAL_CORE_DIR or the package)
    env.setdefault("CADMEDIAL_CORE_DIR", os.path.dirname(os.path.abspath(core.__file__)))
    return env


class BatchRunner(QtCore.QObject):
    """runner = BatchRunner(inputs, out_dir, {"jobs": 2, ...}); runner.progressed.connect(...);
    runner.start(); runner.stop() (the batch records the unfinished parts "stopped")."""

    progressed = QtCore.Signal(object)       # a cadmedial.batch.progress.Update
    finished = QtCore.Signal(object, str)    # (BatchResult or None, error message or "")

    def __init__(self, inputs, out_dir, options, parent=None):
        super().__init__(parent)
        self.request = {"inputs": list(inputs), "out_dir": out_dir, "options": dict(options)}
        self._process = None
        self._stop = threading.Event()
        self._lock = threading.Lock()
        self._thread = threading.Thread(target=self._run, name="cadmedial-batch", daemon=True)

    def start(self):
        self._thread.start()

    def stop(self):
        self._stop.set()
        with self._lock:
            if self._process is not None:
                self._tell_child("stop\n")

    @property
    def stopping(self):
        return self._stop.is_set()

    @property
    def running(self):
        return self._thread.is_alive()

    def wait(self, timeout=None):
        self._thread.join(timeout)

    def _tell_child(self, text):
        try:
            self._process.stdin.write(text)
            self._process.stdin.flush()
        except (BrokenPipeError, OSError, ValueError):  # it ended meanwhile
            pass

    def _run(self):
        result, error = None, ""
        with tempfile.TemporaryFile("w+", prefix="cadmedial-batch-") as log:
            try:
                with self._lock:
                    self._process = subprocess.Popen(
                        _command(), stdin=subprocess.PIPE,
                        stdout=subprocess.PIPE, stderr=log, text=True, env=_child_environment())
                    self._tell_child(json.dumps(self.request) + "\n")
                    if self._stop.is_set():
                        self._tell_child("stop\n")
                for line in self._process.stdout:
                    message = json.loads(line)
                    if "update" in message:
                        self.progressed.emit(Update(*message["update"]))
                    elif "result" in message:
                        result = BatchResult(**message["result"])
                    elif "error" in message:
                        error = message["error"]
                code = self._process.wait()
                if result is None and not error:
                    log.seek(0)
                    tail = [l for l in log.read().splitlines() if l.strip()][-3:]
                    error = "the batch process ended with status %s: %s" % (code, " ".join(tail))
            except Exception as e:  # cannot start Python, or a line that is not JSON: said in the dialog
                error = "%s: %s" % (type(e).__name__, e)
                if self._process is not None and self._process.poll() is None:
                    self._process.kill()
                    self._process.wait()
            finally:
                if self._process is not None and self._process.stdin:
                    self._process.stdin.close()
        self.finished.emit(result, error)
