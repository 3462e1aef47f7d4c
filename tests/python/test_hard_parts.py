"""bench/hard_parts.py and bench/hard_eval.py.

The generator: deterministic, valid closed solids, and each solid's Euler characteristic by
construction equals two independent counts of its boundary (chi(solid) = chi(boundary) / 2 for a
solid): the B-rep's V - E + F (measures.solid_euler) and that of OpenCASCADE's tessellation of it
(a welded, closed, manifold triangle mesh), on 2 seeds per family.

The judge: on two small seeds (0: a chip and its two caps, 6: a wedge), today's engine's axis is
right, and seed 0's axis with a face deleted, or with vertices moved out of the solids, is judged
wrong for that reason.
"""
import os
import sys

import numpy as np
import pytest

sys.path.append("/usr/lib/freecad/lib")
pytest.importorskip("FreeCAD")
pytest.importorskip("Part")
sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "bench"))
import hard_parts  # noqa: E402
import measures  # noqa: E402

# 2 seeds per family; not 5, whose plate with 291 holes takes 10 s to make.
SEEDS = list(range(len(hard_parts.FAMILIES), 3 * len(hard_parts.FAMILIES)))


@pytest.mark.parametrize("seed", SEEDS)
def test_part(seed):
    import MeshPart
    shape, meta = hard_parts.generate(seed)
    again, meta2 = hard_parts.generate(seed)
    assert meta == meta2
    assert abs(shape.Volume - again.Volume) <= 1e-12 * max(shape.Volume, 1)
    assert shape.isValid()
    assert meta["family"] == hard_parts.FAMILIES[seed % len(hard_parts.FAMILIES)][0]
    assert len(shape.Solids) == len(meta["solids"])
    for solid, m in zip(shape.Solids, meta["solids"]):
        assert solid.isValid() and solid.Volume > 0
        assert all(sh.isClosed() for sh in solid.Shells)
        assert measures.solid_euler(solid) == m["euler"]
        mesh = MeshPart.meshFromShape(Shape=solid, LinearDeflection=0.01 * solid.BoundBox.DiagonalLength,
                                      AngularDeflection=0.5)
        assert mesh.isSolid() and not mesh.hasNonManifolds()
        assert mesh.CountPoints - mesh.CountEdges + mesh.CountFacets == 2 * m["euler"]


def test_hard_ranges():
    """The families reach the ranges of issue 32's hard real parts (over seeds 0-109): walls down
    to 0.1 % of the part's size or thinner (cans), wedges of 10 to 25 degrees, some under 15,
    polytopes whose sharpest edge is the wedge's, 5 to 25 degrees, some under 10."""
    import math
    import Part
    seeds = range(110)
    metas = [hard_parts.generate(s)[1] for s in hard_parts.seeds_of("can", seeds)]
    assert min(m["params"]["wall_rel_diag"] for m in metas) < 0.001
    metas = [hard_parts.generate(s)[1] for s in hard_parts.seeds_of("wedge", seeds)]
    assert min(m["params"]["angle_deg"] for m in metas) < 15
    assert all(10 <= m["params"]["angle_deg"] <= 25 for m in metas)
    angles = []
    for s in hard_parts.seeds_of("polytope", seeds):
        shape, meta = hard_parts.generate(s)
        solid = shape.Solids[0]
        sharpest = 180.0
        for e in solid.Edges:
            f1, f2 = solid.ancestorsOfType(e, Part.Face)
            p = e.valueAt(0.5 * (e.FirstParameter + e.LastParameter))
            n1 = f1.normalAt(*f1.Surface.parameter(p))
            n2 = f2.normalAt(*f2.Surface.parameter(p))
            sharpest = min(sharpest, 180.0 - math.degrees(n1.getAngle(n2)))
        assert abs(sharpest - meta["params"]["angle_deg"]) < 1e-6, (s, sharpest)
        angles.append(sharpest)
    assert min(angles) < 10 and all(5 <= a <= 25 for a in angles)


