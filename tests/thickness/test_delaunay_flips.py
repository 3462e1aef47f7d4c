"""The flips that look again only around the last round's flips give the mesh that full rounds
over every side give, on BRepMesh's strips of a tube and a filleted box bisected (no flips
between) until the flips come in chains over several rounds."""

import numpy as np
import pytest

from conftest import Part, tube
from cadmedial.thickness.delaunay_flips import flip_round, flip_until_delaunay
from cadmedial.thickness.surface_mesh import _merge_coincident, _split_long_sides


def split(points, triangles, faces, times):
    for _ in range(times):  # bisection without projection: long strips of slivers to flip
        points, triangles, faces, _ = _split_long_sides(points, triangles, faces, 0.2,
                                                       lambda p, f: p)
    return points, triangles, faces


def brepmesh(shape, deflection):
    pts, tris, faces, offset = [], [], [], 0
    for i, face in enumerate(shape.Faces):
        p, t = face.tessellate(deflection)
        pts.append(np.array([tuple(q) for q in p]))
        tris.append(np.asarray(t, dtype=np.int64) + offset)
        faces.append(np.full(len(t), i))
        offset += len(p)
    points, triangles = _merge_coincident(np.vstack(pts), np.vstack(tris), 1e-9)
    return points, triangles, np.concatenate(faces)


def filleted_box():
    box = Part.makeBox(20, 10, 5)
    return box.makeFillet(2, box.Edges[:4])


@pytest.mark.parametrize("make, splits", [(tube, 3), (tube, 4), (filleted_box, 1)],
                         ids=["tube3", "tube4", "filleted_box"])
def test_flips_equal_full_rounds(make, splits):
    points, triangles, faces = split(*brepmesh(make(), 0.05), splits)
    rounds, full, counts = 12, triangles, []
    for _ in range(rounds):
        full, flipped = flip_round(points, full, faces)
        counts.append(flipped)
        if not flipped:
            break
    assert counts[0] > 100 and len(counts) > 4  # chains of flips over several rounds
    assert np.array_equal(flip_until_delaunay(points, triangles, faces, rounds), full)


def test_flips_stop_delaunay():
    shape = filleted_box()
    points, triangles, faces = split(*brepmesh(shape, 0.05), 2)
    done = flip_until_delaunay(points, triangles, faces, rounds=1000)
    assert flip_round(points, done, faces)[1] == 0  # no side left to flip
    # Each triangle keeps its face: a planar face's area is unchanged (a curved one's chords move).
    def area(t):
        a, b, c = (points[t[:, i]] for i in range(3))
        return np.bincount(faces, 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1))
    planar = np.array([type(f.Surface).__name__ == "Plane" for f in shape.Faces])
    assert planar.sum() >= 6
    assert np.allclose(area(done)[planar], area(triangles)[planar], rtol=1e-9)
    assert np.allclose(area(done), area(triangles), rtol=1e-2)
