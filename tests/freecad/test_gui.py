"""GUI smoke test in the real FreeCAD under Xvfb: install the addon into a scratch home, start
FreeCAD with gui_smoke.py, and check what it saw. Skips (saying why) without xvfb-run or the
FreeCAD GUI; everything else that goes wrong fails."""

import re

import pytest

from conftest import run_gui_script


@pytest.fixture(scope="module")
def smoke(tmp_path_factory):
    report, _, _ = run_gui_script(tmp_path_factory, "gui_smoke.py", "report.json",
                                  keep=("workbench.png", "view.png", "panel.png", "face_message.png",
                                        "reopened.png", "reopened_workbench.png", "thinnest_wall.png",
                                        "report.json"), check_status=True)
    return report


def test_workbench_activates(smoke):
    assert smoke["workbench"] == "MedialAxisWorkbench"


def test_command_is_active_only_with_a_solid_selected(smoke):
    assert smoke["create_active_without_selection"] is False
    assert smoke["create_active_with_box"] is True
    # Active with a face too: clicking says why it cannot be used, instead of a greyed button.
    assert smoke["create_active_with_face"] is True
    assert "not a solid" in smoke["face_message"], smoke["face_message"]
    assert smoke["dialog_open_for_face"] is False


def test_task_panel_previews_the_sample_count(smoke):
    assert smoke["task_dialog_open"] is True
    assert smoke["mode_default"] == "automatic"
    # A 40 x 20 x 10 box: preview follows the spin box. It shows the count the compute will use
    # (the engine calibrates the spacing to within 15 % of the target).
    def shown(text):
        return int(re.search(r"([\d,]+) samples", text).group(1).replace(",", ""))
    assert abs(shown(smoke["preview_default"]) - 20000) <= 0.15 * 20000, smoke["preview_default"]
    assert abs(shown(smoke["preview_4000"]) - 4000) <= 0.15 * 4000, smoke["preview_4000"]
    assert smoke["stop_enabled_while_running"] is True
    assert smoke["refine_default"] is True  # sample finer where the axis's topology is wrong


def test_one_feature_per_selected_solid(smoke):
    assert smoke["features_for_two_boxes"] == 2


def test_feature_is_coloured_per_vertex(smoke):
    feature = smoke["feature"]
    assert feature["status"] == "ok"
    assert feature["points"] == feature["vertex_count"] > 0
    assert feature["colors"] == feature["points"]
    assert feature["coloring"] is True
    assert feature["samples"] == 4000
    assert feature["refine"] is True  # the panel's default
    assert feature["proxy"] == "cadmedial.gui.view_provider.ViewProviderMedialAxis"
    assert smoke["shape_faces"] > 0


def test_legend_shows_the_radius_range(smoke):
    low, high = smoke["feature"]["radius"]
    assert smoke["legend"] is not None
    assert "Medial radius" in smoke["legend"]
    assert "%.4g" % high in smoke["legend"]


def test_view_shows_radius_colours(smoke):
    # Of ~30,000 sampled pixels of the 800 x 600 view, the coloured mesh covers a good part.
    assert smoke["view_size"] == [800, 600]
    assert smoke["coloured_pixels_sampled"] > 1000
    assert (smoke["out"] / "workbench.png").stat().st_size > 20000


def test_changing_the_box_recomputes_in_the_gui(smoke):
    x_length, y_length = smoke["bbox_after_change"]
    assert x_length == pytest.approx(80.0, abs=3.0)
    colors, points = smoke["colors_after_change"]
    assert colors == points > 0


def test_face_gives_an_error_in_the_report_and_no_object(smoke):
    assert smoke["face_error"].startswith("InvalidInput")
    assert smoke["objects_added_by_face"] == 0
    assert smoke["report_view_has_error"] is True


def test_stop_cancels_the_compute_and_adds_nothing(smoke):
    assert smoke["stopped_message"].startswith("Stopped")
    assert smoke["objects_added_by_stop"] == 0
    assert smoke["dialog_open_after_reject"] is False
    assert smoke["dialog_open_after_one_cancel"] is False
    assert smoke["objects_added_by_cancel"] == 0


def test_panel_fits_the_combo_view(smoke):
    # FreeCAD's default Combo View is about 240 px wide: the panel needs no more, Stop shows.
    assert smoke["panel_min_width"] <= 240, smoke["panel_min_width"]
    assert smoke["stop_visible"] is True
    # Every row, Min feature's too, is shown whole at that width.
    assert smoke["panel_width"] <= 240, smoke["panel_width"]
    assert smoke["panel_cut_off"] == [], smoke["panel_cut_off"]
    assert smoke["min_feature_row"] == {"label": "Min feature", "text": "0.1250 mm", "visible": True}


def test_min_feature_goes_from_the_panel_to_the_object_and_back(smoke):
    assert smoke["min_feature_default"] == [0.0, "none"]  # 0: no minimum
    assert smoke["feature"]["min_feature"] == 0.125  # a new object gets it
    assert smoke["edit_min_feature"] == 0.125  # editing loads it
    assert smoke["edited"]["min_feature"] == 0.25  # and saves it
    assert smoke["reedit_min_feature"] == 0.25


def test_picked_point_shows_its_radius(smoke):
    assert "medial radius" in smoke["pick_message"]


def test_reopened_document_keeps_its_colours(smoke):
    assert smoke["reopened_coloured_pixels_sampled"] > 1000
    assert smoke["reopened_legend"] is not None and "Medial radius" in smoke["reopened_legend"]


def test_task_panel_edits_an_existing_feature(smoke):
    assert smoke["edit_panel_for"] == "MedialAxis"
    assert smoke["edit_mode"] == "samples"  # the feature was made with 4000 samples
    assert smoke["edited"] == {"theta": 10.0, "refine": False, "status": "ok", "min_feature": 0.25,
                               "dialog_open": False}


def test_console_one_liner_gets_the_coloured_view(smoke):
    console = smoke["console"]
    assert console["proxy"] == "ViewProviderMedialAxis"
    assert console["coloring"] is True
    assert console["colors"] == console["points"] > 0


def test_one_click_zooms_onto_the_thinnest_wall(smoke):
    # Nothing selected: the one click goes to the 40 x 40 x 1 plate's wall, the thinnest shown.
    assert smoke["thinnest_wall_active_unselected"] is True
    wall = smoke["thinnest_wall"]
    assert wall["thickness"] == pytest.approx(1.0, rel=0.05)
    # The camera looks at the wall (its focal point there) with a field 40 wall thicknesses high.
    gap = sum((f - a) ** 2 for f, a in zip(wall["focal_point"], wall["at"])) ** 0.5
    assert gap < 1e-3 * wall["thickness"], (wall["focal_point"], wall["at"])
    height = float(re.search(r"height ([-\d.e]+)", wall["camera"]).group(1))
    assert height == pytest.approx(40.0 * wall["thickness"], rel=0.01)
    assert "thinnest wall" in wall["status"]


def test_the_thinnest_wall_is_marked_once(smoke):
    wall = smoke["thinnest_wall"]
    assert wall["marks_in_view"] == 1
    assert wall["mark_at"] == pytest.approx(wall["at"])
    assert wall["marks_after_second_click"] == 1
