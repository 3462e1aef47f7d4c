"""The radius legend shows a colour range set by hand, in the real FreeCAD under Xvfb
(gui_color_range.py): its five ticks are the range's, the automatic range brings the radii's
back, a reopened document shows the set range, and the edit panel's Colours rows set one and
fit the Combo View (also at 200 % scaling). Skips (saying why) without xvfb-run or the
FreeCAD GUI."""

import os

import pytest

from cadmedial.colormap import STOPS
from conftest import run_gui_script

MIDDLE = STOPS[len(STOPS) // 2].tolist()


@pytest.fixture(scope="module")
def shown(tmp_path_factory):
    report, _, _ = run_gui_script(tmp_path_factory, "gui_color_range.py", "color_range.json",
                                  keep=("range_automatic.png", "range_set.png", "range_reopened.png", "range_panel.png",
                                        "color_range.json"))
    return report


@pytest.fixture(scope="module")
def shown_at_200_percent(tmp_path_factory):
    # The same script with Qt's user interface scaled 2 times (a 200 % screen setting).
    before = os.environ.get("QT_SCALE_FACTOR")
    os.environ["QT_SCALE_FACTOR"] = "2"
    try:
        report, _, _ = run_gui_script(tmp_path_factory, "gui_color_range.py", "color_range.json")
    finally:
        if before is None:
            del os.environ["QT_SCALE_FACTOR"]
        else:
            os.environ["QT_SCALE_FACTOR"] = before
    return report


def ticks(low, high):
    return ["– %.3g mm" % (high - i * (high - low) / 4) for i in range(5)]


def test_ticks_show_the_radii_by_default(shown):
    low, high = shown["radius"]
    assert high == pytest.approx(5.0, abs=0.5)  # half the box's 10 mm side
    assert shown["automatic"]["ticks"] == ticks(low, high)
    assert "radii" not in shown["automatic"]["lines"]


def test_ticks_show_a_set_range(shown):
    assert shown["set_properties"] == [False, 1.0, 3.0, False]  # set, and nothing to recompute
    assert shown["set"]["ticks"] == ["– 3 mm", "– 2.5 mm", "– 2 mm", "– 1.5 mm", "– 1 mm"]
    # The object's line gives the range, and the radii beyond it (their colours clamp).
    low, high = shown["radius"]
    assert "1 – 3 mm" in shown["set"]["lines"]
    assert "radii %.4g – %.4g mm" % (low, high) in shown["set"]["lines"]


def test_the_view_draws_the_set_range_s_colours(shown):
    # The point nearest radius 2, the middle of 1..3, is drawn in the map's middle colour; in the
    # automatic range 0..5 it is at 0.4 of the map, another colour.
    assert abs(shown["middle_radius"] - 2.0) < 0.02
    assert max(abs(a - b) for a, b in zip(shown["middle_shown"], MIDDLE)) < 0.03
    assert max(abs(a - b) for a, b in zip(shown["middle_shown_automatic"], MIDDLE)) > 0.05


def test_automatic_range_comes_back_on_the_legend(shown):
    assert shown["automatic_again"] == shown["automatic"]


def test_the_edit_panel_sets_the_range_and_fits(shown):
    low, high = shown["radius"]
    assert shown["rows_loaded"] == [True, False, pytest.approx(low, abs=1e-4), pytest.approx(high, abs=1e-4)]
    rows = shown["rows_set"]
    assert rows["object"] == [False, 1.5, 2.5, False]
    assert rows["legend"]["ticks"] == ["– 2.5 mm", "– 2.25 mm", "– 2 mm", "– 1.75 mm", "– 1.5 mm"]
    # Radius 2 is the middle of 1.5..2.5 too.
    assert max(abs(a - b) for a, b in zip(rows["shown"], MIDDLE)) < 0.03
    assert rows["panel_width"] <= 240 and rows["cut_off"] == [], rows
    assert shown["rows_dialog_open_after_cancel"] is False


def test_reopened_document_shows_the_set_range(shown):
    assert shown["reopened"] is not None
    assert shown["reopened"]["ticks"] == ["– 3 mm", "– 2.5 mm", "– 2 mm", "– 1.5 mm", "– 1 mm"]


def test_the_edit_panel_fits_at_200_percent(shown_at_200_percent):
    # Widths in Qt's scaled pixels: the Combo View keeps its default width, every row shows whole.
    rows = shown_at_200_percent["rows_set"]
    assert rows["panel_width"] <= 240 and rows["cut_off"] == [], rows
