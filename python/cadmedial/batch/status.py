"""A part's status from how its process ended, and its summary columns from the engine's stats."""

import math
import re
import signal

# Statuses, in the order the text summary lists them.
STATUSES = ("ok", "refused", "error", "out_of_memory", "timeout", "crashed", "lost", "stopped")
# The message of a part the batch did not finish because it was stopped (batch(stop=...)).
STOPPED_MESSAGE = "not done: the batch was stopped"

# What running out of an address-space limit looks like from inside the engine: bad_alloc (main.cpp
# says "out of memory"), or a thread that cannot get its stack (std::system_error EAGAIN,
# "Resource temporarily unavailable"; seen on NIST FTC 11 under a 250 MB limit), or OpenCASCADE's
# own allocator ("Standard_OutOfMemory: Standard_MMgrRaw::Allocate(): malloc failed", the same part
# under 100 MB), or Python's MemoryError in the FCStd reader.
_MEMORY_MESSAGES = re.compile(r"out of memory|OutOfMemory|bad_alloc|malloc failed|Resource temporarily unavailable|"
                              r"Cannot allocate memory|MemoryError", re.IGNORECASE)


def _message(stderr):
    """The error line the engine printed ('cadmedial: error: ...', without the prefix), else the
    last line it printed, else ''."""
    lines = [l.strip() for l in stderr.splitlines() if l.strip()]
    for line in reversed(lines):
        if line.startswith("cadmedial: error: "):
            return line[len("cadmedial: error: "):]
    return lines[-1] if lines else ""


def _signal_name(number):
    try:
        return signal.Signals(number).name
    except ValueError:
        return "signal %d" % number


def classify(outcome, timeout, memory_bytes):
    """(status, message) of a limits.Outcome."""
    text = _message(outcome.stderr)
    if outcome.timed_out:
        return "timeout", "killed after the %g s time limit" % timeout
    if outcome.signal is not None:
        if memory_bytes is not None and _MEMORY_MESSAGES.search(outcome.stderr):
            # "terminate called after throwing an instance of 'std::bad_alloc'", then SIGABRT
            return "out_of_memory", "past the %g GB memory limit: %s" % (memory_bytes / 2**30, text)
        what = "killed by %s" % _signal_name(outcome.signal)
        if outcome.signal == signal.SIGKILL and memory_bytes is None:
            what += " (the kernel's out-of-memory killer, or a user)"
        return "crashed", what + ("; last message: " + text if text else "")
    if outcome.returncode == 0:
        return "ok", ""
    if memory_bytes is not None and _MEMORY_MESSAGES.search(text):
        return "out_of_memory", "past the %g GB memory limit: %s" % (memory_bytes / 2**30, text)
    if outcome.returncode == 2:
        return "refused", text or "exit status 2"
    return "error", text or "exit status %d" % outcome.returncode


def _finite(x):
    return x if isinstance(x, (int, float)) and math.isfinite(x) else None


def summary_columns(stats):
    """The summary's columns from ``cadmedial compute --stats`` JSON. topology_right follows the
    engine's own rule (compute_medial_axis.cpp, topology_is_right): every solid's axis has the
    solid's Euler characteristic and is one piece. thinnest_wall is the thinnest over the solids
    (the stats' thickness of the thinnest wall under two spacings), with the sample where it is."""
    solids = stats.get("solids", [])
    walls = [(s["thinnest_wall"], s.get("thinnest_wall_at")) for s in solids if _finite(s.get("thinnest_wall"))]
    wall, at = min(walls, key=lambda w: w[0]) if walls else (None, None)
    return {
        "solids": len(solids),
        "samples": stats.get("samples"),
        "vertices": stats.get("vertices"),
        "faces": stats.get("faces"),
        "edges": stats.get("edges"),
        "spacing": stats.get("spacing"),
        # The engine's own judgement when its stats carry it (older stats: the same rule here).
        "topology_right": bool(solids) and all(
            s["topology_right"] if "topology_right" in s else
            s.get("euler_characteristic") == s.get("solid_euler_characteristic") and s.get("components", 1) <= 1
            for s in solids),
        "euler": [s.get("euler_characteristic") for s in solids],
        "solid_euler": [s.get("solid_euler_characteristic") for s in solids],
        "thinnest_wall": wall,
        "thinnest_wall_at": at,
        "warnings": len(stats.get("warnings", [])),
        "engine_time_s": (stats.get("timings") or {}).get("total"),
    }
