"""Shared fixtures of the cadmedial package tests. Run with /usr/bin/python3 (the interpreter the
module is built for); ctest sets PYTHONPATH and CADMEDIAL_CORE_DIR (see CMakeLists.txt)."""

import os
import shutil

import numpy as np
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
def torus_brep():
    # Its medial axis is the core circle: the engine's mesh has 1-D edges there.
    return os.path.join(DATA, "torus_10_3.brep")


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


def canonical(result, decimals=9):
    """The medial mesh independent of vertex and face order (the engine's order varies from run
    to run): rows (x, y, z, radius) sorted, the sorted list of faces, each face given by its
    kind, solid and the sorted rounded coordinates of its vertices, and the sorted list of 1-D
    edges, each given by its solid and the sorted rounded coordinates of its ends."""
    rows = np.round(np.column_stack([result.vertices, result.radius]), decimals)
    rows = rows[np.lexsort(rows.T[::-1])]
    points = [tuple(p) for p in np.round(result.vertices, decimals).tolist()]
    faces = sorted((int(kind), int(solid), tuple(sorted(points[v] for v in face)))
                   for face, kind, solid in zip(result.faces, result.face_kind, result.face_solid))
    edges = sorted((int(solid), tuple(sorted(points[v] for v in edge)))
                   for edge, solid in zip(result.edges.tolist(), result.edge_solid))
    return rows, faces, edges


def assert_same_mesh(a, b):
    """Same vertices with the same radii, the same faces and the same edges, in any order."""
    assert (a.num_vertices, a.num_faces, a.num_edges) == (b.num_vertices, b.num_faces, b.num_edges)
    rows_a, faces_a, edges_a = canonical(a)
    rows_b, faces_b, edges_b = canonical(b)
    # Sources differ in their last digits (BREP text vs file vs shape); circumcentres of nearly
    # cospherical samples amplify that to ~1e-8 on a part 30 units long.
    np.testing.assert_allclose(rows_a, rows_b, rtol=0, atol=1e-7)
    assert faces_a == faces_b
    assert edges_a == edges_b
