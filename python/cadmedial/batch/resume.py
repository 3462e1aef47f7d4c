"""Resume: a part is done when its record says ok, its outputs exist, and all are newer than its
input, for the same options. --force redoes every part."""

import json
import os

from . import outputs


def finished_record(part, out_dir, fmt, options_key):
    """The record of a previous successful run of ``part`` that still holds, or None."""
    record_file = outputs.record_path(out_dir, part.name)
    try:
        with open(record_file, encoding="utf-8") as f:
            record = json.load(f)
        input_time = os.path.getmtime(part.path)
        files = [record_file, outputs.mesh_path(out_dir, part.name, fmt), outputs.stats_path(out_dir, part.name)]
        times = [os.path.getmtime(p) for p in files]
    except (OSError, ValueError):
        return None
    if record.get("status") != "ok" or record.get("options") != options_key:
        return None
    if min(times) <= input_time:
        return None
    return record
