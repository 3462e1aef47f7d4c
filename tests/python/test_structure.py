"""cadmedial.structure on analytic solids, against their exact medial axis.

The exact axis of a box a x b x c (a > b > c), by reasoning: a point of the axis is a centre of a
maximal ball, equidistant from two or more faces and nearer to them than to the others.
- The two largest faces (c apart) give the mid-plane z = c/2, where the ball (radius c/2) fits
  between the four side faces: the rectangle [c/2, a - c/2] x [c/2, b - c/2]. No other pair of
  opposite faces gives a sheet: a ball b/2 or a/2 wide does not fit in the height c.
- Each of the 12 edges gives its bisector plane, at 45 degrees to both faces, from the edge
  inward until the ball (radius t at depth t) reaches a third face: the 4 edges of length a give
  trapezoids a -> a - c wide, c/2 * sqrt(2) high, ending on the long sides of the rectangle; the
  4 edges of length b trapezoids b -> b - c ending on its short sides; the 4 edges of length c
  triangles whose apex is a corner of the rectangle. 13 sheets.
- Seams, where three sheets meet: each side of the rectangle (the mid-plane and the two edge
  sheets of that side) and, from each of the 8 corners of the box to the nearest corner of the
  rectangle, the line x = y = z (from the corner) where its three edges' sheets meet:
  4 + 8 = 12 seams, the corner ones c/2 * sqrt(3) long.
- Junctions: the 4 corners of the rectangle, where two sides and two corner seams meet (degree
  4); the corner seams end at the box's 8 corners (degree 1).
- Rims: each sheet but the mid-plane reaches the boundary along its edge: 12 rims, the edges.
A plate is such a box with c small: the mid-plane is one big sheet and the 12 edge sheets are
narrow bands along the rim. A block with a hole of radius rh through its height c (centred, far
from the sides) keeps this structure, with a hole of radius rh + c/2 in the mid-plane and, from
each circular edge of the hole, the cone where the ball touches the hole and the top (or
bottom) face: z = c - t at r = rh + t, up to t = c/2; they meet the mid-plane along the circle
r = rh + c/2 (a closed seam of three sheets, no junction): 15 sheets, 13 seams. A cylinder of
radius R and height H > 2R: the segment of its axis from z = R to H - R (balls of radius R
touching the whole side: a curve, no sheet) and the two cones z = R - r (bottom) where the ball
touches the side and an end disk; the cones' rims are the two circular edges.

Tolerances are in spacings h of the sampling.
"""
import json
import math
import os
import sys

import numpy as np
import pytest

sys.path.append("/usr/lib/freecad/lib")
FreeCAD = pytest.importorskip("FreeCAD")
Part = pytest.importorskip("Part")

import cadmedial  # noqa: E402
import cadmedial.structure  # noqa: E402
from cadmedial.structure import SEAM  # noqa: E402

ROOT2, ROOT3 = math.sqrt(2), math.sqrt(3)


def box_faces(a, b, c):
    """The 6 faces of [0,a]x[0,b]x[0,c] as (outward normal, n . x on the face)."""
    out = []
    for k, size in enumerate((a, b, c)):
        n = np.zeros(3)
        n[k] = -1
        out.append((n.copy(), 0.0))
        n[k] = 1
        out.append((n, float(size)))
    return out


def bisector(f, g):
    """(unit normal, offset) of the plane equidistant from faces f and g (inside distance
    d - n . x): (n_g - n_f) . x = d_g - d_f."""
    n = g[0] - f[0]
    return n / np.linalg.norm(n), (g[1] - f[1]) / np.linalg.norm(n)


def polygon_area_centroid(corners):
    """(area, centroid) of a planar polygon given by its corners in order."""
    p = np.asarray(corners, dtype=float)
    cross = np.cross(p[1:-1] - p[0], p[2:] - p[0])
    areas = 0.5 * np.linalg.norm(cross, axis=1)
    centres = (p[0] + p[1:-1] + p[2:]) / 3
    return areas.sum(), (areas[:, None] * centres).sum(axis=0) / areas.sum()


