"""The thickness layer on exact medial balls (the radii issue 32 gives the engine): every value
must be the solid's true sphere thickness to 1 %."""

import numpy as np
import pytest

from conftest import (RIB, faces_on_plane, rib_balls, rib_on_plate, shell_balls,
                      spherical_shell, slab_balls, tilted_slab, tube, tube_balls)
from cadmedial.thickness import thickness


def counted_values(result):
    return result.values[result.counted]


def test_tilted_slab_reads_its_thickness_2():
    t = thickness(tilted_slab(), medial=slab_balls())
    v = counted_values(t)
    assert len(v) > 0.4 * len(t.values)
    np.testing.assert_allclose(v, 2.0, rtol=0.01)
    assert t.statistics["mean"] == pytest.approx(2.0, rel=0.01)


def test_tube_wall_reads_2():
    t = thickness(tube(), medial=tube_balls())
    v = counted_values(t)
    assert len(v) > 0.5 * len(t.values)
    np.testing.assert_allclose(v, 2.0, rtol=0.01)


def test_spherical_shell_reads_2_everywhere():
    # No edges: every point counts.
    t = thickness(spherical_shell(), medial=shell_balls())
    assert t.counted.all()
    np.testing.assert_allclose(t.values, 2.0, rtol=0.01)


def test_rib_is_one_thin_region_per_side_at_its_width():
    shape = rib_on_plate()
    t = thickness(shape, min=1.5, medial=rib_balls())
    sides = set(faces_on_plane(shape, 0, RIB["x"]) + faces_on_plane(shape, 0, RIB["x"] + RIB["width"]))
    assert len(sides) == 2
    # Where the rib meets the plate's end faces the wall is truly thin too (a ball there is held
    # by the two concave edges at the rib's foot: radius about 0.7): small patches at y = 0, 40.
    big = [g for g in t.thin_regions if g["area"] > 10]
    for g in t.thin_regions:
        if g["area"] <= 10:
            assert g["at"][1] in (0.0, 40.0) and abs(g["at"][0] - 20) < 1
    assert len(big) == 2
    for region in big:
        assert region["extreme"] == pytest.approx(RIB["width"], rel=0.01)
        assert set(region["faces"]) <= sides | set(faces_on_plane(shape, 2, RIB["plate"]))
        x, y, z = region["at"]
        assert min(abs(x - RIB["x"]), abs(x - RIB["x"] - RIB["width"])) < 1e-6
        assert RIB["plate"] <= z <= RIB["plate"] + RIB["height"]
        # Most of each rib side (40 x 10, less the corner bands) is in its region.
        assert 0.6 * 40 * RIB["height"] < region["area"] <= 40 * RIB["height"]
    # The plate far from the rib and from its edges reads the plate's 4.
    p = t.points
    plate_top = (np.abs(p[:, 2] - RIB["plate"]) < 1e-9) & (np.abs(p[:, 0] - 10) < 4) \
        & (np.abs(p[:, 1] - 20) < 10)
    assert plate_top.sum() > 20
    np.testing.assert_allclose(t.values[plate_top], RIB["plate"], rtol=0.01)
    assert not t.passed


def test_zero_policy_counts_the_corners_and_reads_zero_at_the_edges():
    t = thickness(tilted_slab(), corners="zero", medial=slab_balls())
    assert t.counted.all()
    on_edge = t.edge_distance < 1e-9
    assert on_edge.sum() > 100
    assert np.all(t.values[on_edge] < 1e-6)
    # Beside a 90-degree edge the largest ball tangent at distance a has radius a.
    near = (t.edge_distance > 0.2) & (t.edge_distance < 0.8)
    np.testing.assert_allclose(t.values[near], 2 * t.edge_distance[near], rtol=0.01, atol=0.02)


def test_statistics_are_area_weighted_and_the_histogram_holds_the_area():
    t = thickness(rib_on_plate(), min=1.5, medial=rib_balls())
    st = t.statistics
    assert sum(st["histogram"]["area"]) == pytest.approx(st["area"], rel=1e-9)
    area = t.area[t.counted]
    v = t.values[t.counted]
    assert st["mean"] == pytest.approx((v * area).sum() / area.sum())
    below = sum(g["area"] for g in t.thin_regions) / st["area"]
    assert st["share_below_min"] == pytest.approx(below, rel=1e-9)
    # The mesh area is the solid's.
    assert st["area_total"] == pytest.approx(rib_on_plate().Area, rel=1e-6)
