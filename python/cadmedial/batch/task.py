"""One part of a batch, as a Dask task: runs the engine on it in a child process under the part's
limits, moves its outputs into place, and returns its record (a plain dict, a summary row).

Everything that can go wrong with a part is caught here and recorded, so that the task itself
never fails and a worker never dies of a part: the engine runs in a child process.
"""

import json
import os
import signal
import socket
import sys
import time
from typing import NamedTuple, Optional, Tuple

from . import outputs
from .analyses import Analysis, load as load_analysis
from .limits import run_limited
from .programs import find_cli, is_program
from .status import classify, summary_columns


class TaskOptions(NamedTuple):
    cli: str                     # the cadmedial program
    fmt: str                     # mesh format: ply, obj or ma
    compute_args: Tuple[str, ...]  # compute options passed on (--samples 3000 ...)
    timeout: Optional[float]     # wall seconds per part, None = no limit
    memory_bytes: Optional[int]  # address-space limit per part, None = no limit
    analyses: Tuple[Analysis, ...] = ()
    python: str = "/usr/bin/python3"  # FreeCAD's interpreter, for FCStd documents

    def key(self):
        """What a part's outputs depend on besides the input: resume redoes a part when it changes."""
        return {"fmt": self.fmt, "compute_args": list(self.compute_args),
                "analyses": [[a.name, a.options] for a in self.analyses]}


_FCSTD = os.path.join(os.path.dirname(os.path.abspath(__file__)), "fcstd.py")


def _remaining(deadline):
    return None if deadline is None else max(0.01, deadline - time.monotonic())


def _step(argv, work, name, deadline, options, replace):
    """Runs one command of the part; (status, message, outcome). ``replace`` maps temporary paths
    to the user's in messages."""
    try:
        outcome = run_limited(argv, _remaining(deadline), options.memory_bytes,
                              stderr_path=os.path.join(work, name + ".stderr"))
    except OSError as e:
        return "error", "cannot run %s: %s" % (argv[0], e), None
    status, message = classify(outcome, options.timeout, options.memory_bytes)
    for old, new in replace.items():
        message = message.replace(old, new)
    return status, message, outcome


def run_part(part, out_dir, options: TaskOptions):
    """The record of ``part`` (discover.Part) after running it: a dict with 'status' (ok, refused,
    error, out_of_memory, timeout, crashed), 'message', 'time_s', 'peak_memory_mb' and the
    summary columns of status.summary_columns. Writes OUTDIR/parts/<name>.* (outputs.py)."""
    start = time.monotonic()
    deadline = None if options.timeout is None else start + options.timeout
    work = outputs.make_work_dir(out_dir)
    record = {"part": part.name, "input": part.path, "worker": socket.gethostname(),
              "options": options.key()}
    peak, logs = 0.0, []
    try:
        source, replace = part.path, {}
        status, message = "ok", ""
        # The client's path of the program, unless this worker (another machine) has it elsewhere.
        cli = options.cli if is_program(options.cli) else find_cli()
        if part.path.lower().endswith(".fcstd"):
            source = os.path.join(work, "document.brep")
            replace[source] = part.path
            status, message, outcome = _step([options.python, _FCSTD, part.path, source], work, "fcstd",
                                             deadline, options, replace)
            if outcome:
                peak = max(peak, outcome.peak_rss_mb)
                logs.append(outcome.stderr)
        stats = None
        mesh = os.path.join(work, "mesh." + options.fmt)
        stats_file = os.path.join(work, "stats.json")
        if status == "ok":
            argv = [cli, "compute", source, "-o", mesh, "--stats", stats_file, "--quiet"]
            argv += list(options.compute_args)
            status, message, outcome = _step(argv, work, "compute", deadline, options, replace)
            if outcome:
                peak = max(peak, outcome.peak_rss_mb)
                logs.append(outcome.stderr)
        if status == "ok":
            with open(stats_file, encoding="utf-8") as f:
                stats = json.load(f)
            record.update(summary_columns(stats))
            moves = {mesh: outputs.mesh_path(out_dir, part.name, options.fmt),
                     stats_file: outputs.stats_path(out_dir, part.name)}
            for a in options.analyses:
                module = load_analysis(a.name)
                argv, files = module.batch_step(source, work, cli, a.options)
                step_status, step_message, outcome = _step(argv, work, a.name, deadline, options, replace)
                if outcome:
                    peak = max(peak, outcome.peak_rss_mb)
                    logs.append(outcome.stderr)
                    if outcome.returncode is not None and not outcome.timed_out:
                        try:
                            record.update(module.batch_result(outcome.returncode, files))
                            step_status, step_message = "ok", ""
                        except Exception as e:
                            step_status, step_message = "error", str(e) or step_message
                if step_status != "ok":
                    status, message = step_status, "%s: %s" % (a.name, step_message)
                    break
                for suffix, path in files.items():
                    moves[path] = outputs.part_stem(out_dir, part.name) + suffix
            if status == "ok":
                for src, dst in moves.items():
                    outputs.promote(src, dst)
        if status != "ok":
            outputs.remove_outputs(out_dir, part.name, options.fmt)
    except Exception as e:  # a bug of ours or a full disk: still a record, never a dead batch
        status, message = "error", "batch: %s: %s" % (type(e).__name__, e)
    finally:
        outputs.remove_work_dir(work)
    record.update(status=status, message=message, time_s=round(time.monotonic() - start, 4),
                  peak_memory_mb=round(peak, 1))
    try:
        log = "".join(logs)
        for old, new in replace.items():
            log = log.replace(old, new)
        outputs.write_text_atomically(outputs.log_path(out_dir, part.name), log)
        # Last: the record is what tells a later run that the part is done (resume.py).
        outputs.write_json_atomically(outputs.record_path(out_dir, part.name), record)
    except OSError as e:
        record.update(status="error", message="batch: cannot write the record: %s" % e)
    return record