def exact_box_axis(a, b, c):
    """The exact axis of the box [0,a]x[0,b]x[0,c], a >= b > c (see the module docstring):
    sheets [(normal, offset, area, centroid)], seams [(p, q)], meeting points, box corners, and
    for each sheet the pair of box_faces() it bisects."""
    faces = box_faces(a, b, c)
    size = np.array([a, b, c], dtype=float)
    h = c / 2
    meet = [np.array([x, y, h]) for x in (h, a - h) for y in (h, b - h)]

    def nearest_meet(p):
        return min(meet, key=lambda m: np.linalg.norm(m - p))

    sheets = [(*bisector(faces[4], faces[5]), [meet[0], meet[1], meet[3], meet[2]], (4, 5))]
    for i in range(6):
        for j in range(i + 1, 6):
            ki, kj = i // 2, j // 2
            if ki == kj:
                continue
            along = 3 - ki - kj  # the edge runs along this axis
            p = np.zeros(3)
            p[ki], p[kj] = size[ki] * (i % 2), size[kj] * (j % 2)
            q = p.copy()
            q[along] = size[along]
            corners = [p, q, nearest_meet(q)]
            if np.linalg.norm(nearest_meet(q) - nearest_meet(p)) > 0:
                corners.append(nearest_meet(p))  # a trapezoid, else a triangle
            sheets.append((*bisector(faces[i], faces[j]), corners, (i, j)))
    seams = [(meet[0], meet[1]), (meet[2], meet[3]), (meet[0], meet[2]), (meet[1], meet[3])]
    corners = [np.array([x, y, z]) for x in (0, a) for y in (0, b) for z in (0, c)]
    for p in corners:
        seams.append((p, nearest_meet(p)))
    return ([(n, d, *polygon_area_centroid(poly)) for n, d, poly, _ in sheets],
            seams, meet, corners, [pair for *_, pair in sheets])


def segment_distance(points, p, q):
    """(N,) distances of points to the segment pq."""
    d = q - p
    t = np.clip((points - p) @ d / (d @ d), 0, 1)
    return np.linalg.norm(points - (p + t[:, None] * d), axis=1)


def axis_of(shape, samples=20000):
    result = cadmedial.compute(shape, samples=samples)
    return result, cadmedial.structure(result)


def match_planar_sheets(result, s, exact, tol):
    """For each exact planar sheet (normal, offset, area, centroid), the found sheet whose
    vertices lie on its plane (RMS distance under tol; of those, the one whose centroid is
    nearest: two sheets of a square block share a plane); asserts each is found once.
    Returns [(area, found sheet id)]."""
    corner_sheet = np.repeat(s.face_sheet, result.faces.sizes())
    corners = np.asarray(result.faces.indices)
    points = [result.vertices[np.unique(corners[corner_sheet == k])] for k in range(len(s.sheets))]
    pairs = []
    for normal, offset, area, centroid in exact:
        rms = np.array([np.sqrt(np.mean((v @ normal - offset) ** 2)) for v in points])
        on_plane = np.flatnonzero(rms < tol)
        assert len(on_plane), (normal, offset, rms.min())
        k = min(on_plane,
                key=lambda k: np.linalg.norm(np.array(s.sheets[k]["centroid"]) - centroid))
        pairs.append((area, int(k)))
    assert len({k for _, k in pairs}) == len(exact)
    return pairs


def check_seams(result, found, exact_seams, tol):
    """Each found seam lies within tol of one exact seam segment and has its length within tol
    plus 2 % (the polyline zig-zags about the line, within a quarter spacing, which lengthens
    it: the plate's long seams by 1.2 %); each exact segment is matched once."""
    matched = []
    for seam in found:
        p = result.vertices[seam["vertices"]]
        far = [segment_distance(p, a, b).max() for a, b in exact_seams]
        k = int(np.argmin(far))
        assert far[k] < tol, (k, far[k])
        exact_length = np.linalg.norm(exact_seams[k][1] - exact_seams[k][0])
        assert abs(seam["length"] - exact_length) < tol + 0.02 * exact_length, \
            (seam["length"], exact_length)
        matched.append(k)
    assert sorted(matched) == list(range(len(exact_seams)))


def check_junctions(s, meet, corners, tol):
    inner = [j for j in s.junctions if j["seam_degree"] >= 3]
    ends = [j for j in s.junctions if j["seam_degree"] == 1]
    assert len(inner) == len(meet) and len(ends) == len(corners)
    assert len(s.junctions) == len(meet) + len(corners)
    assert all(j["seam_degree"] == 4 for j in inner)
    for group, exact in ((inner, meet), (ends, corners)):
        d = np.array([[np.linalg.norm(np.array(j["point"]) - e) for e in exact] for j in group])
        assert d.min(axis=1).max() < tol
        assert sorted(d.argmin(axis=1).tolist()) == list(range(len(exact)))


