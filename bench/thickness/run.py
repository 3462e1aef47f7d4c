"""Accuracy and speed of cadmedial.thickness against the exact shrinking-ball reference.

    /usr/bin/python3 bench/thickness/run.py [--points 500] [--parts analytic|shared|all|NAME...]
        [--out bench/out/thickness.json]

For each part: the analysis (default density, corners="exclude"), then the reference at up to
--points counted surface points lying inside one face (seeded choice), at the exact B-rep point
nearest each. Prints per part: p50/p95/max relative error (and, at the same points, of the medial
reading alone: the analysis again on the same medial axis with refine_budget=0), the analysis's and the medial axis's
times, wall and CPU (and the exact refinement's part of the analysis, with the share of counted points it
refined), the reference's time per point and for all the analysis's points (extrapolated), and the
reference at the analysis's thinnest point.
"""

import argparse
import csv
import json
import math
import os
import sys
import time

import numpy as np

sys.path.append("/usr/lib/freecad/lib")
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, os.pardir))

import FreeCAD  # noqa: E402,F401
import Part  # noqa: E402

from cadmedial.thickness import thickness  # noqa: E402
from reference import exact_point_and_normal, shrinking_ball  # noqa: E402
import solids  # noqa: E402

MODELS = "/work/shared/data/models"


def shared_parts():
    with open(os.path.join(MODELS, "MANIFEST.tsv")) as f:
        return [row["path"] for row in csv.DictReader(f, delimiter="\t")]


def load(name):
    if name in solids.NAMES:
        return solids.make(name)
    path = os.path.join(MODELS, name)
    if path.lower().endswith(".fcstd"):
        import results_part
        return results_part.fcstd_shape(path)
    s = Part.Shape()
    s.read(path)
    return s


def single_face_points(result):
    """Indices of the points that lie on one face only (not on a B-rep edge)."""
    t = result.triangles
    f = np.repeat(result.triangle_face, 3)
    lo = np.full(len(result.points), np.iinfo(np.int64).max)
    hi = np.full(len(result.points), -1)
    np.minimum.at(lo, t.ravel(), f)
    np.maximum.at(hi, t.ravel(), f)
    return np.nonzero(lo == hi)[0], lo


