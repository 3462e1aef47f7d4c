"""The bad-input corpus of tests/data/bad/ (README.md there) through the CLI and through Python.

Each input gives either a correct medial axis or a refusal: exit status 2 with one line
`cadmedial: error: ...` naming the problem and no output file (CLI), InvalidInput with the same
message (Python). Never a signal, never a partial file.
"""

import os
import subprocess

import numpy as np
import pytest

import cadmedial

HERE = os.path.dirname(os.path.abspath(__file__))
BAD = os.path.normpath(os.path.join(HERE, os.pardir, "data", "bad"))
BOX = os.path.join(HERE, "data", "box_10x20x30.brep")
SAMPLES = 3000


def bad(name):
    return os.path.join(BAD, name)


def run_cli(cli, *args):
    return subprocess.run([cli, *args], capture_output=True, text=True, timeout=300)


def assert_refused(run, fragment, out_dir):
    assert run.returncode == 2, (run.returncode, run.stderr)  # a signal would be negative
    lines = run.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("cadmedial: error: "), run.stderr
    assert fragment in lines[0], lines[0]
    assert run.stdout == ""
    assert os.listdir(out_dir) == []  # no output, no temporary file


# file, what the message must say
REFUSED = [
    ("empty.step", "the file is empty"),
    ("truncated.step", "truncated.step"),
    ("wire_only.step", "holds no solid"),
    ("face_only.step", "the shell is open"),
    ("open_shell.brep", "the shell is open"),
    ("two_faces_apart.brep", "loose faces"),
    ("nonmanifold_edge.brep", "non-manifold"),
    ("self_intersecting.brep", "invalid"),
    ("zero_volume.brep", "zero volume"),
    ("degenerate_edge.brep", "edge 13 is bounded by 1 face"),
    ("fuzz/oom_unterminated_subshape_list.brep", "not valid BREP"),
]


@pytest.mark.parametrize("name, fragment", REFUSED, ids=[r[0] for r in REFUSED])
def test_cli_refuses_bad_file(cli, tmp_path, name, fragment):
    out = tmp_path / "out"
    out.mkdir()
    run = run_cli(cli, "compute", bad(name), "-o", str(out / "axis.ply"), "--samples", str(SAMPLES),
                  "--stats", str(out / "stats.json"), "--quiet")
    assert_refused(run, fragment, out)


@pytest.mark.parametrize("name, fragment", REFUSED, ids=[r[0] for r in REFUSED])
def test_python_refuses_bad_file(name, fragment):
    with pytest.raises(cadmedial.InvalidInput) as raised:
        cadmedial.compute(bad(name), samples=SAMPLES)
    assert fragment in str(raised.value)


@pytest.mark.parametrize("name, fragment", [r for r in REFUSED if r[0].endswith(".brep")],
                         ids=[r[0] for r in REFUSED if r[0].endswith(".brep")])
def test_python_refuses_bad_brep_text(name, fragment):
    with open(bad(name)) as f:
        text = f.read()
    with pytest.raises(cadmedial.InvalidInput) as raised:
        cadmedial.compute(text, samples=SAMPLES)
    assert fragment in str(raised.value)


# ---- inputs that are legitimate: each gives a correct medial axis ----------------------------

def box_axis_facts(result, sides):
    """A box's medial axis: radius in (0, min side / 2], the largest about min side / 2, every
    vertex inside the box, and the axis spanning the box's longest side (it reaches the corners)."""
    sides = np.asarray(sides, float)
    tol = 2.5 * result.stats["spacing"]
    assert result.num_vertices > 0 and result.num_faces > 0
    assert np.all(np.isfinite(result.vertices)) and np.all(np.isfinite(result.radius))
    assert result.radius.min() >= 0
    assert result.radius.max() == pytest.approx(sides.min() / 2, abs=tol)
    assert result.radius.max() <= sides.min() / 2 + tol
    assert np.all(result.vertices >= -1e-9 * sides.max()) and np.all(result.vertices <= sides * (1 + 1e-9))
    np.testing.assert_allclose(np.ptp(result.vertices, axis=0), sides, atol=tol)


