"""batch(): discovers the parts, skips the finished ones, runs the others on Dask, writes the
summary."""

import math
import os
import time
from typing import List, NamedTuple

from .. import api
from .._core import InvalidInput
from . import analyses, outputs, resume, summary
from .client import dask_client, dashboard_link
from .discover import discover
from .progress import Progress
from .programs import find_cli
from .status import STOPPED_MESSAGE
from .task import TaskOptions, run_part

FORMATS = ("ply", "obj", "ma")
DEFAULT_TIMEOUT = 3600.0  # seconds per part
DEFAULT_MEMORY = 8.0      # GB of address space per part


class BatchResult(NamedTuple):
    records: List[dict]  # one per part, sorted by name: the rows of summary.json
    counts: dict         # {status: number of parts}
    seconds: float       # wall time of the whole batch
    text: str            # the short text summary


def compute_args(spacing=None, samples=None, theta=None, rho=None, refine=False, uniform=False,
                 plain_medial=False, min_feature=None):
    """The `cadmedial compute` options for these parameters, checked here so that a typo fails
    the batch at once instead of every part."""
    args = []
    if spacing is not None and samples is not None:
        raise InvalidInput("give spacing or samples, not both")
    spacing, samples = api._density(spacing, samples)
    if spacing:
        args += ["--spacing", repr(spacing)]
    if samples:
        args += ["--samples", str(samples)]
    if theta is not None:
        theta = api._number("theta", theta)
        if not 0 < theta < 90:
            raise InvalidInput("theta must be in (0, 90) degrees, got %r" % theta)
        args += ["--theta", repr(theta)]
    if rho is not None:
        rho = api._number("rho", rho)
        if not rho > 0:
            raise InvalidInput("rho must be > 0, got %r" % rho)
        args += ["--rho", repr(rho)]
    if min_feature is not None:
        min_feature = api._number("min_feature", min_feature)
        if not min_feature > 0:
            raise InvalidInput("min_feature must be > 0, got %r" % min_feature)
        args += ["--min-feature", repr(min_feature)]
    for flag, on in (("--refine", refine), ("--uniform", uniform), ("--plain-medial", plain_medial)):
        if api._flag(flag.lstrip("-").replace("-", "_"), on):
            args.append(flag)
    return tuple(args)


def _limit(name, value, scale):
    """None for no limit (0 or None), else value * scale; InvalidInput when not a number >= 0."""
    if value is None:
        return None
    x = api._number(name, value)
    if not (math.isfinite(x) and x >= 0):
        raise InvalidInput("%s must be a number >= 0 (0: no limit), got %r" % (name, value))
    return None if x == 0 else x * scale


def batch(inputs, out_dir, client=None, jobs=None, scheduler=None, timeout=DEFAULT_TIMEOUT,
          memory=DEFAULT_MEMORY, force=False, format="ply", spacing=None, samples=None, theta=None,
          rho=None, refine=False, uniform=False, plain_medial=False, thickness=None, cli=None,
          progress=True, on_progress=None, stop=None, min_feature=None):
    """Computes the medial axis of every part of ``inputs`` into ``out_dir``, on Dask.

    inputs     a path or a list of them: CAD files (STEP, IGES, BREP, FCStd), folders (searched
               for them) or list files (.txt/.lst/.list: one path a line)
    out_dir    the output folder (outputs.py gives its layout); on a cluster, a folder that every
               worker sees at the same path, as the inputs
    client     a distributed.Client to submit to; else ``scheduler`` (a running scheduler's
               address, "tcp://host:8786"), else a local cluster of ``jobs`` worker processes
               (default: one per core)
    timeout    wall seconds per part (default 3600; 0 or None: no limit)
    memory     GB of address space per part (default 8; 0 or None: no limit)
    force      redo every part; by default a part whose outputs exist, are newer than its input
               and were made with the same options is skipped (resume)
    format     the mesh format: "ply", "obj" or "ma"
    spacing, samples, theta, rho, refine, uniform, plain_medial, min_feature
               as `cadmedial compute` (--spacing ... --plain-medial, --min-feature); None: its
               defaults
    thickness  None, or {"min": 0.8, "max": None}: also run the wall-thickness analysis (issue 34)
               on each part; refused while cadmedial.thickness does not exist
    cli        the cadmedial program to run (default: found as programs.find_cli says)
    progress   print progress and the text summary on stderr
    on_progress
               None, or a function called with a progress.Update after each part and with each
               line of progress (in the thread that runs batch(): a GUI hands it on to its own)
    stop       None, or a threading.Event (or a function returning True) that stops the batch:
               checked every 0.1 s; the parts not finished are cancelled (a local cluster's
               running ones killed with it) and recorded "stopped", finished ones are kept

    Returns a BatchResult; writes OUTDIR/summary.csv and summary.json. A part that fails is a
    record with its status and message, never an exception; InvalidInput is raised for bad
    arguments (before any part runs).
    """
    start = time.monotonic()
    if format not in FORMATS:
        raise InvalidInput("format must be one of %s, got %r" % (", ".join(FORMATS), format))
    if jobs is not None and (isinstance(jobs, bool) or not isinstance(jobs, int) or jobs < 1):
        raise InvalidInput("jobs must be a whole number >= 1, got %r" % (jobs,))
    if scheduler and client is not None:
        raise InvalidInput("give a client or a scheduler address, not both")
    stopped = _stop_test(stop)
    extra = ()
    if thickness is not None:
        extra = (analyses.Analysis("thickness", dict(thickness)),)
    analyses.check(extra)
    columns = analyses.columns(extra)
    options = TaskOptions(cli=find_cli(cli), fmt=format,
                          compute_args=compute_args(spacing, samples, theta, rho, refine, uniform, plain_medial,
                                                    min_feature),
                          timeout=_limit("timeout", timeout, 1.0), memory_bytes=_limit("memory", memory, 2**30),
                          analyses=extra)
    if options.memory_bytes is not None:
        options = options._replace(memory_bytes=int(options.memory_bytes))
    parts = discover(inputs)
    out_dir = os.path.abspath(os.fspath(out_dir))
    os.makedirs(out_dir, exist_ok=True)
    if not os.access(out_dir, os.W_OK | os.X_OK):
        raise InvalidInput("%s: the output folder is not writable" % out_dir)

    report = Progress(len(parts), enabled=progress, listener=on_progress)
    records, todo = [], []
    for part in parts:
        done = None if force else resume.finished_record(part, out_dir, format, options.key())
        if done is not None:
            records.append(dict(done, resumed=True))
        else:
            todo.append(part)
    report.resumed(len(records))
    if records:
        report.say("%d of %d parts done before (outputs newer than their input): skipped; --force redoes them"
                   % (len(records), len(parts)))
    if todo:
        finished = _run(todo, out_dir, options, client, scheduler, jobs, report, columns, stopped)
        records += finished + _unfinished(todo, finished, out_dir, options)
    records.sort(key=lambda r: r["part"])
    summary.write(out_dir, records, columns)
    seconds = time.monotonic() - start
    text = summary.text(records, seconds)
    if progress:
        report.say("wrote %s and %s\n%s" % (os.path.join(out_dir, "summary.csv"), "summary.json", text))
    return BatchResult(records, summary.counts(records), seconds, text)