@pytest.mark.parametrize("samples", [3000, 20000])
def test_box_has_the_sheets_seams_and_junctions_of_its_exact_axis(samples):
    """40 x 25 x 15: 13 sheets, 12 seams, 4 meeting points and 8 seam ends, 12 rims (the
    module docstring counts them); seams within a spacing of the exact ones (measured: 0.27 h),
    junctions within half a spacing (0.03 h), areas within 2 % (0.7 %; at 3,000 samples 3 %,
    measured 1.7 %)."""
    result, s = axis_of(Part.makeBox(40, 25, 15), samples)
    h = s.spacing
    sheets, seams, meet, corners, _ = exact_box_axis(40, 25, 15)
    assert s.counts() == {"sheets": 13, "seams": 12, "junctions": 12, "rims": 12, "free": 0,
                          "curves": 0}
    for area, k in match_planar_sheets(result, s, sheets, 0.2 * h):
        assert s.sheets[k]["area"] == pytest.approx(area, rel=0.02 if samples >= 20000 else 0.03)
    # The mid-plane is the one sheet that does not reach the boundary.
    mid = [k for k, d in enumerate(s.sheets) if d["rim_length"] == 0]
    assert len(mid) == 1 and s.sheets[mid[0]]["radius_min"] > 7.5 - h
    assert sorted(s.sheets[mid[0]]["seams"]) == sorted(
        k for k, seam in enumerate(s.seams) if mid[0] in seam["sheets"])
    check_seams(result, s.seams, seams, h)
    assert all(len(seam["sheets"]) == 3 for seam in s.seams)
    check_junctions(s, meet, corners, 0.5 * h)
    rims = sorted(r["length"] for r in s.rims)
    np.testing.assert_allclose(rims, sorted([40] * 4 + [25] * 4 + [15] * 4), atol=h)
    assert all(r["radius_max"] <= h for r in s.rims)


def test_plate_is_one_big_sheet_with_narrow_rim_bands():
    """60 x 40 x 3: the mid-plane, 57 x 37 at z = 1.5, holds 72 % of the axis's area; the 12
    edge sheets are bands 1.5 * sqrt(2) wide along the rim (module docstring)."""
    result, s = axis_of(Part.makeBox(60, 40, 3))
    h = s.spacing
    sheets, seams, meet, corners, _ = exact_box_axis(60, 40, 3)
    assert len(s.sheets) == 13 and len(s.seams) == 12 and len(s.rims) == 12
    pairs = match_planar_sheets(result, s, sheets, 0.2 * h)
    for area, k in pairs:
        assert s.sheets[k]["area"] == pytest.approx(area, rel=0.05, abs=h * h)
    big = s.sheets[0]
    assert pairs[0][1] == 0  # the largest sheet is the mid-plane
    assert big["area"] == pytest.approx(57 * 37, rel=0.01)
    exact_share = 57 * 37 / sum(area for _, _, area, _ in sheets)
    assert big["area"] / sum(d["area"] for d in s.sheets) == pytest.approx(exact_share, abs=0.01)
    assert abs(big["centroid"][2] - 1.5) < 0.1 * h and abs(abs(big["normal"][2]) - 1) < 1e-3
    assert big["radius_min"] > 1.5 - h and big["rim_length"] == 0 and len(big["seams"]) == 4
    assert sum(r["length"] for r in s.rims) == pytest.approx(4 * (60 + 40 + 3), abs=h)
    check_seams(result, s.seams, seams, h)
    check_junctions(s, meet, corners, 0.5 * h)