@pytest.mark.parametrize("name, scale", [("tiny_box.brep", 1e-6), ("huge_box.brep", 1e6)])
def test_scale_does_not_matter(name, scale):
    result = cadmedial.compute(bad(name), samples=SAMPLES)
    box_axis_facts(result, [scale, 2 * scale, 3 * scale])
    # The spacing scales with the part, so the sampling (and the mesh size) is about the same.
    unit = cadmedial.compute(BOX, samples=SAMPLES)
    assert result.stats["spacing"] / scale == pytest.approx(unit.stats["spacing"] / 10, rel=0.3)
    assert result.stats["samples"] == pytest.approx(unit.stats["samples"], rel=0.3)


@pytest.mark.parametrize("name, scale", [("tiny_box.brep", 1e-6), ("huge_box.brep", 1e6)])
def test_cli_computes_tiny_and_huge(cli, tmp_path, name, scale):
    out = tmp_path / "axis.ply"
    run = run_cli(cli, "compute", bad(name), "-o", str(out), "--samples", str(SAMPLES), "--quiet")
    assert run.returncode == 0, run.stderr
    loaded = cadmedial.load(out)
    assert loaded.radius.max() == pytest.approx(scale / 2, rel=0.2)


def test_overlapping_solids_are_computed_each_on_its_own():
    # Documented choice (README.md in tests/data/bad/): a compound is a list of parts; two that
    # overlap are not fused, each gets the medial axis of its own volume.
    result = cadmedial.compute(bad("overlapping_solids.brep"), samples=SAMPLES)
    assert sorted(set(result.face_solid.tolist())) == [0, 1]
    tol = 2.5 * result.stats["spacing"]
    for solid, corner in ((0, 0.0), (1, 5.0)):
        faces = [f for f, s in zip(result.faces, result.face_solid) if s == solid]
        used = np.unique(np.concatenate([np.asarray(f) for f in faces]))
        pts, r = result.vertices[used], result.radius[used]
        assert r.max() == pytest.approx(5.0, abs=tol)
        assert np.all(pts >= corner - 1e-9) and np.all(pts <= corner + 10 + 1e-9)


def test_sliver_face_narrower_than_the_spacing():
    # A 20 x 20 x 10 block with a step 0.001 high on half its top: the step's side face is far
    # narrower than the spacing. The axis is the block's, about 5 thick at most.
    result = cadmedial.compute(bad("sliver_face.brep"), samples=SAMPLES)
    tol = 2.5 * result.stats["spacing"]
    assert result.stats["spacing"] > 0.1  # the sliver (0.001) is far below it
    assert result.radius.max() == pytest.approx(5.0, abs=tol)
    assert np.all(result.vertices >= -1e-9) and np.all(result.vertices[:, :2] <= 20 + 1e-9)
    assert np.all(result.vertices[:, 2] <= 10.001 + 1e-9)


# ---- inputs that are healed: computed, with a warning saying what was fixed or skipped ---------

# file, what the warning must say, the box(es) of the healed solid(s): (x0, sides)
HEALED = [
    ("reversed_face.brep", "shell 1 is invalid (BRepCheck_BadOrientationOfSubshape); healed by ShapeFix",
     [(0.0, [10, 20, 30])]),
    ("gap_of_0.001.brep", "is bounded by 1 face (the shell is open) near (10.001, 0, 15); closed by sewing",
     [(0.0, [10.001, 20, 30])]),
    ("assembly_with_empty_solid.brep", "solid 3: has no shell (an empty solid); skipped",
     [(0.0, [10, 10, 10]), (10.0, [10, 10, 10]), (20.0, [10, 10, 10])]),
]


