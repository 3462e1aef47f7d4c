"""The Dask client a batch submits to: a given one, a running scheduler's address, or a local
cluster of one single-threaded worker process per core."""

import contextlib
import importlib.util
import logging
import os
import sys

from .._core import InvalidInput

_PACKAGE_ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def _export_package_path():
    """Local workers are new interpreters (multiprocessing's spawn): they must import this very
    package to run its tasks, and find its compiled module, whatever way this process found it
    (a sys.path.append in a script is not inherited)."""
    paths = os.environ.get("PYTHONPATH", "").split(os.pathsep)
    if _PACKAGE_ROOT not in paths:
        os.environ["PYTHONPATH"] = os.pathsep.join([_PACKAGE_ROOT] + [p for p in paths if p])
    import cadmedial._core as core
    os.environ.setdefault("CADMEDIAL_CORE_DIR", os.path.dirname(os.path.abspath(core.__file__)))


def _spawn_with_python():
    """Local workers are started as `sys.executable -c ...` (multiprocessing's spawn). Inside
    FreeCAD sys.executable is the freecad program, which would open a FreeCAD per worker: spawn
    them with the Python FreeCAD embeds, of this very version (the compiled module is built for it)."""
    import multiprocessing
    if os.path.basename(sys.executable or "").startswith("python"):
        return
    for python in ("/usr/bin/python%d.%d" % sys.version_info[:2], "/usr/bin/python3"):
        if os.access(python, os.X_OK):
            multiprocessing.set_executable(python)
            return


def dashboard_link(client):
    """Dask's dashboard address, or None: it needs bokeh, which Debian 12 does not package."""
    if importlib.util.find_spec("bokeh") is None:
        return None
    return getattr(client, "dashboard_link", None)


@contextlib.contextmanager
def dask_client(client=None, scheduler=None, jobs=None):
    """Yields a distributed.Client; closes what it opened (not a client it was given)."""
    if client is not None:
        yield client
        return
    try:
        import distributed
    except ImportError as e:
        raise InvalidInput("cadmedial batch needs Dask (Debian: apt-get install python3-dask "
                           "python3-distributed): %s" % e) from None
    if scheduler:
        try:
            c = distributed.Client(scheduler, timeout="30s")
        except (OSError, TimeoutError) as e:
            raise InvalidInput("--scheduler %s: cannot connect: %s" % (scheduler, e)) from None
        try:
            yield c
        finally:
            c.close()
        return
    _export_package_path()
    _spawn_with_python()
    n = jobs or os.cpu_count() or 1
    # One thread per worker: a task only waits for its part's child process, and a worker per
    # core runs as many parts at once as there are cores. No dashboard without bokeh (above).
    dashboard = ":0" if importlib.util.find_spec("bokeh") else None
    cluster = distributed.LocalCluster(n_workers=n, threads_per_worker=1, processes=True,
                                       dashboard_address=dashboard, silence_logs=logging.ERROR)
    try:
        c = distributed.Client(cluster)
        try:
            yield c
        finally:
            c.close()
    finally:
        cluster.close()