def test_block_with_hole_has_a_ring_sheet_two_cones_and_a_circular_seam():
    """40 x 40 x 10 with a hole of radius 5 through it, centred: 15 sheets, 13 seams (the circle
    r = 10 at z = 5 closed, no junction on it), 4 + 8 junctions, 14 rims (12 edges, 2 circles)."""
    hole = Part.makeCylinder(5, 10, FreeCAD.Vector(20, 20, 0))
    result, s = axis_of(Part.makeBox(40, 40, 10).cut(hole))
    h = s.spacing
    sheets, seams, meet, corners, _ = exact_box_axis(40, 40, 10)
    sheets[0] = (sheets[0][0], sheets[0][1], 30 * 30 - math.pi * 10 ** 2, sheets[0][3])
    assert s.counts() == {"sheets": 15, "seams": 13, "junctions": 12, "rims": 14, "free": 0,
                          "curves": 0}
    for area, k in match_planar_sheets(result, s, sheets, 0.2 * h):
        assert s.sheets[k]["area"] == pytest.approx(area, rel=0.02)
    ring = [seam for seam in s.seams if seam["closed"]]
    assert len(ring) == 1 and ring[0]["length"] == pytest.approx(2 * math.pi * 10, abs=h)
    p = result.vertices[ring[0]["vertices"]]
    assert np.abs(np.hypot(p[:, 0] - 20, p[:, 1] - 20) - 10).max() < 2 * h
    assert np.abs(p[:, 2] - 5).max() < 2 * h
    # Its three sheets: the ring-shaped mid-plane and the two cones.
    cones = [k for k in ring[0]["sheets"] if k != 0]
    assert 0 in ring[0]["sheets"] and len(cones) == 2
    for k in cones:
        assert s.sheets[k]["area"] == pytest.approx(math.pi * (5 + 10) * 5 * ROOT2, rel=0.02)
        assert s.sheets[k]["rim_length"] == pytest.approx(2 * math.pi * 5, abs=h)
    check_seams(result, [seam for seam in s.seams if not seam["closed"]], seams, h)
    check_junctions(s, meet, corners, 0.5 * h)


def test_cylinder_is_its_axis_curve_and_two_cones():
    """Radius 5, height 40: one curve, the segment z = 5 .. 35 of the axis with radius 5, drawn
    by the engine as a bundle of sliver faces (a tube); two cone sheets (area pi * 5 * 5 * sqrt 2
    each) with the circular edges as rims; no seam; the curve's ends are junctions at the cones'
    apexes, each naming its cone."""
    result, s = axis_of(Part.makeCylinder(5, 40))
    h = s.spacing
    assert len(s.curves) == 1 and len(s.sheets) == 2 and len(s.seams) == 0
    curve = s.curves[0]
    p = result.vertices[curve["vertices"]]
    assert np.hypot(p[:, 0], p[:, 1]).max() < 0.5 * h
    assert sorted(e[2] for e in curve["ends"]) == pytest.approx([5, 35], abs=h)
    assert curve["length"] == pytest.approx(30, abs=2 * h)
    assert curve["radius_min"] > 5 - 0.05 * h and curve["radius_max"] < 5 + 1e-6
    # Every face is in a cone or in the tube.
    assert np.all((s.face_sheet >= 0) != (s.face_curve >= 0))
    assert (s.face_curve == 0).sum() > 0.5 * result.num_faces
    for k, z in ((0, 35), (1, 5)):
        cone = s.sheets[k]
        assert cone["area"] == pytest.approx(math.pi * 25 * ROOT2, rel=0.02)
        assert cone["rim_length"] == pytest.approx(2 * math.pi * 5, abs=h)
    assert sorted(s.sheets[k]["centroid"][2] > 20 for k in (0, 1)) == [False, True]
    assert len(s.rims) == 2 and all(r["closed"] for r in s.rims)
    apexes = sorted(j["point"][2] for j in s.junctions if j["curve_ends"])
    assert apexes == pytest.approx([5, 35], abs=h)
    # Each end of the axis meets the cone on its side.
    for j in s.junctions:
        assert len(j["sheets"]) == 1
        assert (s.sheets[j["sheets"][0]]["centroid"][2] > 20) == (j["point"][2] > 20)


def test_cylinder_without_merging_is_thousands_of_sliver_sheets():
    """The raw labels (merge_slivers=False): the axis's bundle of slivers makes every face near
    the axis a sheet of its own, which is why slivers are merged."""
    result = cadmedial.compute(Part.makeCylinder(5, 40), samples=20000)
    raw = cadmedial.structure(result, merge_slivers=False)
    assert len(raw.sheets) > 1000 and len(raw.curves) == 0
    assert (raw.edge_kind == SEAM).sum() > 10000