@pytest.mark.parametrize("name, fragment, boxes", HEALED, ids=[h[0] for h in HEALED])
def test_python_heals_and_warns(name, fragment, boxes):
    result = cadmedial.compute(bad(name), samples=SAMPLES)
    assert any(fragment in w for w in result.stats["warnings"]), result.stats["warnings"]
    assert sorted(set(result.face_solid.tolist())) == list(range(len(boxes)))
    tol = 2.5 * result.stats["spacing"]
    for solid, (x0, sides) in enumerate(boxes):
        assert result.stats["solids"][solid]["euler_characteristic"] == 1
        faces = [f for f, s in zip(result.faces, result.face_solid) if s == solid]
        used = np.unique(np.concatenate([np.asarray(f) for f in faces]))
        pts, r = result.vertices[used] - [x0, 0, 0], result.radius[used]
        assert r.max() == pytest.approx(min(sides) / 2, abs=tol)
        assert np.all(pts >= -1e-6) and np.all(pts <= np.asarray(sides) + 1e-6)


@pytest.mark.parametrize("name, fragment, boxes", HEALED, ids=[h[0] for h in HEALED])
def test_cli_heals_and_warns(cli, tmp_path, name, fragment, boxes):
    out = tmp_path / "axis.ply"
    run = run_cli(cli, "compute", bad(name), "-o", str(out), "--samples", str(SAMPLES), "--quiet")
    assert run.returncode == 0, run.stderr
    warnings = [line for line in run.stderr.splitlines() if line.startswith("cadmedial: warning: ")]
    assert any(fragment in w for w in warnings), run.stderr
    assert cadmedial.load(out).radius.max() == pytest.approx(min(min(b[1]) for b in boxes) / 2, rel=0.2)


# ---- parameters --------------------------------------------------------------------------------

NAN, INF = float("nan"), float("inf")


@pytest.mark.parametrize("params, field", [
    ({"spacing": NAN}, "spacing"), ({"spacing": INF}, "spacing"), ({"spacing": 0.0}, "spacing"),
    ({"spacing": -1.0}, "spacing"), ({"spacing": 1e-9}, "spacing"),
    ({"samples": NAN}, "samples"), ({"samples": INF}, "samples"), ({"samples": 0}, "samples"),
    ({"samples": -1}, "samples"), ({"samples": 10**30}, "samples"), ({"samples": 10**9}, "samples"),
    ({"theta": NAN}, "theta"), ({"theta": INF}, "theta"), ({"theta": 0.0}, "theta"),
    ({"theta": -5.0}, "theta"), ({"theta": 1e300}, "theta"),
    ({"rho": NAN}, "rho"), ({"rho": INF}, "rho"), ({"rho": 0.0}, "rho"), ({"rho": -8.0}, "rho"),
    ({"spacing": "abc"}, "spacing"), ({"samples": "many"}, "samples"),
])
def test_python_bad_parameter_is_named(params, field):
    with pytest.raises(cadmedial.InvalidInput, match=field):
        cadmedial.compute(BOX, **params)


@pytest.mark.parametrize("spacing", [50.0, 1e6])
def test_spacing_near_the_part_size_is_refused(spacing):
    # A box 10 x 20 x 30 at spacing 50 would get a few dozen samples: no medial axis.
    with pytest.raises(cadmedial.InvalidInput, match="too coarse"):
        cadmedial.compute(BOX, spacing=spacing)


