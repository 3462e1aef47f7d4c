"""summary.csv and summary.json (one row per part), and the short text summary at the end."""

import collections
import csv
import io
import json

from . import outputs
from .status import STATUSES

# The CSV's columns, in order; summary.json has every field of each record.
COLUMNS = ("part", "status", "message", "solids", "samples", "vertices", "faces", "edges", "topology_right",
           "thinnest_wall", "thinnest_wall_at", "time_s", "peak_memory_mb", "warnings", "resumed", "worker",
           "input")


def _cell(value):
    if value is None:
        return ""
    if isinstance(value, (list, tuple)):
        return " ".join("%.6g" % v if isinstance(v, float) else str(v) for v in value)
    if isinstance(value, float):
        return "%.6g" % value
    return str(value)


def write(out_dir, records, extra_columns=()):
    """Writes OUTDIR/summary.csv and summary.json atomically, rows sorted by part name."""
    rows = sorted(records, key=lambda r: r["part"])
    columns = list(COLUMNS) + [c for c in extra_columns if c not in COLUMNS]
    text = io.StringIO()
    w = csv.writer(text, lineterminator="\n")
    w.writerow(columns)
    for r in rows:
        w.writerow([_cell(r.get(c)) for c in columns])
    outputs.write_text_atomically(outputs.os.path.join(out_dir, "summary.csv"), text.getvalue())
    outputs.write_json_atomically(outputs.os.path.join(out_dir, "summary.json"),
                                  {"parts": rows, "counts": counts(rows)})


def counts(records):
    c = collections.Counter(r["status"] for r in records)
    return {s: c[s] for s in STATUSES if c[s]}


def text(records, wall_seconds, slowest=5):
    """A few lines: counts by status, the slowest parts, failures grouped by message."""
    lines = []
    c = counts(records)
    resumed = sum(1 for r in records if r.get("resumed"))
    lines.append("%d parts in %.1f s: %s%s" % (
        len(records), wall_seconds, ", ".join("%d %s" % (n, s) for s, n in c.items()),
        " (%d done before, skipped)" % resumed if resumed else ""))
    ran = [r for r in records if not r.get("resumed") and r.get("time_s") is not None]
    if ran:
        lines.append("sum of part times %.1f s; slowest: %s" % (
            sum(r["time_s"] for r in ran),
            ", ".join("%s %.1f s" % (r["part"], r["time_s"])
                      for r in sorted(ran, key=lambda r: -r["time_s"])[:slowest])))
    failures = collections.defaultdict(list)
    for r in records:
        if r["status"] != "ok":
            failures[(r["status"], r.get("message", ""))].append(r["part"])
    for (status, message), parts in sorted(failures.items(), key=lambda kv: (-len(kv[1]), kv[0])):
        shown = ", ".join(parts[:3]) + (", ..." if len(parts) > 3 else "")
        lines.append("%s (%d): %s [%s]" % (status, len(parts), message, shown))
    return "\n".join(lines)
