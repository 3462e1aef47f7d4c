"""The medial reading where the thickness changes within a spacing: a wedge.

Between the planes z = 0 and z = x tan(2 beta) the largest ball tangent to the floor at x is
x tan(beta) in radius (centre on the bisector): the thickness 2 x tan(beta) grows along x. Its
exact medial balls, one spacing apart on the bisector, touch the floor a spacing apart; a floor
point lies between the touches."""

import math

import numpy as np

from cadmedial.thickness.sphere import sphere_thickness

BETA = math.radians(15.0)
SPACING = 1.0


def wedge_balls():
    rho, y = np.meshgrid(np.arange(5.0, 60.0, SPACING), np.arange(-10.0, 10.0 + 1e-9, SPACING),
                         indexing="ij")
    rho, y = rho.ravel(), y.ravel()
    centres = np.column_stack([rho * math.cos(BETA), y, rho * math.sin(BETA)])
    return centres, rho * math.sin(BETA)


def floor_points():
    rng = np.random.default_rng(3)
    return np.column_stack([rng.uniform(20.0, 40.0, 2000), rng.uniform(-5.0, 5.0, 2000),
                            np.zeros(2000)])


def test_weighted_reading_follows_a_wedge_and_the_largest_ball_reads_over():
    centres, radii = wedge_balls()
    p = floor_points()
    exact = 2.0 * p[:, 0] * math.tan(BETA)
    upper = np.empty(len(p))
    value, gap, ball = sphere_thickness(p, centres, radii, reach=SPACING, upper=upper)
    error = value / exact - 1.0
    assert np.quantile(np.abs(error), 0.95) < 0.01
    # The largest ball within a spacing is one touching up to a spacing further up the slope.
    assert np.all(upper >= value - 1e-12)
    assert np.quantile(upper / exact - 1.0, 0.5) > 0.015  # 2.3 % (the weighted p95: 0.5 %)
    # The ball used is the largest containing one (its gap within the tolerance or its power
    # within the spacing), as before.
    assert np.allclose(2.0 * radii[ball], upper)


def test_without_reach_the_reading_is_the_largest_ball():
    centres, radii = wedge_balls()
    p = floor_points()
    upper = np.empty(len(p))
    value, _, _ = sphere_thickness(p, centres, radii, reach=0.0, upper=upper)
    assert np.array_equal(value, upper)