@pytest.mark.parametrize("option, value, fragment", [
    ("--spacing", "nan", "not a finite number"), ("--spacing", "-1", "must be > 0"),
    ("--spacing", "0", "must be > 0"), ("--spacing", "1e400", "not a finite number"),
    ("--spacing", "1e-9", "spacing"),
    ("--samples", "nan", "not a finite number"), ("--samples", "-1", "must be > 0"),
    ("--samples", "0", "must be > 0"), ("--samples", "1e30", "whole number"),
    ("--samples", "1e9", "samples"),
    ("--theta", "nan", "not a finite number"), ("--theta", "-1", "(0, 90)"), ("--theta", "0", "(0, 90)"),
    ("--theta", "1e300", "(0, 90)"),
    ("--rho", "nan", "not a finite number"), ("--rho", "-1", "must be > 0"), ("--rho", "0", "must be > 0"),
    ("--rho", "inf", "not a finite number"),
])
def test_cli_bad_parameter_is_named(cli, tmp_path, option, value, fragment):
    out = tmp_path / "out"
    out.mkdir()
    run = run_cli(cli, "compute", BOX, "-o", str(out / "axis.ply"), option, value, "--quiet")
    assert_refused(run, fragment, out)


# ---- paths -------------------------------------------------------------------------------------

@pytest.mark.parametrize("make_input, fragment", [
    (lambda d: str(d / "nowhere.brep"), "no such file"),
    (lambda d: str(d), "unknown file type"),
    (lambda d: (d / "dir.brep").mkdir() or str(d / "dir.brep"), "is a directory"),
])
def test_cli_bad_input_path(cli, tmp_path, make_input, fragment):
    src = tmp_path / "src"
    src.mkdir()
    out = tmp_path / "out"
    out.mkdir()
    run = run_cli(cli, "compute", make_input(src), "-o", str(out / "axis.ply"), "--quiet")
    assert_refused(run, fragment, out)


@pytest.mark.parametrize("target, fragment", [
    ("/etc/hostname/x.ply", "is not a directory"),      # a path under a regular file
    ("{out}", "is a directory"),                         # a directory
    ("{out}/missing/x.ply", "does not exist"),
    ("{out}/x.xyz", "unknown output type"),
])
def test_cli_unwritable_output(cli, tmp_path, target, fragment):
    out = tmp_path / "out"
    out.mkdir()
    path = target.format(out=out)
    run = run_cli(cli, "compute", BOX, "-o", path, "--samples", str(SAMPLES), "--quiet")
    assert_refused(run, fragment, out)


@pytest.mark.parametrize("target", ["/etc/hostname/x.ply", "{out}", "{out}/missing/x.ply"])
def test_python_save_to_unwritable_path(tmp_path, target):
    out = tmp_path / "out"
    out.mkdir()
    result = cadmedial.compute(BOX, samples=SAMPLES)
    with pytest.raises(cadmedial.Error) as raised:
        result.save(target.format(out=out))
    assert str(raised.value)
    assert os.listdir(out) == []


# ---- fuzzer findings (tests/data/bad/fuzz/) ------------------------------------------------------

# Each was a crash (or an endless loop) before the fix named in tests/data/bad/README.md. Run through
# the CLI in a subprocess so that a regression fails one test instead of killing pytest.
@pytest.mark.parametrize("name", sorted(os.listdir(os.path.join(BAD, "fuzz"))))
def test_fuzz_finding_is_refused_without_a_crash(cli, tmp_path, name):
    out = tmp_path / "out"
    out.mkdir()
    run = run_cli(cli, "compute", os.path.join(BAD, "fuzz", name), "-o", str(out / "axis.ply"), "--quiet")
    assert_refused(run, "", out)


# tests/data/bad/fuzz-slow/: BRepCheck ran for minutes on these; the curve-end check in
# extract_solids now refuses them first (a regression shows as a timeout here).
@pytest.mark.parametrize("name", sorted(os.listdir(os.path.join(BAD, "fuzz-slow"))))
def test_slow_fuzz_input_is_refused_quickly(cli, tmp_path, name):
    out = tmp_path / "out"
    out.mkdir()
    run = subprocess.run([cli, "compute", os.path.join(BAD, "fuzz-slow", name), "-o", str(out / "axis.ply"),
                          "--quiet"], capture_output=True, text=True, timeout=60)
    assert_refused(run, "curve", out)
