"""cadmedial.simplify and --simplify: the compact mesh has the full mesh's topology, and every
ball of either lies within the tolerance of the other (measured here with numpy, independently
of the simplifier's own bookkeeping), on real parts and the generator's hard solids."""

import json
import os
import subprocess

import numpy as np
import pytest
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree

import cadmedial
from conftest import REPO

MODELS = os.path.join(REPO, os.pardir, "shared", "data", "models")


def euler_and_pieces(result):
    """V - E + F over the vertices that faces or edges use, and the connected pieces."""
    tri, _ = result.faces.triangulate()
    sides = set()
    for f in result.faces:
        n = len(f)
        for k in range(n):
            a, b = int(f[k]), int(f[(k + 1) % n])
            sides.add((min(a, b), max(a, b)))
    for a, b in np.asarray(result.edges):
        sides.add((min(a, b), max(a, b)))
    used = np.unique(np.concatenate([np.asarray(result.faces.indices), np.asarray(result.edges).ravel()]))
    s = np.array(sorted(sides)) if sides else np.zeros((0, 2), int)
    n = result.num_vertices
    g = coo_matrix((np.ones(len(s)), (s[:, 0], s[:, 1])), shape=(n, n))
    _, label = connected_components(g, directed=False)
    return len(used) - len(sides) + result.num_faces, len(np.unique(label[used]))


def ball_to_triangles(p, r, A, B, C, RA, RB, RC):
    """min over triangles of |p - q| + |r - r(q)|, q the point of each triangle nearest p
    (inside: the projection; else the nearest point of its sides), r(q) interpolated."""
    best = np.inf
    AB, AC = B - A, C - A
    n = np.cross(AB, AC)
    n2 = np.einsum("ij,ij->i", n, n)
    ok = n2 > 0
    if ok.any():
        t = np.einsum("ij,ij->i", p - A[ok], n[ok]) / n2[ok]
        q = p - t[:, None] * n[ok]
        wb = np.einsum("ij,ij->i", np.cross(q - A[ok], AC[ok]), n[ok]) / n2[ok]
        wc = np.einsum("ij,ij->i", np.cross(AB[ok], q - A[ok]), n[ok]) / n2[ok]
        wa = 1 - wb - wc
        inside = (wa >= 0) & (wb >= 0) & (wc >= 0)
        if inside.any():
            rq = wa * RA[ok] + wb * RB[ok] + wc * RC[ok]
            d = np.linalg.norm(q - p, axis=1) + np.abs(r - rq)
            best = float(np.min(d[inside]))
    for P, Q, RP, RQ in ((A, B, RA, RB), (B, C, RB, RC), (A, C, RA, RC)):
        PQ = Q - P
        l2 = np.einsum("ij,ij->i", PQ, PQ)
        t = np.clip(np.einsum("ij,ij->i", p - P, PQ) / np.where(l2 > 0, l2, 1), 0, 1)
        q = P + t[:, None] * PQ
        d = np.linalg.norm(q - p, axis=1) + np.abs(r - (RP + t * (RQ - RP)))
        best = min(best, float(np.min(d)))
    return best


def worst_gap(src, dst, tol, probe):
    """The largest ball distance from the points of `src` (vertices, or lattice points of its
    triangles with probe=True) to the triangles of `dst`, over points whose nearest triangle
    is within reach."""
    tri, _ = dst.triangles(), None
    V, R = np.asarray(dst.vertices), np.asarray(dst.radius)
    A, B, C = V[tri[:, 0]], V[tri[:, 1]], V[tri[:, 2]]
    centroid = (A + B + C) / 3
    reach = np.max(np.linalg.norm(np.stack([A, B, C]) - centroid, axis=2)) + tol
    tree = cKDTree(centroid)
    SV, SR = np.asarray(src.vertices), np.asarray(src.radius)
    if probe:
        st = src.triangles()
        pts, rad = [], []
        for a, b in [(1 / 3, 1 / 3), (0.5, 0.5), (0.5, 0), (0, 0.5), (0.25, 0.25), (0.5, 0.25), (0.25, 0.5)]:
            w = 1 - a - b
            pts.append(a * SV[st[:, 0]] + b * SV[st[:, 1]] + w * SV[st[:, 2]])
            rad.append(a * SR[st[:, 0]] + b * SR[st[:, 1]] + w * SR[st[:, 2]])
        SV, SR = np.concatenate(pts), np.concatenate(rad)
    worst = 0.0
    for p, r, near in zip(SV, SR, tree.query_ball_point(SV, reach)):
        k = np.array(near, int)
        if len(k) == 0:
            return np.inf
        worst = max(worst, ball_to_triangles(p, r, A[k], B[k], C[k], R[tri[k, 0]], R[tri[k, 1]], R[tri[k, 2]]))
        if worst > 2 * tol:
            break
    return worst


@pytest.mark.parametrize("model", ["freecad/holesInFace2.brep", "freecad/Y_Rod_Mount.brep",
                                   "nist/nist_ctc_01_asme1_rd.stp"])
