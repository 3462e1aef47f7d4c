"""The Wall thickness command in the real FreeCAD GUI under Xvfb (thickness_gui_smoke.py): the thin
rib of a plate is listed as thin, a click selects its face; the legend range recolours without an
analysis; clicks on the view probe the thickness (ball and ray drawn, the GUI's stall measured);
CSV and HTML exports; screenshots are kept."""

import pytest

from conftest import run_gui_script



@pytest.fixture(scope="module")
def smoke(tmp_path_factory):
    report, _, _ = run_gui_script(tmp_path_factory, "thickness_gui_smoke.py", "thickness.json",
                                  keep=("thickness.png", "thickness_probe.png", "thickness_window.png",
                                        "thickness.json"))
    return report


def test_analysis_runs_off_the_gui_thread_and_adds_one_object(smoke):
    assert smoke["gui_thread_free"]
    assert smoke["objects"] == 1
    assert smoke["status"].startswith("FAIL")


def test_the_rib_is_listed_thin_and_a_click_selects_its_face(smoke):
    big = [line for line in smoke["regions"] if line.startswith("thin")
           and float(line.split()[-1]) > 10]
    assert len(big) == 2
    assert all(abs(float(line.split()[1]) - 1.0) < 0.05 for line in big)
    assert smoke["selected"] and all(name.startswith("Face") for name in smoke["selected"])


def test_screenshot_is_written(smoke):
    assert (smoke["out"] / "thickness.png").stat().st_size > 10000


def test_legend_range_recolours_without_an_analysis(smoke):
    v = smoke["legend_vertex"]
    assert abs(v["value"] - 4.0) < 0.01
    # Colours are kept as 8-bit RGBA: the colour map's value within one step.
    assert all(abs(a - e) <= 1.5 / 255 for a, e in zip(v["after"], v["expected"]))
    assert max(abs(a - b) for a, b in zip(v["after"], v["before"])) > 0.2
    assert v["recomputed"] == v["after"]
    assert v["analyses"] == 0 and "Touched" not in v["state"]
    assert "– 6 mm" in smoke["legend_after"] and "– 3 mm" in smoke["legend_after"]
    assert "thinner than 1.5 mm" in smoke["legend_after"]


def test_legend_is_in_the_top_left_clear_of_the_triad_and_cube(smoke):
    x, y, w, h = smoke["legend_rect"]
    width, height = smoke["view_size"]
    assert x < 50 and y < 50 and x + w < width / 2 and y + h < height / 2
    assert "Wall thickness" in smoke["legend"] and "– 1 mm" in smoke["legend"]


def test_a_click_reads_the_sphere_and_ray_thickness(smoke):
    assert len(smoke["probes"]) == 3
    for p in smoke["probes"]:
        assert p["probed"], p
        # The click lands where it was aimed (a pixel is about 0.05 mm here).
        assert max(abs(a - b) for a, b in zip(p["at"], p["point"])) < 0.5, p
        assert abs(p["sphere"] / p["exact"] - 1) < 0.02, p
        assert abs(p["ray"] / p["exact"] - 1) < 0.02, p
        assert abs(2 * p["ball_radius"] - p["sphere"]) < 1e-9
    on_source = smoke["source_probe"]
    assert on_source["face"].startswith("Face")
    assert max(abs(a - b) for a, b in zip(on_source["at"], smoke["probes"][0]["point"])) < 0.5
    assert abs(on_source["sphere"] / smoke["probes"][0]["exact"] - 1) < 0.02
    last = smoke["probes"][-1]
    assert "sphere %.4g mm" % last["sphere"] in smoke["status_bar"]
    assert "sphere %.4g mm" % last["sphere"] in smoke["probe_text"]
    assert smoke["selection_after_clicks"] == []  # probing does not select


def test_the_ball_and_ray_are_in_the_scene_graph(smoke):
    assert smoke["ball_node"] and smoke["ray_node"]
    assert abs(smoke["ball_node_radius"] - smoke["last_ball_radius"]) < 1e-5
    assert (smoke["out"] / "thickness_probe.png").stat().st_size > 10000


def test_a_click_costs_the_gui_thread_under_100_ms_besides_the_redraw(smoke):
    # Our work on the GUI thread per click: the ray pick (getObjectInfo) and the probe with its
    # drawing and messages. The whole click as a 10 ms timer sees it is mostly the view's
    # redraw in Xvfb's software OpenGL (a click that draws nothing stalls as long), noisy on a
    # shared machine: the quickest click is held to the slowest plain redraw plus 100 ms. Our
    # work is held to 100 ms of the GUI thread's CPU time: its wall time grows with the load of
    # other processes (68 + 54 ms once with ctest -j2 beside two other test runs).
    assert smoke["samples"] > 15000
    for p in smoke["probes"]:
        assert p["pick_cpu_ms"] + p["probe_cpu_ms"] < 100, p
    quickest = min(p["stall_ms"] for p in smoke["probes"])
    assert quickest < max(smoke["redraws_ms"]) + 100, (smoke["probes"], smoke["redraws_ms"])


def test_a_region_click_draws_the_ball_at_its_extreme(smoke):
    g = smoke["region_ball"]
    assert max(abs(a - b) for a, b in zip(g["probed_at"], g["at"])) < 1e-6
    assert abs(g["sphere"] / g["extreme"] - 1) < 0.02


def test_csv_export_lists_the_regions_and_faces(smoke):
    import csv
    import io
    rows = list(csv.DictReader(io.StringIO(smoke["regions_csv"])))
    assert len(rows) == len(smoke["regions"])
    assert [r["kind"] for r in rows] == [line.split()[0] for line in smoke["regions"]]
    assert abs(min(float(r["extreme"]) for r in rows) - smoke["result_min"]) < 1e-5
    faces = list(csv.DictReader(io.StringIO(smoke["faces_csv"])))
    assert {r["face"] for r in faces} >= {f for r in rows for f in r["faces"].split()}
    assert abs(min(float(r["min"]) for r in faces if r["min"]) - smoke["result_min"]) < 1e-5
    assert smoke["dialog_folder"] == str(smoke["out"])


def test_html_report_holds_the_view_picture_and_the_minimum(smoke):
    import base64
    import struct
    html = smoke["html"]
    assert "FAIL" in html
    assert "<td>minimum</td><td>%.4g</td>" % smoke["result_min"] in html
    data = base64.b64decode(html.split("data:image/png;base64,")[1].split('"')[0])
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    assert struct.unpack(">II", data[16:24]) == (1000, 750)  # the 3D view's picture
