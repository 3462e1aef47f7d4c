"""Progress of a batch on the terminal (parts done, failed, rate and time left), and the same
updates handed to a caller's function (batch(on_progress=...): the FreeCAD dialog's progress bar)."""

import sys
import time
from typing import NamedTuple, Optional


class Update(NamedTuple):
    """What on_progress receives: after each part (``record`` is its summary row) and with each
    line the batch says (``message``: the parts found, the cluster started, a stop)."""
    done: int                # parts finished, those done before (resumed) included
    failed: int              # of those, not ok
    total: int               # parts in the batch
    record: Optional[dict]   # the part just finished, else None
    message: str             # a line the batch said, else ""


def _duration(seconds):
    seconds = int(round(seconds))
    if seconds < 60:
        return "%ds" % seconds
    if seconds < 3600:
        return "%dm%02ds" % divmod(seconds, 60)
    return "%dh%02dm" % (seconds // 3600, seconds % 3600 // 60)


class Progress:
    """On a terminal one line redrawn in place; elsewhere (a log, CI) one line per part."""

    def __init__(self, total, stream=None, enabled=True, listener=None):
        self.total, self.done, self.failed = total, 0, 0
        self.skipped = 0  # done before (resume): in done, not in the rate
        self.stream = stream or sys.stderr
        self.enabled = enabled
        self.listener = listener  # called with an Update, in the batch's thread
        self.tty = enabled and hasattr(self.stream, "isatty") and self.stream.isatty()
        self.start = time.monotonic()

    def _tell(self, record=None, message=""):
        if self.listener is not None:
            self.listener(Update(self.done, self.failed, self.total, record, message))

    def resumed(self, count):
        """Parts done before: they count as done (the bar starts there), at no rate."""
        self.done += count
        self.skipped += count

    def say(self, line):
        self._tell(message=line)
        if self.enabled:
            if self.tty:
                self.stream.write("\r\033[K")
            self.stream.write("cadmedial batch: %s\n" % line)
            self.stream.flush()

    def part_done(self, record):
        self.done += 1
        self.failed += record["status"] != "ok"
        self._tell(record=record)
        if not self.enabled:
            return
        elapsed = time.monotonic() - self.start
        ran = self.done - self.skipped
        rate = ran / elapsed if elapsed > 0 else 0.0
        left = (self.total - self.done) / rate if rate > 0 else 0.0
        head = "[%d/%d] %d failed, %.2f parts/s, %s left" % (self.done, self.total, self.failed, rate,
                                                            _duration(left))
        if self.tty:
            self.stream.write("\r\033[K" + head)
            if self.done == self.total:
                self.stream.write("\n")
        else:
            self.stream.write("cadmedial batch: %s: %s %s%s\n" % (
                head, record["part"], record["status"],
                "" if record["status"] == "ok" else " (%s)" % record.get("message", "")))
        self.stream.flush()
