"""What the GUI scripts under Xvfb share (run inside FreeCAD): the 10 ms heartbeat that measures how long
the GUI stops answering, and the ending that writes the report and leaves FreeCAD."""
import gc
import json
import os
import time
import traceback

from PySide2 import QtCore


class Heartbeat:
    """The longest gap between ticks of a 10 ms timer since reset(), in ms; and the full garbage
    collections meanwhile (FreeCAD's heap is large: each holds the GIL, so the GUI, a while)."""

    def __init__(self):
        self.timer = QtCore.QTimer()
        self.timer.setInterval(10)
        self.timer.timeout.connect(self._tick)
        self.reset()
        self.timer.start()
        gc.callbacks.append(self._collected)

    def reset(self):
        self.last = self.start = time.monotonic()
        self.longest = 0.0
        self.gaps = []  # (seconds since reset, gap ms) of the gaps over 50 ms
        self.collections = []  # (seconds since reset, ms) of each full garbage collection

    def _collected(self, phase, info):
        if info["generation"] != 2:
            return
        if phase == "start":
            self._gc_start = time.monotonic()
        else:
            self.collections.append((round(self._gc_start - self.start, 2),
                                     round(1000.0 * (time.monotonic() - self._gc_start), 1)))

    def _tick(self):
        now = time.monotonic()
        gap = 1000.0 * (now - self.last)
        self.longest = max(self.longest, gap)
        if gap > 50:
            self.gaps.append((round(self.last - self.start, 2), round(gap, 1)))
        self.last = now

    def gap(self):
        self._tick()
        return round(self.longest, 1)


def run_and_report(run, report, path):
    """Runs run(); its exception, if any, goes into report["exception"]; writes report as JSON to
    path and ends FreeCAD (os._exit: its own exit can hang under Xvfb)."""
    try:
        run()
    except Exception:
        report["exception"] = traceback.format_exc()
    with open(path, "w") as f:
        json.dump(report, f, indent=1)
    os._exit(0)
