"""Judge today's engine on generated hard parts (issue 32: parts nobody tuned on).

    nice /usr/bin/python3 bench/hard_eval.py --seeds 0-29 --build build -o bench/out/hard_eval \\
        [--timeout 120] [--jobs 1]

Per seed: bench/hard_parts.py makes the part (OUT/seed_NNN.brep), `BUILD/cadmedial compute` runs on
it with default options (no density: 20,000 samples, refined where its own topology check fails)
under a time limit, and the axis it wrote (.ply) is judged here, independently of the engine's
stats, by bench/measures.py's checks (the ones bench/results_part.py applies to real parts):

  topology   per solid, one piece with the solid's Euler characteristic by construction (1-D
             edges counted)
  edges      >= 98 % of the points along the solid's convex edges within h of the axis
  uncovered  <= 1 % of the diagonal of surface that no ball of the axis reaches
  inside     no tested vertex of the axis outside every solid
Stick-out (balls reaching out of the solid) is reported, not judged. h is the finest sample
spacing the engine's stats name (the scale of "within h"; the only figure taken from them).
A run past the time limit, or one that fails, is wrong. Each seed runs in its own process
(`hard_eval.py --one SEED ...`), so a crash in the judge is that seed's alone.

Writes OUT/hard_eval.json (every record) and OUT/hard_eval.md (the table).
"""
import argparse
import json
import os
import signal
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
sys.path.append("/usr/lib/freecad/lib")

EDGES_REACHED = 0.98
UNCOVERED = 0.01  # of the diagonal
# Per family, the parameters that make it hard (shown in the table).
KEY = {"smd_chip": ["L", "cap_wall", "cup"], "leaded": ["L", "lead", "kind", "n"],
       "can": ["R", "wall", "wall_rel_diag", "bottom", "holes"], "bracket": ["L", "t", "t_rel", "gusset", "holes"],
       "ribbed_plate": ["L", "rib", "rib_rel", "ribs", "cross_ribs"],
       "holes_plate": ["L", "holes", "hole", "kind"], "wedge": ["L", "angle_deg", "finish", "hole"], "polytope": ["angle_deg", "faces"],
       "bosses_slots": ["L", "features", "through_holes"], "assembly": ["kinds"],
       "spline_fillet": ["L", "sections", "fillet", "hole"]}


def mesh_arrays(result):
    """The plain arrays the judge reads from a cadmedial result (compute() or load())."""
    return {"V": np.asarray(result.vertices, float), "R": np.asarray(result.radius, float),
            "offsets": np.asarray(result.faces.offsets, np.int64), "indices": np.asarray(result.faces.indices, np.int64),
            "face_solid": np.asarray(result.face_solid, np.int64),
            "edges": np.asarray(result.edges, np.int64).reshape(-1, 2),
            "edge_solid": np.asarray(result.edge_solid, np.int64)}


def judge(shape, eulers, mesh, h):
    """The four counts of issue 32 on one axis (mesh: mesh_arrays) of shape's solids, whose Euler
    characteristics by construction are `eulers`; h the sample spacing. Returns the record with
    "verdict" ("right" / "wrong") and "why" (the failed counts)."""
    import Part
    from scipy.spatial import cKDTree
    from cadmedial.result import Faces
    import measures
    import results_part
    solids = shape.Solids
    V, R = mesh["V"], mesh["R"]
    diag = shape.BoundBox.DiagonalLength
    rec = {"h": h, "diag": diag, "vertices": int(len(V)), "faces": int(len(mesh["offsets"]) - 1),
           "edges_1d": int(len(mesh["edges"]))}
    if len(V) == 0:
        rec.update(verdict="wrong", why=["empty axis"])
        return rec
    comp = Part.makeCompound(solids)
    err, _ = measures.reconstruction_error(comp, diag, V, R, h)
    Y, N, spacing = err.pop("surface")
    rec["recon"] = err
    T3 = Faces(mesh["offsets"], mesh["indices"]).triangulate()[0]
    dense = measures.sample_mesh(V, np.asarray(T3, np.int64).reshape(-1, 3), h / 3, np.random.default_rng(5))
    # 1-D edges reach edges too (a thin wall's axis may be a curve): sample them as well.
    E = mesh["edges"]
    if len(E):
        t = np.linspace(0, 1, 8)[:, None, None]
        dense = np.vstack([dense, (V[E[:, 0]] * (1 - t) + V[E[:, 1]] * t).reshape(-1, 3)])
    ep, cp, length = measures.convex_edge_points(solids, h)
    rec["completeness"] = results_part.completeness(cKDTree(dense), ep, cp, length, h)
    topo = results_part.topology_record(mesh["offsets"], mesh["indices"], mesh["face_solid"], E, mesh["edge_solid"],
                                        len(V), solids)
    by_solid = {t["solid"]: t for t in topo}
    rec["topology"] = [dict(by_solid.get(s, {"solid": s, "components": 0, "euler": None,
                                             "solid_euler": measures.solid_euler(solids[s])}), expected=e)
                       for s, e in enumerate(eulers)]
    rec["topology_extra_solids"] = sorted(set(by_solid) - set(range(len(eulers))))
    surface = (Y, N, spacing) if N is not None and len(solids) == 1 else None
    frac, n, exact = measures.leakage(solids, V, 1e-6 * diag, n=5000, surface=surface)
    rec["leakage"] = {"outside_fraction": frac, "tested": n, "classifier": exact}
    why = []
    bad = [t for t in rec["topology"] if t["components"] != 1 or t["euler"] != t["expected"]]
    if bad or rec["topology_extra_solids"]:
        why.append("topology (%d of %d solids)" % (len(bad), len(eulers)))
    reached = rec["completeness"].get("edge_reached", 1.0)
    if reached < EDGES_REACHED:
        why.append("convex edges %.1f %%" % (100 * reached))
    if err["uncovered_max"] > UNCOVERED * diag:
        why.append("uncovered %.2f %% diag" % (100 * err["uncovered_max"] / diag))
    if frac > 0:
        why.append("vertices outside %.2f %%" % (100 * frac))
    rec.update(verdict="wrong" if why else "right", why=why)
    return rec