@pytest.fixture(scope="module")
def computed(tmp_path_factory):
    """Seeds 0 (a chip and its two caps) and 6 (a wedge) through hard_eval.one: the engine's axis."""
    import hard_eval
    cli = os.environ.get("CADMEDIAL_CLI")
    if not cli:
        pytest.skip("CADMEDIAL_CLI is not set (ctest sets it)")
    out = str(tmp_path_factory.mktemp("hard_eval"))
    return out, {s: hard_eval.one(s, os.path.dirname(cli), out, 120) for s in (0, 6)}


def judge_again(out, seed, change):
    import json
    import Part
    import cadmedial
    import hard_eval
    base = os.path.join(out, "seed_%03d" % seed)
    shape = Part.Shape()
    shape.read(base + ".brep")
    _, meta = hard_parts.generate(seed)
    mesh = hard_eval.mesh_arrays(cadmedial.load(base + ".ply"))
    h = hard_eval.spacing_of(json.load(open(base + ".stats.json")))
    change(mesh, shape)
    return hard_eval.judge(shape, [s["euler"] for s in meta["solids"]], mesh, h)


def test_engine_right_on_small_seeds(computed):
    _, recs = computed
    for seed, r in recs.items():
        assert r["engine"] == "ok"
        assert r["verdict"] == "right", (seed, r["why"])
        assert all(t["components"] == 1 and t["euler"] == t["expected"] for t in r["topology"])
        assert r["completeness"]["edge_reached"] >= 0.98


def delete_face(mesh, shape):
    """Drops the face whose centre is nearest the mean of all face centres (inside the axis, not
    on its rim): that solid's axis loses one face, so its Euler characteristic changes."""
    off, idx = mesh["offsets"], mesh["indices"]
    sizes = np.diff(off)
    centres = np.add.reduceat(mesh["V"][idx], off[:-1], axis=0) / sizes[:, None]
    f = int(np.argmin(np.linalg.norm(centres - centres.mean(0), axis=1)))
    keep = np.ones(len(sizes), bool)
    keep[f] = False
    mesh["indices"] = idx[keep[np.repeat(np.arange(len(sizes)), sizes)]]
    mesh["offsets"] = np.concatenate([[0], np.cumsum(sizes[keep])])
    mesh["face_solid"] = mesh["face_solid"][keep]


def move_out(mesh, shape):
    """Moves every tenth vertex a diagonal away from the part, out of every solid."""
    V = mesh["V"].copy()
    V[::10] += np.array([shape.BoundBox.DiagonalLength * 2, 0, 0])
    mesh["V"] = V


def test_judge_catches_deleted_face(computed):
    out, _ = computed
    r = judge_again(out, 0, delete_face)
    assert r["verdict"] == "wrong"
    assert any(w.startswith("topology") for w in r["why"]), r["why"]


def test_judge_catches_vertices_outside(computed):
    out, _ = computed
    r = judge_again(out, 0, move_out)
    assert r["verdict"] == "wrong"
    # About a tenth of the tested vertices are outside.
    assert 0.05 < r["leakage"]["outside_fraction"] < 0.15, r["leakage"]
    assert any(w.startswith("vertices outside") for w in r["why"]), r["why"]


