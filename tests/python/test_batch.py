"""cadmedial.batch on Dask: the summary's contents against the files written, resume and --force,
and each fault a part can have (bad file, hang, crash, out of memory) recorded while the run goes
on. Most tests share one in-process cluster (a Client passed in); test_scheduler_address runs the
default local cluster and a separate one given by its address."""

import csv
import json
import os
import shutil
import subprocess
import sys
import time

import pytest

distributed = pytest.importorskip("distributed")

import cadmedial  # noqa: E402
from cadmedial.batch import outputs  # noqa: E402

from conftest import DATA, REPO, SAMPLES  # noqa: E402

NIST_11 = os.path.join(REPO, "examples", "data", "nist_ftc_11_asme1_rb.stp")


@pytest.fixture(scope="module")
def client():
    # Threads in this process (processes=False) start in a fraction of a second; each part still
    # runs in its own child process, which is what the limits apply to.
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=False,
                                       dashboard_address=None)
    c = distributed.Client(cluster)
    yield c
    c.close()
    cluster.close()


@pytest.fixture
def parts(tmp_path):
    """A folder of three good parts and two bad ones, copied so that tests may touch them."""
    folder = tmp_path / "in"
    folder.mkdir()
    for name in ("box_10x20x30.step", "l_bracket.brep", "two_cubes.brep", "square_face.brep"):
        shutil.copy(os.path.join(DATA, name), folder / name)
    (folder / "corrupt.step").write_text("ISO-10303-21;\nthis is not a STEP file\n")
    (folder / "notes.txt.bak").write_text("not a CAD file: not searched for\n")
    return folder


def rows(out_dir):
    with open(os.path.join(out_dir, "summary.csv"), newline="") as f:
        return {r["part"]: r for r in csv.DictReader(f)}


def mesh_mtimes(out_dir):
    found = {}
    for root, _, files in os.walk(os.path.join(out_dir, outputs.PARTS)):
        for f in files:
            if f.endswith(".ply"):
                found[f] = os.stat(os.path.join(root, f)).st_mtime_ns
    return found


def test_summary_matches_outputs(parts, tmp_path, client, cli):
    out = tmp_path / "out"
    result = cadmedial.batch(parts, out, client=client, samples=SAMPLES, cli=cli, progress=False)
    table = rows(out)
    assert sorted(table) == ["in/box_10x20x30.step", "in/corrupt.step", "in/l_bracket.brep",
                             "in/square_face.brep", "in/two_cubes.brep"]
    assert result.counts == {"ok": 3, "refused": 2}
    with open(out / "summary.json") as f:
        assert {r["part"]: r["status"] for r in json.load(f)["parts"]} == {k: v["status"] for k, v in table.items()}
    for name in ("in/box_10x20x30.step", "in/l_bracket.brep", "in/two_cubes.brep"):
        row = table[name]
        mesh = cadmedial.load(outputs.mesh_path(str(out), name, "ply"))
        with open(outputs.stats_path(str(out), name)) as f:
            stats = json.load(f)
        assert row["status"] == "ok" and row["message"] == ""
        assert int(row["vertices"]) == mesh.num_vertices == stats["vertices"]
        assert int(row["faces"]) == mesh.num_faces == stats["faces"]
        assert int(row["samples"]) == stats["samples"]
        assert int(row["solids"]) == len(stats["solids"]) == len(set(mesh.face_solid.tolist()))
        # Boxes and their unions: the axis has the solid's topology at this density.
        assert row["topology_right"] == "True"
        assert 0 < float(row["peak_memory_mb"]) < 8 * 1024
    assert table["in/two_cubes.brep"]["solids"] == "2"


def test_bad_files_are_recorded_with_their_error(parts, tmp_path, client, cli):
    out = tmp_path / "out"
    cadmedial.batch(parts, out, client=client, samples=SAMPLES, cli=cli, progress=False)
    table = rows(out)
    assert table["in/square_face.brep"]["status"] == "refused"
    assert "does not sew into closed shells" in table["in/square_face.brep"]["message"]
    assert table["in/corrupt.step"]["status"] == "refused"
    assert str(parts / "corrupt.step") in table["in/corrupt.step"]["message"]
    for name in ("in/square_face.brep", "in/corrupt.step"):
        assert not os.path.exists(outputs.mesh_path(str(out), name, "ply"))
        with open(outputs.log_path(str(out), name)) as f:
            assert "cadmedial: error:" in f.read()