def spacing_of(stats):
    """The finest sample spacing in the engine's stats (a refined solid's is finer than the plan's)."""
    per = [float(s["spacing"]) for s in stats.get("solids", []) if "spacing" in s]
    return min(per) if per else float(stats["spacing"])


def run_engine(build, brep, ply, stats, timeout):
    """(status, seconds): "ok", "time limit" or "failed (exit N): last stderr line". Its own
    process group, all of which a time limit ends."""
    cmd = [os.path.join(build, "cadmedial"), "compute", brep, "-o", ply, "--stats", stats, "--quiet"]
    t = time.time()
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True)
    try:
        _, err = p.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        p.communicate()
        return "time limit", time.time() - t
    dt = time.time() - t
    if p.returncode != 0:
        last = (err.strip().splitlines() or [""])[-1]
        return "failed (exit %d): %s" % (p.returncode, last[:200]), dt
    return "ok", dt


def one(seed, build, out, timeout):
    """Generates, computes and judges one seed; the record goes to OUT/seed_NNN.json."""
    import FreeCAD  # noqa: F401 - before Part
    import Part
    import cadmedial
    import hard_parts
    t = time.time()
    shape, meta = hard_parts.generate(seed)
    base = os.path.join(out, "seed_%03d" % seed)
    shape.exportBrep(base + ".brep")
    rec = {"seed": seed, "family": meta["family"], "params": meta["params"], "used_seed": meta["used_seed"],
           "solids": len(meta["solids"]), "expected_euler": [s["euler"] for s in meta["solids"]],
           "generate_seconds": time.time() - t}
    for f in (base + ".ply", base + ".stats.json"):
        if os.path.exists(f):
            os.remove(f)
    status, dt = run_engine(build, base + ".brep", base + ".ply", base + ".stats.json", timeout)
    rec.update(engine=status, engine_seconds=dt)
    if status != "ok":
        rec.update(verdict="wrong", why=[status])
    else:
        stats = json.load(open(base + ".stats.json"))
        rec["samples"] = stats.get("samples")
        rec["engine_warnings"] = stats.get("warnings", [])
        rec["refinements"] = [s.get("refinements") for s in stats.get("solids", [])]
        # The part as the engine read it (same file), so both see the same solids in the same order.
        read = Part.Shape()
        read.read(base + ".brep")
        t = time.time()
        rec.update(judge(read, rec["expected_euler"], mesh_arrays(cadmedial.load(base + ".ply")), spacing_of(stats)))
        rec["judge_seconds"] = time.time() - t
    json.dump(rec, open(base + ".json", "w"), indent=1, default=float)
    return rec


def run_one_process(seed, a):
    """Runs `hard_eval.py --one SEED` in its own process; a crash becomes a wrong record."""
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([os.path.join(ROOT, "python"), os.environ.get("PYTHONPATH", "")]),
               CADMEDIAL_CORE_DIR=os.path.join(os.path.abspath(a.build), "python", "cadmedial"))
    out = os.path.join(a.out, "seed_%03d.json" % seed)
    if os.path.exists(out):
        os.remove(out)
    cmd = [sys.executable, os.path.abspath(__file__), "--one", str(seed), "--build", a.build, "-o", a.out,
           "--timeout", str(a.timeout)]
    p = subprocess.run(cmd, env=env, capture_output=True, text=True)
    if p.returncode == 0 and os.path.exists(out):
        return json.load(open(out))
    last = (p.stderr.strip().splitlines() or [""])[-1]
    import hard_parts
    return {"seed": seed, "family": hard_parts.FAMILIES[seed % len(hard_parts.FAMILIES)][0], "params": {},
            "verdict": "wrong", "why": ["judge failed (exit %d): %s" % (p.returncode, last[:200])]}


