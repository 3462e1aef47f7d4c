"""The Python API and the cadmedial program give the same medial axis for the same input."""

import json
import subprocess

import pytest

import cadmedial
from conftest import SAMPLES, assert_same_mesh


def ply_counts(path):
    """(vertices, faces, edges) from a PLY header, read without the engine's reader."""
    counts = {}
    with open(path, "rb") as f:
        for line in f:
            words = line.decode("ascii").split()
            if words[:1] == ["element"]:
                counts[words[1]] = int(words[2])
            if words == ["end_header"]:
                break
    return counts["vertex"], counts["face"], counts["edge"]


@pytest.mark.parametrize("name", ["box_10x20x30.step", "l_bracket.brep", "two_cubes.brep",
                                  "torus_10_3.brep"])
def test_python_matches_cli(cli, data, tmp_path, name):
    source = data(name)
    ply, stats = tmp_path / "out.ply", tmp_path / "stats.json"
    run = subprocess.run([cli, "compute", source, "-o", str(ply), "--samples", str(SAMPLES),
                          "--theta", "5", "--rho", "8", "--stats", str(stats), "--quiet"],
                         capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr
    ours = cadmedial.compute(source, samples=SAMPLES, theta=5.0, rho=8.0)

    assert ply_counts(ply) == (ours.num_vertices, ours.num_faces, ours.num_edges)
    assert_same_mesh(cadmedial.load(ply), ours)
    cli_stats = json.loads(stats.read_text())
    for key in ("samples", "vertices", "faces", "edges"):
        assert cli_stats[key] == ours.stats[key], key
    assert cli_stats["spacing"] == pytest.approx(ours.stats["spacing"], rel=1e-9)


def test_cli_and_python_reject_the_same_non_solid(cli, data, tmp_path):
    source = data("square_face.brep")
    run = subprocess.run([cli, "compute", source, "-o", str(tmp_path / "x.ply"), "--quiet"],
                         capture_output=True, text=True, timeout=120)
    assert run.returncode == 2
    with pytest.raises(cadmedial.InvalidInput):
        cadmedial.compute(source)
    assert not (tmp_path / "x.ply").exists()