def test_torus_core_is_one_closed_curve():
    """tests/python/data/torus_10_3.brep (major radius 10, minor 3): its axis is the core
    circle, which the engine gives partly as 1-D edges and partly as a tube: one closed curve of
    length 2 pi 10 and radius 3."""
    path = os.path.join(os.path.dirname(__file__), "data", "torus_10_3.brep")
    result = cadmedial.compute(path, samples=20000)
    s = cadmedial.structure(result)
    h = s.spacing
    assert len(s.curves) == 1 and len(s.sheets) == 0
    curve = s.curves[0]
    assert curve["closed"] and curve["length"] == pytest.approx(2 * math.pi * 10, abs=2 * h)
    p = result.vertices[curve["vertices"]]
    assert np.hypot(np.hypot(p[:, 0], p[:, 1]) - 10, p[:, 2]).max() < h
    assert curve["radius_min"] > 3 - h and curve["radius_max"] < 3 + 1e-6


def test_labels_follow_the_edges_and_the_tables_are_plain_data(tmp_path):
    """Two core faces across an edge of exactly two faces share a sheet; a seam edge has three
    faces or more; a loaded file (no stats) gives the same structure from its own spacing
    estimate; to_dict() is JSON."""
    from cadmedial.structure.edge_table import edge_table
    result, s = axis_of(Part.makeBox(40, 25, 15), 3000)
    table = edge_table(result.faces, result.num_vertices)
    assert np.array_equal(table.pairs, s.edges)
    pairs = np.flatnonzero(table.count == 2)
    f0 = table.faces[table.face_start[pairs]]
    f1 = table.faces[table.face_start[pairs] + 1]
    assert np.array_equal(s.face_sheet[f0], s.face_sheet[f1])
    assert np.all(table.count[s.edge_kind == SEAM] >= 3)
    path = tmp_path / "box.ply"
    result.save(path)
    loaded = cadmedial.structure(cadmedial.load(path))
    assert loaded.counts() == s.counts()
    assert 0.2 * s.spacing < loaded.spacing < 5 * s.spacing
    text = json.dumps(s.to_dict())
    back = json.loads(text)
    assert len(back["sheets"]) == 13 and back["spacing"] == s.spacing


def test_cadmedial_structure_loads_on_first_use(tmp_path):
    """``import cadmedial`` alone: cadmedial.structure(result) is the structure (the attribute
    loads the subpackage), with the counts computed in this process for the same file."""
    import subprocess
    result = cadmedial.compute(Part.makeBox(40, 25, 15), samples=3000)
    path = tmp_path / "box.ply"
    result.save(path)
    expected = cadmedial.structure(cadmedial.load(path)).counts()
    code = ("import json, sys, cadmedial; assert 'cadmedial.structure' not in sys.modules; "
            "print(json.dumps(cadmedial.structure(cadmedial.load(sys.argv[1])).counts()))")
    out = subprocess.run([sys.executable, "-c", code, str(path)], capture_output=True, text=True,
                         check=True, env=dict(os.environ))
    assert json.loads(out.stdout) == expected
    assert expected["sheets"] == 13


def test_each_sheet_and_curve_names_its_solid():
    """Two solids, a box and a cylinder apart: the box's 13 sheets are of solid 0 or 1 and the
    cylinder's two cones and axis of the other; faces of a sheet are all of its solid."""
    box = Part.makeBox(40, 25, 15)
    rod = Part.makeCylinder(5, 40, FreeCAD.Vector(100, 0, 0))
    result = cadmedial.compute(Part.makeCompound([box, rod]), samples=20000)
    s = cadmedial.structure(result)
    h = s.spacing
    by_solid = {}
    for k, d in enumerate(s.sheets):
        assert np.all(result.face_solid[s.face_sheet == k] == d["solid"])
        by_solid.setdefault(d["solid"], []).append(k)
    assert sorted(len(v) for v in by_solid.values()) == [2, 13]
    rod_solid = [k for k, v in by_solid.items() if len(v) == 2][0]
    assert len(s.curves) == 1 and s.curves[0]["solid"] == rod_solid
    assert s.curves[0]["length"] == pytest.approx(30, abs=2 * h)
    assert all(c["centroid"][0] > 90 for c in (s.sheets[k] for k in by_solid[rod_solid]))


