"""Batch runs on Dask: the medial axis of many parts, on a laptop or a cluster.

    import cadmedial
    result = cadmedial.batch(["parts/", "more.step"], "out", jobs=2, samples=20000)
    result.counts             # {"ok": 41, "timeout": 1}
    # out/summary.csv, out/summary.json, out/parts/<name>.ply ...

From the shell: ``cadmedial batch INPUTS... -o OUTDIR`` (or ``python3 -m cadmedial.batch``);
docs/batch.md is the user's page. One job per file: discover (inputs), limits (a child process
under a time and memory limit), task (one part), status (its status and summary columns),
outputs (layout, atomic writes), resume, summary, client (Dask), progress, analyses (the
--thickness hook), fcstd (FreeCAD documents), programs (finding the cadmedial program), run
(batch()), pipe (batch() driven through pipes: the FreeCAD dialog), __main__ (the command line).
"""

import sys as _sys
import types as _types

from .discover import Part, discover
from .run import BatchResult, batch


class _CallableModule(_types.ModuleType):
    # `cadmedial.batch(...)` is the function while `cadmedial.batch` stays this package (so that
    # `python3 -m cadmedial.batch` and `from cadmedial.batch import discover` work too).
    def __call__(self, *args, **kwargs):
        return batch(*args, **kwargs)


_sys.modules[__name__].__class__ = _CallableModule

__all__ = ["batch", "BatchResult", "discover", "Part"]
