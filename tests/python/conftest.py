"""Shared fixtures of the cadmedial package tests. Run with /usr/bin/python3 (the interpreter the
module is built for); ctest sets PYTHONPATH and CADMEDIAL_CORE_DIR (see CMakeLists.txt)."""

import os
import shutil

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, os.pardir, os.pardir))
DATA = os.path.join(HERE, "data")

# Small densities keep each compute to a fraction of a second.
SAMPLES = 3000


@pytest.fixture
def data():
    return lambda name: os.path.join(DATA, name)


@pytest.fixture
def box_step():
    return os.path.join(DATA, "box_10x20x30.step")


@pytest.fixture
def box_brep_text():
    with open(os.path.join(DATA, "box_10x20x30.brep")) as f:
        return f.read()


@pytest.fixture
def cli():
    """Path of the cadmedial program: $CADMEDIAL_CLI (set by ctest), else build/cadmedial."""
    path = os.environ.get("CADMEDIAL_CLI") or os.path.join(REPO, "build", "cadmedial")
    if not (os.path.isfile(path) and os.access(path, os.X_OK)):
        found = shutil.which("cadmedial")
        if found is None:
            pytest.skip("the cadmedial program is not built (set CADMEDIAL_CLI)")
        path = found
    return path