def _stop_test(stop):
    """A function saying whether to stop, from an Event, a function or None."""
    if stop is None:
        return lambda: False
    if hasattr(stop, "is_set"):
        return stop.is_set
    if callable(stop):
        return lambda: bool(stop())
    raise InvalidInput("stop must be a threading.Event or a function, got %r" % (stop,))


def _unfinished(parts, finished, out_dir, options):
    """Records of the parts of a stopped batch that have none: "stopped", unless the part's own
    record says it finished meanwhile (it ended as the batch stopped)."""
    have = {r["part"] for r in finished}
    records = []
    for part in parts:
        if part.name in have:
            continue
        done = resume.finished_record(part, out_dir, options.fmt, options.key())
        records.append(done if done is not None else {
            "part": part.name, "input": part.path, "status": "stopped", "message": STOPPED_MESSAGE,
            "time_s": None, "peak_memory_mb": None, "options": options.key()})
    return records


def _run(parts, out_dir, options, client, scheduler, jobs, report, columns, stopped):
    """Records of ``parts`` run on Dask, in the order they finish; fewer when ``stopped()``
    turns True (the others are cancelled)."""
    from distributed import as_completed
    # The biggest files first (priority): the longest parts should not be the last to start.
    order = sorted(range(len(parts)), key=lambda i: -os.path.getsize(parts[i].path))
    records = []
    if stopped():
        return records
    with dask_client(client, scheduler, jobs) as c:
        link = dashboard_link(c)
        report.say("%d parts on %d workers (%s)%s" % (
            len(parts), len(c.scheduler_info().get("workers", {})), c.scheduler.address,
            "; dashboard " + link if link else ""))
        report.start = time.monotonic()  # the rate is of parts, not of the cluster's start-up
        futures = {}
        for rank, i in enumerate(order):
            f = c.submit(run_part, parts[i], out_dir, options, pure=False, priority=len(parts) - rank,
                         key="cadmedial-part-%d-%s" % (i, os.urandom(4).hex()))
            futures[f] = parts[i]
        try:
            pending = as_completed(futures)
            while not pending.is_empty():
                if stopped():
                    c.cancel(list(futures))
                    report.say("stopped: %d of %d parts finished, the others cancelled" % (
                        len(records), len(parts)))
                    break
                if not pending.has_ready():
                    time.sleep(0.1)  # how soon a stop is seen
                    continue
                f = next(pending)
                part = futures[f]
                try:
                    record = f.result()
                except Exception as e:
                    # The task itself never raises (task.py): this is Dask losing it, e.g. a worker
                    # killed mid-part too often (KilledWorker), or the connection.
                    record = {"part": part.name, "input": part.path, "status": "lost",
                              "message": "%s: %s" % (type(e).__name__, e), "time_s": None,
                              "peak_memory_mb": None, "options": options.key()}
                records.append(record)
                report.part_done(record)
        except KeyboardInterrupt:
            c.cancel(list(futures))
            # What finished is on disk with its record: a rerun resumes from there.
            summary.write(out_dir, records, columns)
            raise
    return records
