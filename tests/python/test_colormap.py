"""Radius colours: ends of the map, clamping, a flat range."""

import numpy as np

from cadmedial.colormap import STOPS, colors_of, packed_colors


def test_low_and_high_map_to_the_ends_of_the_map():
    c = colors_of([0.0, 10.0], 0.0, 10.0)
    np.testing.assert_allclose(c[0], STOPS[0], atol=1e-6)
    np.testing.assert_allclose(c[1], STOPS[-1], atol=1e-6)


def test_values_outside_the_range_are_clamped():
    c = colors_of([-5.0, 50.0], 0.0, 10.0)
    np.testing.assert_allclose(c, STOPS[[0, -1]], atol=1e-6)


def test_brightness_grows_with_radius():
    c = colors_of(np.linspace(0, 1, 50), 0.0, 1.0)
    luminance = c @ np.array([0.2126, 0.7152, 0.0722])
    assert (np.diff(luminance) > 0).all()


def test_flat_range_gives_one_colour():
    c = colors_of([3.0, 3.0, 3.0], 3.0, 3.0)
    assert c.shape == (3, 3) and (c == c[0]).all()


def test_each_stop_and_the_middle_between_two_are_the_table_s():
    c = colors_of(np.linspace(0.0, 10.0, 2 * len(STOPS) - 1), 0.0, 10.0)
    np.testing.assert_allclose(c[::2], STOPS, atol=1e-6)
    np.testing.assert_allclose(c[1::2], (STOPS[:-1] + STOPS[1:]) / 2, atol=1e-6)


def test_packed_colours_are_freecad_s_rrggbbaa_opaque():
    packed = packed_colors([[1.0, 0.0, 0.0], [0.0, 0.5, 1.0], [0.2, 0.4, 0.6]])
    assert packed.dtype == np.uint32
    assert packed.tolist() == [0xFF000000, 0x0080FF00, (51 << 24) | (102 << 16) | (153 << 8)]