def test_resume_skips_done_parts_and_redoes_a_newer_input(parts, tmp_path, client, cli):
    out = tmp_path / "out"
    cadmedial.batch(parts, out, client=client, samples=SAMPLES, cli=cli, progress=False)
    before = mesh_mtimes(out)
    second = cadmedial.batch(parts, out, client=client, samples=SAMPLES, cli=cli, progress=False)
    resumed = {r["part"] for r in second.records if r.get("resumed")}
    assert resumed == {"in/box_10x20x30.step", "in/l_bracket.brep", "in/two_cubes.brep"}
    assert mesh_mtimes(out) == before
    # The failed ones are tried again: they have no outputs.
    assert {r["part"] for r in second.records if not r.get("resumed")} == {"in/corrupt.step", "in/square_face.brep"}
    # An input edited after its outputs is redone, and only it.
    later = os.stat(out / "summary.csv").st_mtime + 10
    os.utime(parts / "l_bracket.brep", (later, later))
    third = cadmedial.batch(parts, out, client=client, samples=SAMPLES, cli=cli, progress=False)
    assert {r["part"] for r in third.records if r["status"] == "ok" and not r.get("resumed")} == {"in/l_bracket.brep"}
    after = mesh_mtimes(out)
    assert after["l_bracket.brep.ply"] > before["l_bracket.brep.ply"]
    assert after["box_10x20x30.step.ply"] == before["box_10x20x30.step.ply"]


def test_other_options_redo_and_force_redoes(parts, tmp_path, client, cli):
    out = tmp_path / "out"
    first = cadmedial.batch(parts, out, client=client, samples=SAMPLES, cli=cli, progress=False)
    before = mesh_mtimes(out)
    forced = cadmedial.batch(parts, out, client=client, samples=SAMPLES, cli=cli, force=True, progress=False)
    assert not any(r.get("resumed") for r in forced.records)
    after = mesh_mtimes(out)
    assert all(after[k] > before[k] for k in before)
    # Same meshes again (the engine is deterministic): same counts in the summary.
    counts = lambda res: {r["part"]: (r["status"], r.get("vertices"), r.get("faces")) for r in res.records}
    assert counts(forced) == counts(first)
    # A different density is not "done": the parts are computed again, with more samples.
    denser = cadmedial.batch(parts, out, client=client, samples=2 * SAMPLES, cli=cli, progress=False)
    assert not any(r.get("resumed") for r in denser.records)
    box = lambda res: next(r for r in res.records if r["part"] == "in/box_10x20x30.step")
    assert box(denser)["samples"] > 1.5 * box(first)["samples"]


def test_the_minimum_feature_size_reaches_each_part(parts, tmp_path, client, cli):
    # The 10-thick box at spacing 6 is sampled finer at its walls; with a minimum feature of 12
    # it is not (test_compute): the batch hands the option on, and the warning reaches the summary.
    out = tmp_path / "out"
    plain = cadmedial.batch(parts, out / "plain", client=client, spacing=6.0, cli=cli, progress=False)
    limited = cadmedial.batch(parts, out / "limited", client=client, spacing=6.0, min_feature=12.0, cli=cli,
                              progress=False)
    box = lambda res: next(r for r in res.records if r["part"] == "in/box_10x20x30.step")
    assert box(limited)["status"] == "ok"
    assert box(limited)["samples"] < box(plain)["samples"] / 2
    with pytest.raises(cadmedial.InvalidInput):
        cadmedial.batch(parts, out / "bad", client=client, min_feature=-1, cli=cli, progress=False)


def faulty_cli(tmp_path, real):
    """A cadmedial program that hangs on parts named hang*, segfaults on crash*, and is the real
    one otherwise: the faults of issue 36's benchmark, on purpose."""
    script = tmp_path / "faulty-cadmedial"
    script.write_text("""#!/bin/sh
case "$2" in
  */hang*) echo $$ > "%s/hang.pid"; sleep 300 ;;
  */crash*) kill -SEGV $$ ;;
esac
exec "%s" "$@"
""" % (tmp_path, real))
    script.chmod(0o755)
    return str(script)


def test_a_hanging_part_times_out_and_the_run_goes_on(tmp_path, client, cli):
    folder = tmp_path / "in"
    folder.mkdir()
    shutil.copy(os.path.join(DATA, "box_10x20x30.step"), folder / "box.step")
    shutil.copy(os.path.join(DATA, "box_10x20x30.step"), folder / "hang.step")
    out = tmp_path / "out"
    result = cadmedial.batch(folder, out, client=client, samples=SAMPLES, timeout=3,
                             cli=faulty_cli(tmp_path, cli), progress=False)
    by = {r["part"]: r for r in result.records}
    assert by["in/hang.step"]["status"] == "timeout"
    assert "3 s time limit" in by["in/hang.step"]["message"]
    assert 3 <= by["in/hang.step"]["time_s"] < 30
    assert by["in/box.step"]["status"] == "ok"
    # The hung program was killed with its process group, not left behind.
    pid = int((tmp_path / "hang.pid").read_text())
    with pytest.raises(ProcessLookupError):
        os.kill(pid, 0)


