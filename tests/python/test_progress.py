"""The progress callback: reports stages, cancels, and carries Python exceptions out; the GIL is
free while the engine works."""

import threading
import time

import pytest

import cadmedial
from conftest import SAMPLES


def test_progress_reports_stages_with_fractions_in_unit_interval(box_step):
    calls = []
    cadmedial.compute(box_step, samples=SAMPLES, progress=lambda s, f: calls.append((s, f)) or True)
    assert calls
    assert all(isinstance(s, str) and s for s, _ in calls)
    assert all(0.0 <= f <= 1.0 for _, f in calls)


def test_returning_none_continues(box_step):
    calls = []
    r = cadmedial.compute(box_step, samples=SAMPLES, progress=lambda s, f: calls.append(s))
    assert r.num_faces > 0 and calls


def test_returning_false_cancels_at_once(box_step):
    calls = []

    def stop(stage, fraction):
        calls.append(stage)
        return False

    with pytest.raises(cadmedial.Cancelled):
        cadmedial.compute(box_step, samples=SAMPLES, progress=stop)
    assert len(calls) == 1  # no work reported after the cancel


def test_cancel_midway_stops_the_work(box_step):
    # Cancelled at the selection, after sampling and the triangulation. (How many times sampling
    # reports depends on timing: it reports while it waits for its second thread. Counting the
    # calls of one run to cancel half way through the next failed on a loaded machine.)
    total = []
    cadmedial.compute(box_step, samples=SAMPLES, progress=lambda s, f: total.append(s))
    assert "selection" in total and total.index("selection") < len(total) - 2
    calls = []

    def stop_at_selection(stage, fraction):
        calls.append(stage)
        return stage != "selection"

    with pytest.raises(cadmedial.Cancelled):
        cadmedial.compute(box_step, samples=SAMPLES, progress=stop_at_selection)
    assert calls[-1] == "selection" and calls.count("selection") == 1  # nothing reported after
    assert "inner" not in calls and "done" not in calls


def test_exception_in_callback_cancels_and_propagates_unchanged(box_step):
    error = KeyError("raised by the callback")
    calls = []

    def fail(stage, fraction):
        calls.append(stage)
        raise error

    with pytest.raises(KeyError) as raised:
        cadmedial.compute(box_step, samples=SAMPLES, progress=fail)
    assert raised.value is error
    assert len(calls) == 1


def test_engine_still_works_after_a_cancel(box_step):
    with pytest.raises(cadmedial.Cancelled):
        cadmedial.compute(box_step, samples=SAMPLES, progress=lambda s, f: False)
    assert cadmedial.compute(box_step, samples=SAMPLES).num_faces > 0


def test_gil_is_released_while_computing(box_step):
    # While a thread computes, this thread keeps running Python. With the GIL held through the
    # engine, it would stall until the compute returns.
    window = {}

    def work():
        window["start"] = time.monotonic()
        cadmedial.compute(box_step, samples=20000)
        window["end"] = time.monotonic()

    worker = threading.Thread(target=work)
    ticks = []
    worker.start()
    while worker.is_alive():
        ticks.append(time.monotonic())
        time.sleep(0.001)
    worker.join()
    duration = window["end"] - window["start"]
    inside = [t for t in ticks if window["start"] < t < window["end"]]
    assert duration > 0.05, "compute too fast to observe (%.3f s)" % duration
    # Ticks every ~1 ms. Held through the engine, the GIL would let this thread in only at the
    # ~20 progress callbacks; a tenth of the possible ticks leaves room for a loaded machine.
    assert len(inside) >= 0.1 * duration / 0.001
