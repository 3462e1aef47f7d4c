"""Analyses a batch can run on each part after its medial axis, by name (``--thickness``).

An analysis lives in its own module, which the batch imports by name; that module provides

    batch_step(source, work_dir, cli, options) -> (argv, outputs)
        argv     the command that analyses the CAD file ``source`` (run under the part's limits)
        outputs  {suffix: path inside work_dir} of the files it writes; each is moved, when the
                 part succeeds, to OUTDIR/parts/<name><suffix>
    batch_result(returncode, outputs) -> {column: value}
        the part's summary columns from the command's exit status and files (a status the
        analysis does not accept raises, and the part is recorded as failed with that message)

and may name the summary.csv columns it adds in ``BATCH_COLUMNS``.

``options`` is the analysis's own options ({"min": 0.8, "max": None} for thickness).
"""

import importlib
from typing import Dict, NamedTuple, Optional

from .._core import InvalidInput


class AnalysisSpec(NamedTuple):
    module: str        # where batch_step and batch_result live
    description: str   # for the error when it is missing
    options: tuple     # the option names it takes


# An install without cadmedial.thickness refuses --thickness with a message that says so.
KNOWN = {
    "thickness": AnalysisSpec("cadmedial.thickness", "the wall-thickness analysis (issue 34)", ("min", "max")),
}


class Analysis(NamedTuple):
    name: str
    options: Dict[str, Optional[float]]


def load(name):
    """The module of analysis ``name``; InvalidInput when it is unknown or not installed."""
    spec = KNOWN.get(name)
    if spec is None:
        raise InvalidInput("unknown analysis '%s' (known: %s)" % (name, ", ".join(sorted(KNOWN))))
    try:
        module = importlib.import_module(spec.module)
    except ImportError as e:
        raise InvalidInput("--%s: %s is not in this version of cadmedial (no module %s: %s)"
                           % (name, spec.description, spec.module, e)) from None
    missing = [f for f in ("batch_step", "batch_result") if not callable(getattr(module, f, None))]
    if missing:
        raise InvalidInput("--%s: %s has no batch support yet (%s lacks %s)"
                           % (name, spec.description, spec.module, " and ".join(missing)))
    return module


def check(analyses):
    """Refuses, before any part runs, an analysis that is missing or given unknown options."""
    for a in analyses:
        load(a.name)
        unknown = set(a.options) - set(KNOWN[a.name].options)
        if unknown:
            raise InvalidInput("--%s takes no option %s" % (a.name, ", ".join(sorted(unknown))))


def columns(analyses):
    """The summary.csv columns the analyses add, in order."""
    return tuple(c for a in analyses for c in getattr(load(a.name), "BATCH_COLUMNS", ()))
