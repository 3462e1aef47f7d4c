"""One part of the results suite (run by bench/results.py in a subprocess, one per part).

    results_part.py NAME --samples N --out FILE.json [--mesh FILE.npz] [--light] [--plain-medial]
    results_part.py NAME --default-density --out FILE.json

NAME is an analytic solid (bench/analytic.py NAMES) or a path under /work/shared/data/models.
Writes a JSON record: engine stats, reconstruction error, accuracy (analytic solids), completeness,
topology, leakage; or {"refused": message} when the engine or the reader refuses the part.
--light skips topology and leakage (density sweeps). --plain-medial computes the paper's plain
MEDIAL (section 3) with its theta = pi/8 (22.5 degrees) instead of CAD_MEDIAL, on the same samples.
--default-density computes as compute(part) does with no density given: from 20,000 samples, each
solid sampled again, finer, where its axis's topology is wrong; h is then the finest solid spacing.
"""
import argparse
import json
import os
import sys
import time

import numpy as np

sys.path.append("/usr/lib/freecad/lib")
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import FreeCAD  # noqa: E402,F401
import Part  # noqa: E402

import analytic  # noqa: E402
import measures  # noqa: E402

MODELS = "/work/shared/data/models"
PLAIN_THETA = 22.5  # the paper's pi/8 for MEDIAL (section 3)


def fcstd_shape(path):
    """The final solids of a FreeCAD document: its top-level objects (no parent) holding solids
    (a PartDesign Body's shape is its tip's; legacy PartDesign: the last feature)."""
    # FreeCAD creates a "PartDesign::Pad" by importing the Python module "PartDesign", which
    # exists only inside FreeCAD's own start-up (the compiled module is _PartDesign): without
    # it, openDocument silently drops every PartDesign object (Body, Pad, Pocket) and only the
    # sketches and planes are left.
    try:
        import _PartDesign
        sys.modules.setdefault("PartDesign", _PartDesign)
    except ImportError:
        pass
    doc = FreeCAD.openDocument(path)
    try:
        doc.recompute()
    except Exception:
        pass
    solids = []
    for obj in doc.Objects:
        if obj.InList or not hasattr(obj, "Shape"):
            continue
        if obj.TypeId in ("App::Origin", "App::Line", "App::Plane") or obj.TypeId.startswith("Sketcher"):
            continue
        found = obj.Shape.Solids
        tip = getattr(obj, "Tip", None)
        if not found and tip is not None and hasattr(tip, "Shape"):
            # A Body saved without its own shape (PartDesignExample.FCStd: up to date, so not
            # recomputed) holds its solid in its tip feature.
            found = tip.Shape.Solids
        solids.extend(found)
    kinds = sorted({o.TypeId for o in doc.Objects})
    FreeCAD.closeDocument(doc.Name)
    if not solids:
        raise ValueError("no top-level object holds a solid after recompute (object types: %s)"
                         % ", ".join(kinds))
    return Part.makeCompound(solids)


def load(name):
    """(source for cadmedial, FreeCAD shape for the measures)."""
    if name in analytic.NAMES:
        s = analytic.make_shape(name)
        return s, s
    path = os.path.join(MODELS, name)
    if path.lower().endswith(".fcstd"):
        s = fcstd_shape(path)
        return s, s
    s = Part.Shape()
    s.read(path)
    if not s.Solids:
        # IGES often holds faces only; the engine sews them into solids, and so do the measures.
        s = sewn_solids(s) or s
    return path, s


def sewn_solids(shape):
    """The closed shells that sewing the shape's faces makes, as solids (a compound), or None."""
    sewn = shape.copy()
    sewn.sewShape()
    solids = []
    for shell in sewn.Shells:
        if not shell.isClosed():
            continue
        solid = Part.Solid(shell)
        if solid.Volume < 0:
            solid.reverse()
        solids.append(solid)
    return Part.makeCompound(solids) if solids else None


def completeness(dense_tree, ep, cp, length, h):
    """How much of the convex edges (points ep along them, total length `length`) and corners cp
    the axis reaches: a point is reached when the dense sample of the axis's faces (dense_tree,
    a k-d tree) comes within h of it."""
    rec = {"edge_points": int(len(ep)), "corners": int(len(cp)), "convex_edge_length": length}
    if len(ep):
        d = dense_tree.query(ep)[0]
        rec["edge_reached"] = float((d <= h).mean())
        rec["edge_max_h"] = float(d.max() / h)
    if len(cp):
        d = dense_tree.query(cp)[0]
        rec["corner_reached"] = float((d <= h).mean())
    return rec


def topology_record(offsets, indices, face_solid, edges, edge_solid, num_vertices, solids):
    """Per solid the axis has: its pieces and Euler characteristic (measures.topology) beside the
    solid's own from its B-rep (measures.solid_euler)."""
    topo = measures.topology(offsets, indices, face_solid, edges, edge_solid, num_vertices)
    return [{"solid": s, **tp, "solid_euler": measures.solid_euler(solids[s]) if s < len(solids) else None}
            for s, tp in topo.items()]


