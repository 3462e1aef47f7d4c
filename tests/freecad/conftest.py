"""FreeCAD tests. test_app.py runs inside freecadcmd (see run_pytest.py and CMakeLists.txt),
where the report view's messages go to stderr; test_gui.py runs from /usr/bin/python3 and starts
the FreeCAD GUI itself under Xvfb."""

import json
import os
import shutil
import subprocess

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, os.pardir, os.pardir))
DATA = os.path.join(REPO, "tests", "python", "data")


@pytest.fixture
def data():
    return lambda name: os.path.join(DATA, name)


GUI_TIMEOUT = 600


def run_gui_script(tmp_path_factory, script, report_name, keep=(), unset=("PYTHONPATH", "CADMEDIAL_CORE_DIR"),
                   check_status=False):
    """Installs the addon into a temporary HOME, runs ``script`` (beside this file) in the real
    FreeCAD GUI under Xvfb, and returns (its report ``report_name`` as a dict, out folder, home).
    Skips when xvfb-run or freecad is missing. The files named in ``keep`` are copied to
    $CADMEDIAL_SCREENSHOT_DIR when it is set. ``unset``: variables removed so that the installed
    addon alone must be enough. check_status: FreeCAD must also exit with status 0."""
    needed = {"xvfb-run": "apt-get install xvfb xauth", "freecad": "apt-get install freecad"}
    missing = ["%s (%s)" % (tool, how) for tool, how in needed.items() if shutil.which(tool) is None]
    if missing:
        pytest.skip("the GUI test needs " + ", ".join(missing))
    home = tmp_path_factory.mktemp("home")
    out = tmp_path_factory.mktemp("gui")
    build = os.environ.get("CADMEDIAL_BUILD_DIR", os.path.join(REPO, "build"))
    subprocess.run([os.path.join(REPO, "tools", "install_addon.sh"), "--build-dir", build,
                    "--dest", str(home / ".local/share/FreeCAD/Mod/MedialAxis")],
                   check=True, capture_output=True, text=True)
    env = dict(os.environ, HOME=str(home), CADMEDIAL_GUI_OUT=str(out),
               # FreeCAD's Start page embeds Chromium, which refuses to run as root sandboxed.
               QTWEBENGINE_DISABLE_SANDBOX="1", QTWEBENGINE_CHROMIUM_FLAGS="--no-sandbox",
               LIBGL_ALWAYS_SOFTWARE="1")
    for name in unset:
        env.pop(name, None)
    run = subprocess.run(["xvfb-run", "-a", "-s", "-screen 0 1400x1000x24", "freecad",
                          os.path.join(HERE, script)],
                         env=env, capture_output=True, text=True, timeout=GUI_TIMEOUT)
    report_path = out / report_name
    assert report_path.exists(), "FreeCAD ended (status %d) without a report:\n%s\n%s" % (
        run.returncode, run.stdout[-3000:], run.stderr[-3000:])
    report = json.loads(report_path.read_text())
    target = os.environ.get("CADMEDIAL_SCREENSHOT_DIR")
    if target:
        os.makedirs(target, exist_ok=True)
        for name in keep:
            if (out / name).exists():
                shutil.copy(out / name, target)
    assert "exception" not in report, report["exception"]
    if check_status:
        assert run.returncode == 0, run.stderr[-3000:]
    report["out"] = out
    report["home"] = home
    return report, out, home
