"""cadmedial.compute on shapes with known medial axes: facts of geometry, not snapshots."""

import pathlib

import numpy as np
import pytest

import cadmedial
from conftest import SAMPLES, assert_same_mesh


def test_box_arrays_have_consistent_shapes_and_types(box_step):
    r = cadmedial.compute(box_step, samples=SAMPLES)
    v, f = r.num_vertices, r.num_faces
    assert v > 0 and f > 0
    assert r.vertices.shape == (v, 3) and r.vertices.dtype == np.float64
    assert r.radius.shape == (v,) and r.radius.dtype == np.float64
    assert len(r.faces) == f and r.faces.offsets.shape == (f + 1,)
    assert r.face_kind.shape == (f,) and r.face_kind.dtype == np.uint8
    assert r.face_solid.shape == (f,)
    assert r.faces.sizes().min() >= 3
    assert r.faces.indices.min() >= 0 and r.faces.indices.max() < v
    assert set(np.unique(r.face_kind)) <= {0, 1, 2}


def test_stats_count_what_the_arrays_hold(box_step):
    r = cadmedial.compute(box_step, samples=SAMPLES)
    assert r.stats["vertices"] == r.num_vertices
    assert r.stats["faces"] == r.num_faces
    assert r.stats["samples"] > 0.5 * SAMPLES
    assert r.stats["spacing"] > 0
    assert "total" in r.stats["timings"]


def test_box_medial_axis_lies_inside_the_box_with_radius_up_to_half_its_thickness(box_step):
    r = cadmedial.compute(box_step, samples=SAMPLES)
    tol = 2 * r.stats["spacing"]
    assert (r.vertices.min(axis=0) >= -tol).all()
    assert (r.vertices.max(axis=0) <= np.array([10, 20, 30]) + tol).all()
    # The largest inscribed ball of a 10 x 20 x 30 box has radius 5; radii are distances to
    # samples, so they are within about a spacing of the true ones.
    assert r.radius.min() >= 0
    assert abs(r.radius.max() - 5.0) <= tol


def test_longer_box_gives_longer_medial_axis(data):
    short = cadmedial.compute(data("box_10x20x30.brep"), samples=SAMPLES)
    l_shape = cadmedial.compute(data("l_bracket.brep"), samples=SAMPLES)
    extent = lambda r: r.vertices.max(axis=0) - r.vertices.min(axis=0)  # noqa: E731
    # The L bracket is 40 x 40 x 30: its medial axis spans far more in x and y than the box's.
    assert extent(l_shape)[0] > extent(short)[0] + 15
    assert extent(l_shape)[1] > extent(short)[1] + 10


def test_two_solids_are_computed_each_on_its_own(data):
    r = cadmedial.compute(data("two_cubes.brep"), samples=SAMPLES)
    assert set(np.unique(r.face_solid)) == {0, 1}
    tol = 2 * r.stats["spacing"]
    for solid, x_low in ((0, 0.0), (1, 20.0)):
        used = np.unique(np.concatenate([r.faces[f] for f in np.flatnonzero(r.face_solid == solid)]))
        xs = r.vertices[used, 0]
        assert xs.min() >= x_low - tol and xs.max() <= x_low + 10 + tol


def test_every_kind_of_source_gives_the_same_result(data, box_brep_text):
    brep_path = data("box_10x20x30.brep")
    results = [cadmedial.compute(source, samples=SAMPLES) for source in (
        brep_path, pathlib.Path(brep_path), box_brep_text, box_brep_text.encode(),
        cadmedial.read_shape(brep_path))]
    for other in results[1:]:
        assert_same_mesh(other, results[0])


def test_step_and_brep_of_the_same_box_agree(box_step, data):
    step = cadmedial.compute(box_step, samples=SAMPLES)
    brep = cadmedial.compute(data("box_10x20x30.brep"), samples=SAMPLES)
    assert step.num_vertices == brep.num_vertices
    np.testing.assert_allclose(step.radius.max(), brep.radius.max(), atol=1e-6)


def test_spacing_sets_the_density(box_step):
    coarse = cadmedial.compute(box_step, spacing=2.0)
    fine = cadmedial.compute(box_step, spacing=1.0)
    assert coarse.stats["spacing"] == pytest.approx(2.0)
    assert fine.stats["samples"] > 2.5 * coarse.stats["samples"]  # ~4x for half the spacing


def test_plan_sampling_predicts_the_sample_count(box_step):
    plan = cadmedial.plan_sampling(box_step, samples=SAMPLES)
    r = cadmedial.compute(box_step, samples=SAMPLES)
    assert plan.spacing == pytest.approx(r.stats["spacing"], rel=1e-6)
    assert 0.5 * r.stats["samples"] <= plan.estimated_samples <= 2 * r.stats["samples"]


