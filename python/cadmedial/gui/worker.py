"""Computing medial axes in a background thread, so the GUI stays live and can cancel.

No Qt here: the task panel polls ``progress`` from a timer. The engine releases the GIL while it
works; its progress callback only records where it is and says whether to go on. The thread also
builds the FreeCAD mesh, colours and PLY file of each result (cadmedial.app.prepare_result):
done in the GUI thread, that took seconds with the GUI frozen.
"""

import threading

import cadmedial
from cadmedial.app import prepare_result


class ComputeJob:
    """Computes ``cadmedial.compute(shape, **params)`` for each shape in turn, in a thread.

    shapes  list of cadmedial._core.Shape (read in the GUI thread beforehand)
    params  keyword arguments of cadmedial.compute (spacing, samples, theta, rho, refine), and
            "simplify": the MedialAxis's Simplify (percent of the diagonal, 0: the full axis),
            which the thread simplifies each result for (cadmedial.app.prepare_result)
    After ``done``: ``results`` (one cadmedial.app StoredResult per shape) when all succeeded, else
    ``error`` (the exception; a cadmedial.Cancelled after cancel()).
    """

    def __init__(self, shapes, params):
        self.shapes = list(shapes)
        self.params = dict(params)
        self.results = []
        self.error = None
        self.progress = (0, "", 0.0)  # (index of the shape, stage, fraction of the stage)
        self._cancel = threading.Event()
        self._thread = threading.Thread(target=self._run, name="cadmedial-compute", daemon=True)

    def start(self):
        self._thread.start()

    def cancel(self):
        self._cancel.set()

    @property
    def done(self):
        return self._thread.ident is not None and not self._thread.is_alive()

    @property
    def overall_fraction(self):
        index, _stage, fraction = self.progress
        return min(1.0, (index + fraction) / max(1, len(self.shapes)))

    def wait(self, timeout=None):
        self._thread.join(timeout)

    def _run(self):
        params = dict(self.params)
        simplify = params.pop("simplify", 0.0)
        try:
            for index, shape in enumerate(self.shapes):
                def report(stage, fraction, index=index):
                    self.progress = (index, stage, fraction)
                    return not self._cancel.is_set()
                if self._cancel.is_set():
                    raise cadmedial.Cancelled()
                result = cadmedial.compute(shape, progress=report, **params)
                stage = "simplifying, building the mesh" if simplify else "building the mesh"
                self.progress = (index, stage + " and its colours", 1.0)
                self.results.append(prepare_result(result, simplify=simplify, source=shape, progress=report))
                if self._cancel.is_set():
                    raise cadmedial.Cancelled()
        except Exception as error:  # handed to the GUI thread, which reports it
            self.error = error
            for stored in self.results:
                stored.discard()
            self.results = []


class Job:
    """Runs ``work(progress)`` in a thread; ``progress(stage, fraction)`` records where it is and
    returns False once cancel() was called (cadmedial.compute then raises Cancelled).
    After ``done``: ``value`` or ``error``."""

    def __init__(self, work):
        self.work = work
        self.value = None
        self.error = None
        self.progress = ("", 0.0)
        self._cancel = threading.Event()
        self._thread = threading.Thread(target=self._run, name="cadmedial-job", daemon=True)

    def start(self):
        self._thread.start()

    def cancel(self):
        self._cancel.set()

    @property
    def cancelled(self):
        return self._cancel.is_set()

    @property
    def done(self):
        return self._thread.ident is not None and not self._thread.is_alive()

    def report(self, stage, fraction):
        self.progress = (stage, fraction)
        return not self._cancel.is_set()

    def _run(self):
        try:
            self.value = self.work(self.report)
        except Exception as error:  # handed to the GUI thread, which raises or reports it
            self.error = error