def test_polytopes_refined_only_where_the_first_pass_is_wrong():
    """Issue 32, item 2: a solid whose axis is right at the first pass is not refined, and stray
    specks at a sharp wedge (crossing completion fans, loose 1-D edges, Voronoi fragments in the
    wedge's thin zone) do not count as pieces. On the polytope family's seeds 65-109 (wedges of 6
    to 16 degrees; three leave specks): the first pass (refine=False) is judged independently;
    where it is right, the default run is that same pass, else it was refined; the default run is
    right on every count."""
    import cadmedial
    import hard_eval
    specks = 0
    for seed in hard_parts.seeds_of("polytope", range(55, 110)):
        shape, meta = hard_parts.generate(seed)
        eulers = [s["euler"] for s in meta["solids"]]
        first = cadmedial.compute(shape, refine=False)
        first_rec = hard_eval.judge(shape, eulers, hard_eval.mesh_arrays(first), hard_eval.spacing_of(first.stats))
        default = cadmedial.compute(shape)
        rec = hard_eval.judge(shape, eulers, hard_eval.mesh_arrays(default), hard_eval.spacing_of(default.stats))
        assert rec["verdict"] == "right", (seed, rec["why"])
        solid = default.stats["solids"][0]
        specks += solid["specks"] > 0
        if all(not w.startswith("topology") for w in first_rec["why"]):
            assert solid["refinements"] == 0, seed
            assert len(default.vertices) == len(first.vertices), seed
        else:
            assert solid["refinements"] >= 1, seed
    # The seeds exercise the rule (else the test would prove nothing).
    assert specks >= 1, specks


def test_convex_edges_the_axis_misses_are_named():
    """Issue 32, item 4: a convex edge the axis does not reach gets a warning naming it and a place
    on it. A leaded package (seed 1: J leads 0.012 thick) at 3,000 samples, where the spacing is
    several lead thicknesses: the engine says which leads' edges are short; the independent
    count (points every h/2 along the B-rep's convex edges, within h of the axis's faces) agrees
    that the axis falls short on those solids and not on the body, and the place the warning
    names is on the solid's boundary and farther than h from the solid's axis. At the default
    density neither the engine nor the count finds a short edge."""
    import cadmedial
    from scipy.spatial import cKDTree
    import results_part
    shape, meta = hard_parts.generate(1)

    def independent_reach(result, h):
        reached = []
        for k, solid in enumerate(shape.Solids):
            ep, cp, length = measures.convex_edge_points([solid], h)
            reached.append(results_part.completeness(cKDTree(axis_of(result, k)), ep, cp, length, h)
                           .get("edge_reached", 1.0))
        return reached

    def axis_of(result, k):
        """Solid k's axis: its vertices and points on its faces every h/3 or closer."""
        V = np.asarray(result.vertices)
        mask = np.repeat(np.asarray(result.face_solid) == k, result.faces.sizes())
        mine = np.unique(np.asarray(result.faces.indices)[mask])
        tri = np.asarray(result.faces.triangulate()[0], np.int64).reshape(-1, 3)
        tri = tri[np.all(np.isin(tri, mine), axis=1)]
        return np.vstack([V[mine], measures.sample_mesh(V, tri, h / 3, np.random.default_rng(5))])

    coarse = cadmedial.compute(shape, samples=3000)
    h = min(s["spacing"] for s in coarse.stats["solids"])
    short = [k for k, s in enumerate(coarse.stats["solids"]) if s["short_convex_edges"] > 0]
    assert short and 0 not in short, short
    warned = [w for w in coarse.stats["warnings"] if "convex edge" in w]
    assert len(warned) == len(short)
    reach = independent_reach(coarse, h)
    assert all(reach[k] < 0.98 for k in short), reach
    assert all(reach[k] >= 0.98 for k in range(len(reach)) if k not in short), reach
    # The place named for the first short solid: on that solid's boundary, far from its axis.
    import re
    import FreeCAD
    import Part
    x, y, z = map(float, re.search(r"not near \(([^,]+), ([^,]+), ([^)]+)\)", warned[0]).groups())
    solid = shape.Solids[short[0]]
    # (printed to 3 significant digits)
    assert solid.distToShape(Part.Vertex(FreeCAD.Vector(x, y, z)))[0] < 0.1 * h
    assert cKDTree(np.asarray(coarse.vertices)).query([x, y, z])[0] > 0.9 * h
    default = cadmedial.compute(shape)
    assert all(s["short_convex_edges"] == 0 for s in default.stats["solids"])
    assert not [w for w in default.stats["warnings"] if "convex edge" in w]
    assert min(independent_reach(default, min(s["spacing"] for s in default.stats["solids"]))) >= 0.98