def test_sheets_name_the_two_faces_their_balls_touch():
    """With shape=: each sheet of the 40 x 25 x 15 box touches exactly the two faces it bisects
    (about half the probes each), each rim names the two faces of the edge it lies on; the
    cylinder's cones touch its side and one end disk."""
    box = Part.makeBox(40, 25, 15)
    result = cadmedial.compute(box, samples=20000)
    s = cadmedial.structure(result, shape=box)
    h = s.spacing
    sheets, _, _, _, pairs = exact_box_axis(40, 25, 15)
    planes = box_faces(40, 25, 15)

    def plane_index(face):
        n = np.array(face.normalAt(0, 0))
        d = n @ np.array(face.CenterOfMass)
        return min(range(6), key=lambda k: np.linalg.norm(planes[k][0] - n) + abs(planes[k][1] - d))

    name = [plane_index(f) for f in box.Faces]
    for (area, k), pair in zip(match_planar_sheets(result, s, sheets, 0.2 * h), pairs):
        touches = s.sheets[k]["touches"]
        assert sorted(name[f] for f, _ in touches) == sorted(pair)
        assert all(share == pytest.approx(0.5, abs=0.05) for _, share in touches)
    # Each rim lies on the B-rep edge between the two faces it names.
    assert len(s.rims) == 12
    for rim in s.rims:
        f, g = sorted(f for f, _ in rim["touches"])
        assert len(rim["touches"]) == 2
        edge = [e for e in box.Faces[f].Edges if any(e.isSame(x) for x in box.Faces[g].Edges)]
        assert len(edge) == 1
        ends = [Part.Vertex(*result.vertices[v]) for v in np.unique(rim["edges"])]
        assert max(edge[0].distToShape(v)[0] for v in ends) < 1e-9 * 40
    rod = Part.makeCylinder(5, 40)
    result = cadmedial.compute(rod, samples=20000)
    s = cadmedial.structure(result, shape=rod)
    kinds = {f: type(face.Surface).__name__ for f, face in enumerate(rod.Faces)}
    for cone in s.sheets:
        touched = sorted(kinds[f] for f, share in cone["touches"] if share > 0.3)
        assert touched == ["Cylinder", "Plane"]
        disk = [f for f, _ in cone["touches"] if kinds[f] == "Plane"][0]
        assert abs(rod.Faces[disk].CenterOfMass.z - cone["centroid"][2]) < 5
    for rim in s.rims:  # the circular edges, between the side and a disk
        assert sorted(kinds[f] for f, _ in rim["touches"]) == ["Cylinder", "Plane"]


def test_thin_plate_keeps_its_corner_triangles():
    """60 x 40 x 0.5: the exact corner triangles (the sheets of the 4 edges 0.5 long) have area
    0.5 * 0.5 * 0.25 * sqrt 2 = 0.088, under half a spacing squared; the engine samples the thin
    plate finer and resolves them, so they are sheets, not slivers (slivers.local_spacing):
    4 of them, each at its corner, in its bisector plane."""
    result, s = axis_of(Part.makeBox(60, 40, 0.5))
    h = s.spacing
    exact = 0.5 * 0.5 * 0.25 * ROOT2
    assert exact < 0.5 * h * h
    small = [d for d in s.sheets if d["area"] < 10 * exact]
    assert len(small) == 4
    corners = {(x, y) for x in (0, 60) for y in (0, 40)}
    for d in small:
        assert d["area"] == pytest.approx(exact, rel=0.1)
        x, y, z = d["centroid"]
        corner = min(corners, key=lambda c: math.hypot(x - c[0], y - c[1]))
        assert math.hypot(x - corner[0], y - corner[1]) < 0.5 and abs(z - 0.25) < 0.05
        assert abs(d["normal"][2]) < 0.05  # vertical, as the edge
        corners.discard(corner)
    assert not corners


def _mesh(vertices, radius, faces, edges=None):
    from cadmedial import _core
    from cadmedial.result import MedialAxisResult
    start = np.r_[0, np.cumsum([len(f) for f in faces])].astype(np.int32)
    flat = np.array([v for f in faces for v in f], dtype=np.int32)
    args = [np.asarray(vertices, float), np.asarray(radius, float), start, flat,
            np.zeros(len(faces), np.uint8), np.zeros(len(faces), np.int32)]
    if edges is not None:
        args += [np.asarray(edges, np.int32), np.zeros(len(edges), np.int32)]
    return MedialAxisResult(_core.MedialMesh(*args), {})


