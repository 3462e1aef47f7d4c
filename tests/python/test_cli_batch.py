"""`cadmedial batch` through the C++ program: it hands over to python3 -m cadmedial.batch, finds
the package from the build tree, and keeps the program's exit statuses and one-line errors."""

import csv
import os
import subprocess

import pytest

pytest.importorskip("distributed")

from conftest import DATA, SAMPLES  # noqa: E402


def run(cli, *args):
    # Not the test's PYTHONPATH: the program must find the package itself.
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "CADMEDIAL_CORE_DIR")}
    return subprocess.run([cli, "batch", *args], capture_output=True, text=True, env=env, timeout=300)


def test_help_lists_the_batch_options(cli):
    p = run(cli, "--help")
    assert p.returncode == 0
    for option in ("--jobs", "--scheduler", "--timeout", "--memory", "--force", "--thickness"):
        assert option in p.stdout


def test_a_missing_input_is_one_error_line(cli, tmp_path):
    p = run(cli, str(tmp_path / "nothing.step"), "-o", str(tmp_path / "out"))
    assert p.returncode == 2
    assert p.stderr.splitlines() == ["cadmedial: error: batch: %s: no such file or folder" % (tmp_path / "nothing.step")]


def test_thickness_adds_its_columns_and_files(cli, tmp_path):
    # The 10 x 20 x 30 box: walls 10 thick, so a 12 minimum fails it, found thin; its medial
    # axis is still computed ("ok"): the thickness is a result, not a failure.
    out = tmp_path / "out"
    p = run(cli, os.path.join(DATA, "box_10x20x30.step"), "-o", str(out), "--jobs", "1",
            "--samples", str(SAMPLES), "--thickness", "--min", "12")
    assert p.returncode == 0, p.stderr
    with open(out / "summary.csv", newline="") as f:
        row = next(csv.DictReader(f))
    assert row["status"] == "ok"
    assert row["thickness_passed"] == "False"
    assert abs(float(row["thickness_max"]) - 10.0) < 0.1
    assert int(row["thin_regions"]) >= 1
    assert (out / "parts" / "box_10x20x30.step_thickness.json").is_file()
    assert (out / "parts" / "box_10x20x30.step_thickness_regions.csv").is_file()


def test_a_batch_with_a_bad_part_exits_3_with_the_summary(cli, tmp_path):
    out = tmp_path / "out"
    p = run(cli, os.path.join(DATA, "box_10x20x30.step"), os.path.join(DATA, "square_face.brep"),
            "-o", str(out), "--jobs", "1", "--samples", str(SAMPLES))
    assert p.returncode == 3, p.stderr
    with open(out / "summary.csv", newline="") as f:
        table = {r["part"]: r for r in csv.DictReader(f)}
    assert table["box_10x20x30.step"]["status"] == "ok"
    assert table["square_face.brep"]["status"] == "refused"
    assert "2 parts in" in p.stderr and "1 ok, 1 refused" in p.stderr
