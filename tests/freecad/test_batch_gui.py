"""The batch dialog in the real FreeCAD GUI under Xvfb (batch_gui_smoke.py), with the addon installed
into a scratch HOME as a user would: three parts (two solids, one file that is not STEP) run from
the dialog's Start button, the GUI's longest stall measured with a 10 ms timer, the summary table
read back, a row opened, then a slow batch stopped. A screenshot of the dialog is kept."""

import pytest

from conftest import run_gui_script

COLUMN = {}


@pytest.fixture(scope="module")
def smoke(tmp_path_factory):
    # Only what the addon installed: its package, its compiled module, its program.
    report, _, _ = run_gui_script(tmp_path_factory, "batch_gui_smoke.py", "batch.json", keep=("batch.png",),
                                  unset=("PYTHONPATH", "CADMEDIAL_CORE_DIR", "CADMEDIAL_CLI"))
    COLUMN.update({name: i for i, name in enumerate(report["headers"])})
    return report


def by_part(rows):
    return {row[COLUMN["Part"]]: row for row in rows}


def test_the_command_is_in_the_toolbar_and_opens_the_dialog(smoke):
    assert "Batch over a folder..." in smoke["toolbar"]
    assert smoke["dialog_visible"]
    assert smoke["default_output"] == str(smoke["out"] / "parts" / "medial_axis")


def test_the_addon_runs_its_own_program_with_python(smoke):
    assert smoke["cli"] == str(smoke["home"] / ".local/share/FreeCAD/Mod/MedialAxis/bin/cadmedial")


def test_the_batch_runs_off_the_gui_thread(smoke):
    assert smoke["running_after_click"]
    assert smoke["click_ms"] < 100
    # The longest gap between ticks of a 10 ms timer while the batch ran (cluster start included).
    print("longest GUI stall %.1f ms over %.2f s (a plain process beside it: %.1f ms; idle before: GUI %.1f, "
          "plain %.1f ms); gaps over 50 ms %s; full garbage collections (s, ms) %s" % (
              smoke["stall_ms"], smoke["batch_seconds"], smoke["machine_ms"], smoke["idle_stall_ms"],
              smoke["idle_machine_ms"], smoke["gaps"], smoke["collections"]))
    assert smoke["stall_ms"] < 300


def test_the_summary_table_has_a_row_per_part_with_its_status(smoke):
    rows = by_part(smoke["rows"])
    assert sorted(rows) == ["parts/bad.step", "parts/box.brep", "parts/cylinder.step"]
    bad = rows["parts/bad.step"]
    assert bad[COLUMN["Status"]] == "refused"
    assert "not a readable STEP file" in bad[COLUMN["Message"]]
    for name in ("parts/box.brep", "parts/cylinder.step"):
        row = rows[name]
        assert row[COLUMN["Status"]] == "ok" and row[COLUMN["Message"]] == ""
        assert row[COLUMN["Solids"]] == "1"
        assert row[COLUMN["Topology right"]] == "yes"
        assert int(row[COLUMN["Faces"]]) > 0
    # Sorted on the numbers behind the cells.
    times = [float(t) for t in smoke["times_sorted"]]
    assert times == sorted(times, reverse=True)


def test_the_outputs_exist(smoke):
    found = set(smoke["outputs"])
    for name in ("box.brep", "cylinder.step"):
        for suffix in (".ply", ".stats.json", ".record.json"):
            assert "parts/parts/%s%s" % (name, suffix) in found
    assert "parts/parts/bad.step.ply" not in found
    assert {"summary.csv", "summary.json"} <= found
    assert smoke["summary_button"]


def test_a_double_click_opens_the_part_with_its_medial_mesh(smoke):
    assert smoke["opened"] == [["Mesh::Feature", "Part::Feature"]]
    assert smoke["opened_faces"][0] > 0


def test_stop_ends_a_slow_batch_and_marks_its_parts(smoke):
    assert smoke["running_before_stop"]
    print("stopped in %.2f s; longest GUI stall %.1f ms (a plain process beside it: %.1f ms); gaps over 50 ms "
          "%s; full garbage collections %s" % (smoke["stop_seconds"], smoke["stop_stall_ms"],
                                               smoke["stop_machine_ms"], smoke["stop_gaps"], smoke["stop_collections"]))
    assert smoke["stop_seconds"] < 60
    # Informative: an engine at 400000 samples and a cluster's shutdown share the 2 cores with
    # FreeCAD here, and the plain process beside it sees gaps of the same order.
    assert smoke["stop_stall_ms"] < 1000
    statuses = {row[COLUMN["Status"]] for row in smoke["stopped_rows"]}
    assert len(smoke["stopped_rows"]) == 2 and "stopped" in statuses


def test_screenshot_is_written(smoke):
    assert (smoke["out"] / "batch.png").stat().st_size > 10000