def test_three_wings_on_one_edge_are_three_sheets_and_a_seam():
    """Three unit squares on the segment (0,0,0)-(0,0,1), 120 degrees apart, their far sides on
    the boundary (radius 0): 3 sheets, 1 seam of length 1 joining all three, ending in two
    junctions of degree 1; 3 rims (the far sides), each wing's two other sides free borders."""
    v = [[0, 0, 0], [0, 0, 1]]
    faces = []
    for k in range(3):
        a = 2 * math.pi * k / 3
        d = [math.cos(a), math.sin(a), 0]
        v += [[d[0], d[1], 0], [d[0], d[1], 1]]
        faces.append([0, 1, 3 + 2 * k, 2 + 2 * k])
    radius = [1, 1] + [0] * 6
    s = cadmedial.structure(_mesh(v, radius, faces), spacing=0.1)
    assert s.counts() == {"sheets": 3, "seams": 1, "junctions": 2, "rims": 3, "free": 6,
                          "curves": 0}
    seam = s.seams[0]
    assert seam["length"] == pytest.approx(1) and sorted(seam["sheets"]) == [0, 1, 2]
    assert sorted(j["seam_degree"] for j in s.junctions) == [1, 1]
    assert all(r["length"] == pytest.approx(1) for r in s.rims)
    # Without the third wing the other two are one sheet: no seam, no junction.
    s = cadmedial.structure(_mesh(v, radius, faces[:2]), spacing=0.1)
    assert s.counts()["sheets"] == 1 and s.counts()["seams"] == 0


def test_a_short_straight_curve_stays_open():
    """A 1-D polyline 3 spacings long (ends 3 h apart, as close as curves get linked): one open
    curve of length 3 with a junction at each end, not a loop."""
    v = [[0, 0, 0], [1, 0, 0], [2, 0, 0], [3, 0, 0]]
    s = cadmedial.structure(_mesh(v, [1] * 4, [], edges=[[0, 1], [1, 2], [2, 3]]), spacing=1.0)
    assert len(s.curves) == 1 and not s.curves[0]["closed"]
    assert s.curves[0]["length"] == pytest.approx(3)
    assert sorted(j["point"][0] for j in s.junctions) == [0, 3]


def test_tee_of_two_rods_is_three_axis_curves_with_their_end_cones():
    """A rod R 3 along x (0 .. 60) and one along y from its middle (30, 0 .. 30): the axis has
    three curves, the arms' axis lines, radius 3, and a cone (area pi * 3 * 3 sqrt 2) at each
    free end, each met by its arm's curve; the arms meet in a sheet round the T's centre."""
    a = Part.makeCylinder(3, 60, FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(1, 0, 0))
    b = Part.makeCylinder(3, 30, FreeCAD.Vector(30, 0, 0), FreeCAD.Vector(0, 1, 0))
    # At 20,000 samples the spacing (1.85) is over half the radius and the cones' areas are
    # 15 % off; 50,000 give 0.16.
    result, s = axis_of(a.fuse(b).removeSplitter(), 50000)
    h = s.spacing
    assert len(s.curves) == 3
    lines = [((0, 0, 0), (60, 0, 0)), ((30, 0, 0), (30, 30, 0))]
    cones = [k for k, d in enumerate(s.sheets)
             if d["area"] == pytest.approx(math.pi * 9 * ROOT2, rel=0.05)]
    apex = {k: np.array(s.sheets[k]["centroid"]) for k in cones}
    assert len(cones) == 3
    for c in s.curves:
        p = result.vertices[c["vertices"]]
        assert min(segment_distance(p, np.array(u, float), np.array(v, float)).max()
                   for u, v in lines) < h
        assert c["radius_max"] == pytest.approx(3, abs=1e-6) and c["radius_min"] > 3 - h
        ends = [j for j in s.junctions if j["curve_ends"] and
                min(np.linalg.norm(np.array(j["point"]) - p[[0, -1]], axis=1)) < 1e-9]
        met = {k for j in ends for k in j["sheets"]} & set(cones)
        assert len(met) == 1  # its own end cone, the nearest of the three
        k = met.pop()
        assert min(np.linalg.norm(p[[0, -1]] - apex[k], axis=1)) < 3 + 2 * h
