"""Progress of a batch on the terminal: parts done, failed, rate and time left."""

import sys
import time


def _duration(seconds):
    seconds = int(round(seconds))
    if seconds < 60:
        return "%ds" % seconds
    if seconds < 3600:
        return "%dm%02ds" % divmod(seconds, 60)
    return "%dh%02dm" % (seconds // 3600, seconds % 3600 // 60)


class Progress:
    """On a terminal one line redrawn in place; elsewhere (a log, CI) one line per part."""

    def __init__(self, total, stream=None, enabled=True):
        self.total, self.done, self.failed = total, 0, 0
        self.stream = stream or sys.stderr
        self.enabled = enabled
        self.tty = enabled and hasattr(self.stream, "isatty") and self.stream.isatty()
        self.start = time.monotonic()

    def say(self, line):
        if self.enabled:
            if self.tty:
                self.stream.write("\r\033[K")
            self.stream.write("cadmedial batch: %s\n" % line)
            self.stream.flush()

    def part_done(self, record):
        self.done += 1
        self.failed += record["status"] != "ok"
        if not self.enabled:
            return
        elapsed = time.monotonic() - self.start
        rate = self.done / elapsed if elapsed > 0 else 0.0
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
