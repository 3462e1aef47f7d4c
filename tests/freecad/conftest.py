"""FreeCAD tests. test_app.py runs inside freecadcmd (see run_pytest.py and CMakeLists.txt),
where the report view's messages go to stderr; test_gui.py runs from /usr/bin/python3 and starts
the FreeCAD GUI itself under Xvfb."""

import os

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, os.pardir, os.pardir))
DATA = os.path.join(REPO, "tests", "python", "data")


@pytest.fixture
def data():
    return lambda name: os.path.join(DATA, name)