def test_compute_is_repeatable_up_to_order(box_step):
    assert_same_mesh(cadmedial.compute(box_step, samples=SAMPLES),
                     cadmedial.compute(box_step, samples=SAMPLES))


def test_walls_thinner_than_two_spacings_are_warned_about(box_step):
    # The box is 10 thick: its medial radius is 5, under a spacing of 6 (the sheet between the
    # 20 x 30 faces has samples only 10 / 6 spacings apart), not under 3. With one spacing
    # everywhere (adapt=False) the first is warned about; by default it is sampled finer.
    adapted = cadmedial.compute(box_step, spacing=6.0)
    assert adapted.stats["warnings"] == []
    assert 10.0 - 1e-6 <= adapted.stats["solids"][0]["thinnest_wall"] <= 12.0
    coarse = cadmedial.compute(box_step, spacing=6.0, adapt=False)
    assert adapted.stats["samples"] > 2 * coarse.stats["samples"]
    assert len(coarse.stats["warnings"]) == 1
    assert "thinner than two sample spacings" in coarse.stats["warnings"][0]
    assert 10.0 - 1e-6 <= coarse.stats["solids"][0]["thinnest_wall"] <= 12.0
    fine = cadmedial.compute(box_step, spacing=3.0)
    assert fine.stats["warnings"] == []
    assert fine.stats["solids"][0]["thinnest_wall"] is None  # only walls under 2 spacings are looked for


def test_walls_under_the_minimum_feature_size_are_not_sampled_finer_and_are_named(box_step):
    # The 10-thick box at spacing 6 is sampled finer by default (above); a minimum feature size
    # of 12 counts its wall as 12 thick, a radius of one spacing: kept at one spacing, and said.
    coarse = cadmedial.compute(box_step, spacing=6.0, adapt=False)
    limited = cadmedial.compute(box_step, spacing=6.0, min_feature=12.0)
    assert limited.stats["samples"] == coarse.stats["samples"]
    assert len(limited.stats["warnings"]) == 1
    assert "thinner than the minimum feature size given (12)" in limited.stats["warnings"][0]
    assert 10.0 - 1e-6 <= limited.stats["solids"][0]["thinnest_wall"] <= 12.0
    assert cadmedial.plan_sampling(box_step, spacing=6.0, min_feature=12.0).estimated_samples == \
        coarse.stats["samples"]
    for bad in (-1.0, "thin", float("nan")):
        with pytest.raises(cadmedial.InvalidInput):
            cadmedial.compute(box_step, spacing=6.0, min_feature=bad)


def test_refine_samples_a_thin_walled_cup_finer_until_its_axis_has_the_cups_topology(data):
    # Walls 1 thick at one spacing of 2: the sheets inside them break apart (the premise). A
    # density given is kept unless refine=True; then the cup is sampled again at 2 / sqrt(2.5).
    cup = data("cup_40x30x20.brep")
    once = cadmedial.compute(cup, spacing=2.0, adapt=False)
    solid = once.stats["solids"][0]
    assert solid["solid_euler_characteristic"] == 1
    assert solid["euler_characteristic"] != 1 or solid["components"] > 1
    assert solid["refinements"] == 0 and solid["spacing"] == 2.0
    assert any("medial axis" in w for w in once.stats["warnings"])
    refined = cadmedial.compute(cup, spacing=2.0, adapt=False, refine=True)
    solid = refined.stats["solids"][0]
    assert solid["euler_characteristic"] == 1 and solid["components"] == 1
    assert solid["refinements"] >= 1
    assert solid["spacing"] == pytest.approx(2.0 / 2.5 ** (solid["refinements"] / 2))
    assert refined.stats["spacing"] == 2.0  # what the parameters gave
    assert refined.stats["samples"] > once.stats["samples"]
    assert not any("medial axis" in w for w in refined.stats["warnings"])


def test_refine_defaults_to_on_only_when_no_density_is_given(box_step, monkeypatch):
    asked = []
    real = cadmedial._core.compute_medial_axis

    def spy(*args, **kwargs):
        asked.append(args[-1])  # refine, the last positional argument
        return real(*args, **kwargs)

    monkeypatch.setattr(cadmedial._core, "compute_medial_axis", spy)
    cadmedial.compute(box_step)
    cadmedial.compute(box_step, samples=SAMPLES)
    cadmedial.compute(box_step, spacing=3.0)
    cadmedial.compute(box_step, samples=SAMPLES, refine=True)
    cadmedial.compute(box_step, refine=False)
    assert asked == [True, False, False, True, False]
    with pytest.raises(cadmedial.InvalidInput, match="refine must be True or False"):
        cadmedial.compute(box_step, refine="yes")
