"""`cadmedial thickness` (the C++ program dispatching to python -m cadmedial.thickness): exit 0
pass, 3 out of limits, 2 bad input; its files."""

import csv
import os
import shutil
import subprocess
import sys

import pytest

from conftest import rib_on_plate

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, os.pardir, os.pardir))


def commands():
    out = [[sys.executable, "-m", "cadmedial.thickness"]]
    cli = os.environ.get("CADMEDIAL_CLI") or os.path.join(REPO, "build", "cadmedial")
    if os.path.isfile(cli) and os.access(cli, os.X_OK):
        out.append([cli, "thickness"])
    return out


@pytest.fixture(scope="module")
def rib_brep(tmp_path_factory):
    path = str(tmp_path_factory.mktemp("rib") / "rib.brep")
    rib_on_plate().exportBrep(path)
    return path


def run(cmd, *args):
    return subprocess.run(cmd + list(args), capture_output=True, text=True, timeout=600)


@pytest.mark.parametrize("cmd", commands(), ids=lambda c: os.path.basename(c[0]))
def test_exit_status_says_pass_or_fail(cmd, rib_brep):
    assert run(cmd, rib_brep, "--min", "0.5", "--quiet").returncode == 0
    failed = run(cmd, rib_brep, "--min", "1.5")
    assert failed.returncode == 3, failed.stderr
    assert "FAIL" in failed.stdout and "Face" in failed.stdout
    assert run(cmd, rib_brep, "--min", "0.5", "--max", "3", "--quiet").returncode == 3


@pytest.mark.parametrize("args", [["--min", "1", "--max", "0.5"], ["--min", "-1"], ["--min", "x"],
                                  [], ["--min", "1", "--corners", "round"],
                                  ["--min", "1", "-o", "values.txt"]])
def test_bad_options_exit_2_with_one_line(rib_brep, args):
    r = run(commands()[-1], rib_brep, *args)
    assert r.returncode == 2
    assert r.stderr.startswith("cadmedial: error:") and r.stderr.count("\n") == 1


def test_bad_input_exits_2(tmp_path):
    cmd = commands()[-1]
    assert run(cmd, str(tmp_path / "missing.step"), "--min", "1").returncode == 2
    face = tmp_path / "face.brep"
    import Part
    Part.makePlane(10, 10).exportBrep(str(face))
    r = run(cmd, str(face), "--min", "1")
    assert r.returncode == 2 and "no closed solid" in r.stderr


def test_files_hold_the_values_and_regions(rib_brep, tmp_path):
    v, rep, reg = (str(tmp_path / n) for n in ("v.csv", "r.html", "regions.csv"))
    r = run(commands()[-1], rib_brep, "--min", "1.5", "-o", v, "--report", rep,
            "--regions-csv", reg, "--quiet")
    assert r.returncode == 3, r.stderr
    with open(v) as f:
        rows = list(csv.DictReader(f))
    assert len(rows) > 1000 and {"x", "y", "z", "thickness", "counted"} <= set(rows[0])
    with open(reg) as f:
        regions = list(csv.DictReader(f))
    big = [g for g in regions if float(g["area"]) > 10]
    assert len(big) == 2 and all(abs(float(g["extreme"]) - 1.0) < 0.05 for g in big)
    html = open(rep).read()
    assert "FAIL" in html and "data:image/png;base64," in html