def main():
    if os.environ.get("BENCH_TRACE"):
        import faulthandler
        faulthandler.dump_traceback_later(int(os.environ["BENCH_TRACE"]), exit=True)
    ap = argparse.ArgumentParser()
    ap.add_argument("name")
    ap.add_argument("--samples", type=int, default=20000)
    ap.add_argument("--out", required=True)
    ap.add_argument("--mesh")
    ap.add_argument("--light", action="store_true")
    ap.add_argument("--plain-medial", action="store_true")
    ap.add_argument("--default-density", action="store_true")
    a = ap.parse_args()
    if a.default_density:
        a.samples = None
    import cadmedial

    rec = {"name": a.name, "target_samples": a.samples, "plain_medial": a.plain_medial}
    params = {"theta": PLAIN_THETA, "plain_medial": True} if a.plain_medial else {}
    t0 = time.time()
    try:
        source, shape = load(a.name)
    except Exception as e:  # noqa: BLE001 - recorded, not hidden
        rec["refused"] = "reader: %s" % e
        json.dump(rec, open(a.out, "w"))
        return
    try:
        t = time.time()
        source = cadmedial.read_shape(source)
        # The engine's first read installs OpenCASCADE's fault handlers, which end the process
        # with status 1 and no word on a fault outside a guarded reader; Python's fault handler,
        # installed over them, says which signal it was and where first.
        import faulthandler
        faulthandler.enable()
        r = cadmedial.compute(source, samples=a.samples, **params)  # None: refined (--default-density)
        rec["wall_compute"] = time.time() - t
    except Exception as e:  # noqa: BLE001
        rec["refused"] = "%s: %s" % (type(e).__name__, e)
        json.dump(rec, open(a.out, "w"))
        return
    st = r.stats
    rec["stats"] = st
    V = np.asarray(r.vertices, float)
    R = np.asarray(r.radius, float)
    face_solid = np.asarray(r.face_solid)
    # A refined solid's spacing is finer than the plan's: the figures in units of h take the finest.
    h = min([float(s["spacing"]) for s in st.get("solids", []) if "spacing" in s] or [float(st["spacing"])])
    solids = shape.Solids
    bb = shape.BoundBox
    diag = bb.DiagonalLength
    rec.update(diag=diag, h=h, vertices=len(V), faces=int(r.num_faces), solids=len(solids),
               face_kinds=np.bincount(np.asarray(r.face_kind, int), minlength=3).tolist())
    if len(V) == 0:
        rec["refused"] = "empty output"
        json.dump(rec, open(a.out, "w"))
        return
    comp = Part.makeCompound(solids) if solids else shape
    tm = rec["measure_seconds"] = {}
    t = time.time()
    err, (P, T) = measures.reconstruction_error(comp, diag, V, R, h)
    tm["reconstruction_error"] = time.time() - t
    t = time.time()
    Y, N, spacing = err.pop("surface")
    rec["recon"] = err
    T3 = np.asarray(r.triangles(), np.int64)
    rng = np.random.default_rng(5)
    dense = measures.sample_mesh(V, T3, h / 3, rng)
    from scipy.spatial import cKDTree
    dtree = cKDTree(dense, balanced_tree=False, compact_nodes=False)

    if a.name in analytic.NAMES:
        dist, axis_pts = analytic.exact_axis(a.name)
        probe = np.vstack([V, V[T3].mean(1)]) if len(T3) else V
        d_out = dist(probe)
        d_in = dtree.query(axis_pts)[0]
        rec["accuracy"] = {
            "out_to_axis_p95_h": float(np.percentile(d_out, 95) / h),
            "out_to_axis_max_h": float(d_out.max() / h),
            "axis_to_out_p95_h": float(np.percentile(d_in, 95) / h),
            "axis_to_out_max_h": float(d_in.max() / h),
            "axis_samples": int(len(axis_pts)),
        }
        ep, cp = analytic.convex_features(a.name, h)
        L = None
    else:
        ep, cp, L = measures.convex_edge_points(solids, h)
    rec["completeness"] = completeness(dtree, ep, cp, L, h)
    tm["accuracy_completeness"] = time.time() - t
    t = time.time()

    if not a.light:
        rec["topology"] = topology_record(r.faces.offsets, r.faces.indices, face_solid, r.edges, r.edge_solid,
                                          r.num_vertices, solids)
        surface = (Y, N, spacing) if N is not None and len(solids) == 1 else None
        frac, n, exact = measures.leakage(solids, V, 1e-6 * diag, surface=surface)
        rec["leakage"] = {"outside_fraction": frac, "tested": n, "classifier": exact}
        tm["topology_leakage"] = time.time() - t
        # The thinnest wall the engine reports, against the exact wall where it found it.
        t = time.time()
        walls = []
        for s, ss in enumerate(st.get("solids", [])):
            at, reported = ss.get("thinnest_wall_at"), ss.get("thinnest_wall")
            if at is None or reported is None or s >= len(solids):
                continue
            walls.append({"solid": s, "reported": reported,
                          "exact": measures.exact_wall(solids[s], at, reported, 1e-7 * diag)})
        rec["thin_walls"] = walls
        tm["thin_walls"] = time.time() - t
    if a.mesh:
        np.savez_compressed(a.mesh, V=V, R=R, T=T3, P=P, Tp=T)
    rec["wall_total"] = time.time() - t0
    json.dump(rec, open(a.out, "w"))


if __name__ == "__main__":
    main()