def bench_part(name, count, seed=0):
    shape = load(name)
    res = thickness(shape)
    # The medial reading alone (no refinement) on the same medial axis and surface mesh, compared
    # at the same points: what the refinement changes.
    plain = thickness(shape, medial=res.medial, refine_budget=0)
    faces = shape.Faces
    inside, face_of = single_face_points(res)
    pool = inside[res.counted[inside]]
    rng = np.random.default_rng(seed)
    pick = rng.choice(pool, size=min(count, len(pool)), replace=False) if len(pool) else pool
    sol = [s for s in (shape.Solids or [Part.Solid(sh) for sh in shape.Shells if sh.isClosed()])]
    bounds = [Part.makeCompound(s.Faces) for s in sol]
    diag = shape.BoundBox.DiagonalLength
    point_solid = np.zeros(len(res.points), dtype=np.int64)
    if len(sol) > 1:  # which solid each face belongs to
        index = {f.hashCode(): i for i, f in enumerate(faces)}
        for k, s in enumerate(sol):
            for f in s.Faces:
                if f.hashCode() in index:
                    point_solid[np.isin(face_of, [index[f.hashCode()]])] = k

    def reference_at(i):
        q, n = exact_point_and_normal(faces[face_of[i]], res.points[i])
        k = point_solid[i]
        return shrinking_ball(sol[k], bounds[k], q, n, diag)[0]

    t0 = time.perf_counter()
    ref = np.array([reference_at(i) for i in pick])
    t_ref = time.perf_counter() - t0
    got = res.values[pick]
    ok = ref > 0
    err = np.abs(got[ok] / ref[ok] - 1.0)
    err_plain = np.abs(plain.values[pick][ok] / ref[ok] - 1.0)
    counted = np.nonzero(res.counted)[0]
    thin = counted[np.argmin(res.values[counted])] if len(counted) else None
    if thin is not None and thin in set(inside.tolist()):
        ref_min = reference_at(thin)
    else:
        ref_min = float("nan")  # on an edge: no single face to put the reference on
    per_point = t_ref / max(len(pick), 1)
    return {
        "part": name, "points": int(len(res.points)), "compared": int(ok.sum()),
        "counted_share": float(res.statistics["area"] / max(res.statistics["area_total"], 1e-300)),
        "p50": float(np.quantile(err, 0.5)) if len(err) else None,
        "p95": float(np.quantile(err, 0.95)) if len(err) else None,
        "max": float(err.max()) if len(err) else None,
        "medial_reading_p50": float(np.quantile(err_plain, 0.5)) if len(err) else None,
        "medial_reading_p95": float(np.quantile(err_plain, 0.95)) if len(err) else None,
        "medial_reading_max": float(err_plain.max()) if len(err) else None,
        "medial_reading_analysis_s": plain.timings["analysis"],
        "medial_s": res.timings["medial_axis"], "analysis_s": res.timings["analysis"],
        "total_over_medial": (res.timings["medial_axis"] + res.timings["analysis"])
        / max(res.timings["medial_axis"], 1e-9),
        "medial_cpu_s": res.timings.get("medial_axis_cpu"),
        "analysis_cpu_s": res.timings.get("analysis_cpu"),
        "total_over_medial_cpu": (res.timings["medial_axis_cpu"] + res.timings["analysis_cpu"])
        / max(res.timings["medial_axis_cpu"], 1e-9) if "analysis_cpu" in res.timings else None,
        "reference_s_per_point": per_point,
        "reference_s_all_points": per_point * len(res.points),
        "min": res.statistics["min"], "min_at": None if thin is None else res.points[thin].tolist(),
        "min_reference": ref_min,
        "spacing": res.settings["spacing"],
        "refine_s": res.timings.get("refine"),
        "refined_share": None if res.refined is None
        else float(res.refined[res.counted].mean()) if res.counted.any() else 0.0,
    }


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--points", type=int, default=500)
    ap.add_argument("--parts", nargs="*", default=["all"])
    ap.add_argument("--out", default=os.path.join(HERE, os.pardir, "out", "thickness.json"))
    a = ap.parse_args()
    names = []
    for p in a.parts:
        names += (solids.NAMES if p in ("analytic", "all") else []) + \
                 (shared_parts() if p in ("shared", "all") else []) + \
                 ([p] if p not in ("analytic", "shared", "all") else [])
    os.makedirs(os.path.dirname(os.path.abspath(a.out)), exist_ok=True)
    records = []
    for name in names:
        try:
            rec = bench_part(name, a.points)
        except Exception as error:  # a refused part is a row, not the end of the run
            rec = {"part": name, "refused": "%s: %s" % (type(error).__name__, error)}
        records.append(rec)
        if "refused" in rec:
            print("%-44s refused: %s" % (name, rec["refused"][:100]), flush=True)
        else:
            f = lambda x: "  nan" if x is None or not math.isfinite(x) else "%5.2f" % (100 * x)
            print("%-44s pts %6d cmp %3d counted %3.0f%% err%% p50 %s p95 %s max %s "
                  "(medial reading: p50 %s p95 %s max %s) | medial %6.2fs "
                  "analysis %6.2fs (x%.2f, CPU x%s; refine %s, %s) ref %.1fms/pt (%.0fs all) | min %.4g ref %.4g"
                  % (name, rec["points"], rec["compared"], 100 * rec["counted_share"],
                     f(rec["p50"]), f(rec["p95"]), f(rec["max"]), f(rec["medial_reading_p50"]),
                     f(rec["medial_reading_p95"]), f(rec["medial_reading_max"]), rec["medial_s"],
                     rec["analysis_s"], rec["total_over_medial"],
                     "-" if rec["total_over_medial_cpu"] is None else "%.2f" % rec["total_over_medial_cpu"],
                     "-" if rec["refine_s"] is None else "%.2fs" % rec["refine_s"],
                     "-" if rec["refined_share"] is None else "%.0f%%" % (100 * rec["refined_share"]),
                     1e3 * rec["reference_s_per_point"], rec["reference_s_all_points"],
                     rec["min"] or float("nan"), rec["min_reference"]), flush=True)
        with open(a.out, "w") as out:
            json.dump(records, out, indent=1)


if __name__ == "__main__":
    main()
