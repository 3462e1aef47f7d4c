"""The Wall thickness command in the real FreeCAD GUI under Xvfb (thickness_gui_smoke.py): the thin
rib of a plate is listed as thin, a click selects its face; a screenshot is kept."""

import json
import os
import shutil
import subprocess

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, os.pardir, os.pardir))


@pytest.fixture(scope="module")
def smoke(tmp_path_factory):
    for tool in ("xvfb-run", "freecad"):
        if shutil.which(tool) is None:
            pytest.skip("the GUI test needs %s" % tool)
    home = tmp_path_factory.mktemp("home")
    out = tmp_path_factory.mktemp("gui")
    build = os.environ.get("CADMEDIAL_BUILD_DIR", os.path.join(REPO, "build"))
    subprocess.run([os.path.join(REPO, "tools", "install_addon.sh"), "--build-dir", build,
                    "--dest", str(home / ".local/share/FreeCAD/Mod/MedialAxis")],
                   check=True, capture_output=True, text=True)
    env = dict(os.environ, HOME=str(home), CADMEDIAL_GUI_OUT=str(out),
               QTWEBENGINE_DISABLE_SANDBOX="1", QTWEBENGINE_CHROMIUM_FLAGS="--no-sandbox",
               LIBGL_ALWAYS_SOFTWARE="1")
    for name in ("PYTHONPATH", "CADMEDIAL_CORE_DIR"):
        env.pop(name, None)
    subprocess.run(["xvfb-run", "-a", "-s", "-screen 0 1400x1000x24", "freecad",
                    os.path.join(HERE, "thickness_gui_smoke.py")],
                   env=env, capture_output=True, text=True, timeout=600)
    report = json.loads((out / "thickness.json").read_text())
    keep = os.environ.get("CADMEDIAL_SCREENSHOT_DIR")
    if keep and (out / "thickness.png").exists():
        os.makedirs(keep, exist_ok=True)
        shutil.copy(out / "thickness.png", keep)
    assert "exception" not in report, report["exception"]
    report["out"] = out
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
