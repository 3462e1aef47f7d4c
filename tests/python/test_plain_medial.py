"""compute(plain_medial=True): the paper's plain MEDIAL (section 3) on the same samples as
CAD_MEDIAL, for the ablation. The paper runs MEDIAL with theta = pi/8; like the program's
--plain-medial, the switch leaves theta to the caller."""

import json
import subprocess

import numpy as np
import pytest

import cadmedial
from conftest import SAMPLES, assert_same_mesh
from test_cli_agreement import ply_counts

PAPER_THETA = 22.5


def test_plain_medial_samples_the_solid_exactly_as_cad_medial(box_step):
    cad = cadmedial.compute(box_step, samples=SAMPLES)
    plain = cadmedial.compute(box_step, samples=SAMPLES, theta=PAPER_THETA, plain_medial=True)
    # The switch is in the medial stage only: the same spacing, hence the same samples.
    assert plain.stats["spacing"] == cad.stats["spacing"]
    assert plain.stats["samples"] == cad.stats["samples"]


def test_plain_medial_has_no_completion_faces(box_step):
    cad = cadmedial.compute(box_step, samples=SAMPLES)
    plain = cadmedial.compute(box_step, samples=SAMPLES, theta=PAPER_THETA, plain_medial=True)
    # A box has 12 convex edges and 8 corners: CAD_MEDIAL closes them with completion faces
    # (4.2.2, 4.2.3); plain MEDIAL does not, every face is a Voronoi facet.
    assert (cad.face_kind == cadmedial.FaceKind.EDGE).any()
    assert plain.num_faces > 0
    assert (plain.face_kind == cadmedial.FaceKind.VORONOI).all()


def test_plain_medial_default_is_cad_medial(box_step):
    default = cadmedial.compute(box_step, samples=SAMPLES)
    explicit = cadmedial.compute(box_step, samples=SAMPLES, plain_medial=False)
    assert_same_mesh(default, explicit)


def test_python_plain_medial_matches_cli(cli, data, tmp_path):
    source = data("l_bracket.brep")
    ply, stats = tmp_path / "plain.ply", tmp_path / "plain.json"
    run = subprocess.run([cli, "compute", source, "-o", str(ply), "--samples", str(SAMPLES),
                          "--theta", str(PAPER_THETA), "--plain-medial", "--stats", str(stats),
                          "--quiet"], capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr
    ours = cadmedial.compute(source, samples=SAMPLES, theta=PAPER_THETA, plain_medial=True)
    assert ply_counts(ply) == (ours.num_vertices, ours.num_faces, ours.num_edges)
    cli_stats = json.loads(stats.read_text())
    for key in ("samples", "vertices", "faces"):
        assert cli_stats[key] == ours.stats[key], key
    assert_same_mesh(cadmedial.load(ply), ours)


@pytest.mark.parametrize("value", ["no", 1, None, 0.0])
def test_plain_medial_must_be_a_bool(box_step, value):
    with pytest.raises(cadmedial.InvalidInput, match="plain_medial"):
        cadmedial.compute(box_step, samples=SAMPLES, plain_medial=value)


def test_numpy_bool_is_accepted(box_step):
    r = cadmedial.compute(box_step, samples=SAMPLES, theta=PAPER_THETA, plain_medial=np.bool_(True))
    assert (r.face_kind == cadmedial.FaceKind.VORONOI).all()