def test_compact_mesh_keeps_topology_and_every_ball(model):
    path = os.path.join(MODELS, model)
    if not os.path.exists(path):
        pytest.skip("shared model %s absent" % model)
    full = cadmedial.compute(path, samples=3000)
    small = cadmedial.simplify(full, "1%")
    tol = small.stats["simplify"]["tolerance"]
    assert tol == pytest.approx(0.01 * full.stats["diagonal"])
    assert euler_and_pieces(small) == euler_and_pieces(full)
    assert small.num_faces * 5 <= full.num_faces
    # The full mesh's vertices (with their radii) within tol of the compact mesh, exactly as
    # the simplifier promises; the compact triangles' inner points within tol of the full mesh,
    # which it checks on a lattice: the grid here may land between, hence the 25 %.
    assert worst_gap(full, small, tol, probe=False) <= tol * (1 + 1e-6)
    assert worst_gap(small, full, tol, probe=True) <= 1.25 * tol


def test_simplify_keeps_vertices_of_the_result(box_step):
    full = cadmedial.compute(box_step, samples=3000)
    small = cadmedial.simplify(full, 0.3)
    keys = {tuple(v) + (r,) for v, r in zip(np.asarray(full.vertices).tolist(), np.asarray(full.radius).tolist())}
    assert all(tuple(v) + (r,) in keys for v, r in zip(np.asarray(small.vertices).tolist(),
                                                       np.asarray(small.radius).tolist()))
    assert small.stats["simplify"]["faces_before"] == full.num_faces
    assert small.stats["simplify"]["max_error"] <= 0.3


def box_axis_gap(result):
    """Per vertex of the 10 x 20 x 30 box's axis: (second smallest - smallest) distance to its
    six planes, and |radius - smallest|. On the exact axis both are 0: the ball touches two."""
    v = np.asarray(result.vertices)
    d = np.sort(np.concatenate([v, np.array([10.0, 20.0, 30.0]) - v], axis=1), axis=1)
    return d[:, 1] - d[:, 0], np.abs(np.asarray(result.radius) - d[:, 0])


def test_compute_simplify_snaps_vertices_onto_the_exact_axis(box_step):
    full = cadmedial.compute(box_step, samples=3000)
    small = cadmedial.compute(box_step, samples=3000, simplify="0.1%")
    snap = small.stats["snap"]
    assert snap["snapped"] >= 0.8 * snap["vertices"]
    gap_full, _ = box_axis_gap(full)
    gap, radius_off = box_axis_gap(small)
    inner = np.asarray(small.radius) > 0.5  # the rims meet the edges: their vertices stay
    tol = 1e-7 * small.stats["diagonal"]
    # The Voronoi vertices are off the axis; the compact mesh's are on it, with exact radii.
    assert np.mean(gap_full[np.asarray(full.radius) > 0.5] > 1e-3) > 0.5
    assert np.mean(gap[inner] <= tol) >= 0.95
    assert np.all(radius_off <= tol)
    assert small.num_faces * 10 <= full.num_faces
    assert small.stats["simplify"]["euler_after"] == small.stats["simplify"]["euler_before"]


def test_bad_tolerances_are_refused(box_step):
    full = cadmedial.compute(box_step, samples=500)
    for bad in ["150%", "abc", -1.0, float("nan")]:
        with pytest.raises(ValueError):
            cadmedial.simplify(full, bad)


def test_cli_simplify_writes_the_compact_mesh(tmp_path, box_step, cli):
    out, stats = tmp_path / "c.ply", tmp_path / "s.json"
    run = subprocess.run([cli, "compute", box_step, "-o", str(out), "--samples", "2000", "--simplify", "1%",
                          "--stats", str(stats), "--quiet"], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    figures = json.loads(stats.read_text())["simplify"]
    written = cadmedial.load(out)
    assert written.num_faces == figures["faces_after"] < figures["faces_before"]
    assert figures["euler_after"] == figures["euler_before"]
    assert figures["max_error"] <= figures["tolerance"]
    bad = subprocess.run([cli, "compute", box_step, "-o", str(out), "--simplify", "100%"], capture_output=True,
                         text=True)
    assert bad.returncode == 2 and "--simplify" in bad.stderr


def test_simplify_with_the_source_snaps_as_compute_does(box_step):
    full = cadmedial.compute(box_step, samples=3000)
    snapped = cadmedial.simplify(full, "0.1%", source=box_step)
    computed = cadmedial.compute(box_step, samples=3000, simplify="0.1%")
    for key in ("vertices", "snapped", "max_move"):
        assert snapped.stats["snap"][key] == computed.stats["snap"][key]
    assert snapped.stats["snap"]["mean_move"] == pytest.approx(computed.stats["snap"]["mean_move"], rel=1e-12)
    assert snapped.num_faces == computed.num_faces
    gap, radius_off = box_axis_gap(snapped)
    inner = np.asarray(snapped.radius) > 0.5
    assert np.mean(gap[inner] <= 1e-7 * full.stats["diagonal"]) >= 0.95


def test_simplify_can_be_cancelled(box_step):
    full = cadmedial.compute(box_step, samples=3000)
    with pytest.raises(cadmedial.Cancelled):
        cadmedial.simplify(full, "0.1%", progress=lambda stage, fraction: fraction < 0.05)
