"""batch(stop=..., on_progress=...) and cadmedial.batch.pipe, the hooks the FreeCAD dialog drives.
A stop ends the run early (a part that would run for 5 minutes is killed with the local cluster),
the unfinished parts are recorded "stopped", and the finished ones keep their outputs."""

import csv
import json
import os
import shutil
import subprocess
import sys
import threading
import time

import pytest

distributed = pytest.importorskip("distributed")

import cadmedial  # noqa: E402
from cadmedial.batch import outputs  # noqa: E402
from cadmedial.batch.status import STOPPED_MESSAGE  # noqa: E402

from conftest import DATA, SAMPLES  # noqa: E402


def hanging_cli(tmp_path, real):
    """The real program, except on parts named hang*: there it becomes a 5-minute sleep (exec, so
    that the part's process is the sleep and a kill of the part is a kill of it)."""
    script = tmp_path / "hanging-cadmedial"
    script.write_text("""#!/bin/sh
case "$2" in
  */hang*) echo $$ > "%s/hang.pid"; exec sleep 300 ;;
esac
exec "%s" "$@"
""" % (tmp_path, real))
    script.chmod(0o755)
    return str(script)


def alive(pid):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    return True


def test_a_stop_ends_the_run_early_keeping_finished_parts(tmp_path, cli):
    folder = tmp_path / "in"
    folder.mkdir()
    # The box is the bigger file: it is submitted first, so with one worker it finishes first.
    shutil.copy(os.path.join(DATA, "box_10x20x30.step"), folder / "box.step")
    shutil.copy(os.path.join(DATA, "box_10x20x30.brep"), folder / "hang.brep")
    assert os.path.getsize(folder / "box.step") > os.path.getsize(folder / "hang.brep")
    stop = threading.Event()
    updates = []

    def on_progress(update):
        updates.append(update)
        # The stop comes once the box is done and the hanging part has started (its pid written).
        if update.record is not None and update.record["part"] == "in/box.step":
            threading.Thread(target=lambda: (wait_for(tmp_path / "hang.pid"), stop.set())).start()

    out = tmp_path / "out"
    start = time.monotonic()
    result = cadmedial.batch(folder, out, jobs=1, samples=SAMPLES, timeout=0, cli=hanging_cli(tmp_path, cli),
                             progress=False, on_progress=on_progress, stop=stop)
    seconds = time.monotonic() - start
    assert stop.is_set()
    assert seconds < 120  # the hanging part alone would take 300 s
    by = {r["part"]: r for r in result.records}
    assert by["in/box.step"]["status"] == "ok"
    assert by["in/hang.brep"]["status"] == "stopped"
    assert by["in/hang.brep"]["message"] == STOPPED_MESSAGE
    assert result.counts == {"ok": 1, "stopped": 1}
    # The finished part's outputs are kept; the stopped one has none and no record (a rerun redoes it).
    assert cadmedial.load(outputs.mesh_path(str(out), "in/box.step", "ply")).num_faces > 0
    assert not os.path.exists(outputs.mesh_path(str(out), "in/hang.brep", "ply"))
    assert not os.path.exists(outputs.record_path(str(out), "in/hang.brep"))
    with open(out / "summary.csv", newline="") as f:
        assert {r["part"]: r["status"] for r in csv.DictReader(f)} == {"in/box.step": "ok", "in/hang.brep": "stopped"}
    # The hanging part's process went with the cluster.
    pid = int((tmp_path / "hang.pid").read_text())
    for _ in range(100):
        if not alive(pid):
            break
        time.sleep(0.1)
    assert not alive(pid)
    # on_progress saw the box finish: done 1 of 2, none failed.
    finished = [u for u in updates if u.record is not None]
    assert [(u.done, u.failed, u.total, u.record["status"]) for u in finished] == [(1, 0, 2, "ok")]
    assert any(u.message.startswith("stopped:") for u in updates)
    # A rerun resumes: the box is skipped, the stopped part runs (here: the real program).
    again = cadmedial.batch(folder, out, jobs=1, samples=SAMPLES, cli=cli, progress=False)
    assert {r["part"]: (r["status"], bool(r.get("resumed"))) for r in again.records} == {
        "in/box.step": ("ok", True), "in/hang.brep": ("ok", False)}


def test_a_stop_before_the_start_runs_nothing(tmp_path, cli):
    updates = []
    result = cadmedial.batch(os.path.join(DATA, "box_10x20x30.step"), tmp_path / "out", samples=SAMPLES,
                             cli=cli, progress=False, on_progress=updates.append, stop=lambda: True)
    assert [(r["part"], r["status"]) for r in result.records] == [("box_10x20x30.step", "stopped")]
    assert not os.path.exists(outputs.mesh_path(str(tmp_path / "out"), "box_10x20x30.step", "ply"))
    assert (tmp_path / "out" / "summary.json").exists()


def test_a_stop_that_is_neither_event_nor_function_is_refused(tmp_path, cli):
    with pytest.raises(cadmedial.InvalidInput, match="stop must be"):
        cadmedial.batch(os.path.join(DATA, "box_10x20x30.step"), tmp_path / "out", cli=cli, progress=False,
                        stop="yes")


def wait_for(path, seconds=60):
    end = time.monotonic() + seconds
    while not (os.path.exists(path) and open(path).read().strip()):
        if time.monotonic() > end:
            return
        time.sleep(0.05)


def test_the_pipe_reports_updates_and_stops_on_a_line(tmp_path, cli):
    # cadmedial.batch.pipe, as the FreeCAD dialog drives it: JSON lines out, "stop" in.
    folder = tmp_path / "in"
    folder.mkdir()
    shutil.copy(os.path.join(DATA, "box_10x20x30.step"), folder / "box.step")
    shutil.copy(os.path.join(DATA, "box_10x20x30.brep"), folder / "hang.brep")
    request = {"inputs": [str(folder)], "out_dir": str(tmp_path / "out"),
               "options": {"jobs": 1, "samples": SAMPLES, "timeout": 0, "cli": hanging_cli(tmp_path, cli)}}
    child = subprocess.Popen([sys.executable, "-m", "cadmedial.batch.pipe"], stdin=subprocess.PIPE,
                             stdout=subprocess.PIPE, text=True)
    child.stdin.write(json.dumps(request) + "\n")
    child.stdin.flush()
    messages = []
    for line in child.stdout:
        messages.append(json.loads(line))
        update = messages[-1].get("update")
        if update and update[3] and update[3]["part"] == "in/box.step":
            wait_for(tmp_path / "hang.pid")
            child.stdin.write("stop\n")
            child.stdin.flush()
    assert child.wait(timeout=120) == 0
    result = messages[-1]["result"]
    assert result["counts"] == {"ok": 1, "stopped": 1}
    assert [m["update"][:3] for m in messages if "update" in m and m["update"][3]] == [[1, 0, 2]]
    # The hanging part's process went with the child's cluster.
    pid = int((tmp_path / "hang.pid").read_text())
    for _ in range(100):
        if not alive(pid):
            break
        time.sleep(0.1)
    assert not alive(pid)


def test_the_pipe_says_a_bad_argument_in_one_line(tmp_path):
    child = subprocess.run([sys.executable, "-m", "cadmedial.batch.pipe"], capture_output=True, text=True,
                           input=json.dumps({"inputs": [str(tmp_path / "missing.step")],
                                             "out_dir": str(tmp_path / "out"), "options": {}}) + "\n")
    assert child.returncode == 2
    assert "missing.step" in json.loads(child.stdout.splitlines()[-1])["error"]