def fmt(v):
    if isinstance(v, float):
        return "%.3g" % v
    if isinstance(v, list):
        return "+".join(str(x) for x in v)
    return str(v)


def topology_cell(r):
    topo = r.get("topology")
    if topo is None:
        return "-"
    bad = [t for t in topo if t["components"] != 1 or t["euler"] != t["expected"]]
    if not bad and not r.get("topology_extra_solids"):
        if len(topo) == 1:
            return "1 piece, χ %s" % topo[0]["expected"]
        return "%d solids, each 1 piece, χ %s" % (
            len(topo), "/".join(str(t["expected"]) for t in topo) if len(topo) <= 3 else "right")
    cells = ["s%d: %d piece%s, χ %s (want %s)" % (t["solid"], t["components"], "" if t["components"] == 1 else "s",
                                                 t["euler"], t["expected"])
             for t in bad[:3]]
    if len(bad) > 3:
        cells.append("%d more" % (len(bad) - 3))
    if r.get("topology_extra_solids"):
        cells.append("faces of unknown solids %s" % r["topology_extra_solids"])
    return "; ".join(cells) + ("" if len(topo) == 1 else " (of %d)" % len(topo))


def table(recs):
    head = ["seed", "family", "key dims", "samples", "engine s", "topology (pieces, χ vs expected)",
            "convex edges reached %", "uncovered % diag", "outside vertices %", "stick-out % diag", "verdict"]
    rows = []
    for r in recs:
        key = ", ".join("%s %s" % (k, fmt(r["params"][k])) for k in KEY.get(r["family"], []) if k in r["params"])
        d = r.get("diag")
        comp = r.get("completeness", {})
        rows.append([str(r["seed"]), r["family"], key, fmt(r.get("samples", "-")),
                     "%.1f" % r["engine_seconds"] if "engine_seconds" in r else "-", topology_cell(r),
                     "%.1f" % (100 * comp["edge_reached"]) if "edge_reached" in comp else "-",
                     "%.3f" % (100 * r["recon"]["uncovered_max"] / d) if "recon" in r else "-",
                     "%.2f" % (100 * r["leakage"]["outside_fraction"]) if "leakage" in r else "-",
                     "%.3f" % (100 * r["recon"]["stick_out_max"] / d) if "recon" in r else "-",
                     "right" if r["verdict"] == "right" else "**wrong**: " + "; ".join(r["why"])])
    out = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    out += ["| " + " | ".join(c.replace("|", "/") for c in row) + " |" for row in rows]
    return "\n".join(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--seeds", default="0-29")
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("-o", "--out", required=True)
    ap.add_argument("--timeout", type=float, default=120.0)
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--one", type=int, help=argparse.SUPPRESS)
    ap.add_argument("--report", action="store_true", help="only write OUT/hard_eval.md again from OUT/hard_eval.json")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    if a.one is not None:
        one(a.one, a.build, a.out, a.timeout)
        return
    if a.report:
        saved = json.load(open(os.path.join(a.out, "hard_eval.json")))
        write_page(saved["run"], saved["records"], a.out)
        return
    import hard_parts
    seeds = hard_parts.parse_seeds(a.seeds)
    t0 = time.time()
    git = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
    started = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
    with ThreadPoolExecutor(max(1, a.jobs)) as ex:
        recs = []
        for r in ex.map(lambda s: run_one_process(s, a), seeds):
            recs.append(r)
            print("seed %d %s: %s %s" % (r["seed"], r["family"], r["verdict"], "; ".join(r["why"])), flush=True)
    right = sum(r["verdict"] == "right" for r in recs)
    head = {"started": started, "wall_seconds": time.time() - t0, "git": git, "build": os.path.abspath(a.build),
            "seeds": a.seeds, "timeout": a.timeout, "jobs": a.jobs, "right": right, "total": len(recs)}
    json.dump({"run": head, "records": recs}, open(os.path.join(a.out, "hard_eval.json"), "w"), indent=1, default=float)
    write_page(head, recs, a.out)
    print("right %d of %d" % (right, len(recs)))


def write_page(head, recs, out):
    md = ["# Hard generated parts, judged (bench/hard_eval.py)", "",
          "Run %s, commit %s, %s, seeds %s, time limit %g s, %d job(s), %.0f s in all." % (
              head["started"], head["git"], head["build"], head["seeds"], head["timeout"], head["jobs"],
              head["wall_seconds"]), "",
          "Right: %d of %d." % (head["right"], head["total"]), "", table(recs), ""]
    open(os.path.join(out, "hard_eval.md"), "w").write("\n".join(md))


if __name__ == "__main__":
    main()