def test_a_crashing_part_is_recorded(tmp_path, client, cli):
    folder = tmp_path / "in"
    folder.mkdir()
    shutil.copy(os.path.join(DATA, "box_10x20x30.step"), folder / "crash.step")
    shutil.copy(os.path.join(DATA, "l_bracket.brep"), folder / "l_bracket.brep")
    result = cadmedial.batch(folder, tmp_path / "out", client=client, samples=SAMPLES,
                             cli=faulty_cli(tmp_path, cli), progress=False)
    by = {r["part"]: r for r in result.records}
    assert by["in/crash.step"]["status"] == "crashed"
    assert "SIGSEGV" in by["in/crash.step"]["message"]
    assert by["in/l_bracket.brep"]["status"] == "ok"


def test_a_part_past_the_memory_limit_is_recorded(tmp_path, client, cli):
    # NIST FTC 11 at the default density peaks at about 110 MB resident (its stats); under a
    # 0.1 GB address-space limit the engine's allocations fail (where depends on the run: a
    # thread's stack, OpenCASCADE's allocator, new) and it says so.
    out = tmp_path / "out"
    result = cadmedial.batch(NIST_11, out, client=client, memory=0.1, cli=cli, progress=False)
    by = {r["part"]: r for r in result.records}
    nist = by["nist_ftc_11_asme1_rb.stp"]
    assert nist["status"] == "out_of_memory"
    assert "0.1 GB memory limit" in nist["message"]
    assert nist["peak_memory_mb"] < 0.1 * 1024
    assert not os.path.exists(outputs.mesh_path(str(out), "nist_ftc_11_asme1_rb.stp", "ply"))


def test_an_analysis_that_is_not_installed_is_refused_before_any_part(tmp_path, cli, monkeypatch):
    from cadmedial.batch import analyses
    monkeypatch.setitem(analyses.KNOWN, "thickness", analyses.AnalysisSpec(
        "cadmedial.no_such_analysis", "the wall-thickness analysis (issue 34)", ("min", "max")))
    with pytest.raises(cadmedial.InvalidInput, match="not in this version"):
        cadmedial.batch(os.path.join(DATA, "box_10x20x30.step"), tmp_path / "out", thickness={"min": 0.8},
                        cli=cli, progress=False)
    assert not (tmp_path / "out" / "summary.csv").exists()


COMPARED = ("part", "status", "message", "solids", "samples", "vertices", "faces", "edges",
            "topology_right", "thinnest_wall", "thinnest_wall_at")


def test_a_scheduler_address_gives_the_same_summary(parts, tmp_path, cli):
    local = cadmedial.batch(parts, tmp_path / "local", jobs=2, samples=SAMPLES, cli=cli, progress=False)
    # Worker processes of their own, as `dask scheduler` / `dask worker` on other machines.
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                       dashboard_address=None)
    try:
        remote = cadmedial.batch(parts, tmp_path / "remote", scheduler=cluster.scheduler_address,
                                 samples=SAMPLES, cli=cli, progress=False)
        workers = set(cluster.scheduler_info["workers"])
    finally:
        cluster.close()
    assert len(workers) == 2
    pick = lambda res: [{k: r.get(k) for k in COMPARED} for r in res.records]
    assert pick(remote) == pick(local)
    assert rows(tmp_path / "remote").keys() == rows(tmp_path / "local").keys()


def test_a_killed_worker_takes_its_part_with_it(tmp_path):
    # A stand-in for a Dask worker: a Python process running one part (a program that would run
    # for 5 minutes) under run_limited, killed with SIGKILL as a lost node would be.
    pid_file = tmp_path / "part.pid"
    worker = subprocess.Popen([sys.executable, "-c", """
import sys
from cadmedial.batch.limits import run_limited
run_limited(["sh", "-c", "echo $$ > %s; exec sleep 300"], timeout=600)
""" % pid_file])
    for _ in range(200):
        if pid_file.exists() and pid_file.read_text().strip():
            break
        time.sleep(0.05)
    part = int(pid_file.read_text())
    worker.kill()
    worker.wait()
    for _ in range(100):  # the kernel delivers the parent-death signal at once; allow for load
        try:
            os.kill(part, 0)
        except ProcessLookupError:
            break
        time.sleep(0.05)
    with pytest.raises(ProcessLookupError):
        os.kill(part, 0)
