"""The quality and speed results: regenerates docs/RESULTS.md and docs/img/results_*.png.

    /usr/bin/python3 bench/results.py [--full] [--only NAME,...] [--jobs J] [--build DIR]

Needs the build tree (default build/: the _core module, cadmedial, bench_pipeline). Each part runs
in its own process (bench/results_part.py) with a time limit; its JSON record goes to
bench/out/ (not committed). The default run leaves out SLOW_PARTS (none now); --full runs every
part, adds 250k samples to the speed table and a denser sweep.
"""
import argparse
import datetime
import json
import os
import platform
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
OUT = os.path.join(HERE, "out")
IMG = os.path.join(ROOT, "docs", "img")
MODELS = "/work/shared/data/models"
sys.path.insert(0, HERE)
import analytic  # noqa: E402

DEFAULT_SAMPLES = 20000
TIME_LIMIT = 200
TIME_LIMIT_FULL = 600  # --full: the largest parts take minutes in the engine's inner stage
# The small parts: the ablation's (and the default run's before every part was measured fast).
SMALL_PARTS = ["nist/nist_ftc_11_asme1_rb.stp", "caxif/sg1-c5-214.stp", "caxif/tail_turbine_prt.stp",
                 "caxif/io1-cm-214.stp", "freecad/Y_Rod_Mount.brep", "freecad/filletBox.brep",
                 "freecad/holesInFace2.brep", "cadquery/red_cube_blue_cylinder.step",
                 "axom/sliced_cylinder.step", "freecad/PadTest.fcstd", "freecad/SOT23.igs",
                 "build123d/M6-1x12-countersunk-screw.step"]
# Parts left out of the default run (--full runs them). None since 89fbf21: the 9 once left out
# here (NIST CTC 02/03/04, FTC 07/08/10, Schenkel, boxed_sphere, c.stp), 34 s to 400 s of engine
# time each in the --full run of 2026-11-22 (mostly OpenCASCADE's classifier settling Voronoi
# vertices), now take 1 to 4 s in the engine at 20,000 samples, 30 to 40 s in all with the measures.
SLOW_PARTS = []
# The ablation (plain MEDIAL against CAD_MEDIAL): the analytic solids and the small parts.
ABLATION_PARTS = analytic.NAMES + SMALL_PARTS
SWEEP_PARTS = ["box", "nist/nist_ftc_11_asme1_rb.stp"]
PICTURE_PARTS = ["cylinder", "nist/nist_ftc_11_asme1_rb.stp", "caxif/sg1-c5-214.stp",
                 "freecad/Y_Rod_Mount.brep"]
SPEED_PART = "nist/nist_ctc_01_asme1_rd.stp"
PAPER_TABLE1 = [  # Dey & Zhao, Table 1 (933 MHz PC, CGAL 2.3): points, Delaunay, recon., filtering
    ("ANCHOR", 27619, 129.66, 75.6, 2.62), ("CAP", 17805, 72.95, 56.55, 1.43),
    ("CHUCK", 46906, 301.63, 148.08, 3.68), ("MAILBOX", 6980, 29.51, 27.61, 0.56),
    ("QUIDE", 14951, 52.52, 44.16, 1.13), ("TAPBOLT", 47870, 241.84, 263.3, 4.04),
    ("WIDGET", 66686, 440.53, 300.43, 5.83)]


def manifest():
    rows = []
    with open(os.path.join(MODELS, "MANIFEST.tsv")) as f:
        head = f.readline().rstrip("\n").split("\t")
        for line in f:
            if line.strip():
                rows.append(dict(zip(head, line.rstrip("\n").split("\t"))))
    return rows


def slug(name):
    return name.replace("/", "__").replace(".", "_")


def run_part(name, samples, build, tag="", mesh=False, light=False, plain=False, limit=TIME_LIMIT):
    """samples None: the default density, refined where the topology is wrong (--default-density)."""
    out = os.path.join(OUT, "%s%s_%s.json" % (slug(name), tag, samples or "default"))
    density = ["--samples", str(samples)] if samples else ["--default-density"]
    cmd = [sys.executable, os.path.join(HERE, "results_part.py"), name] + density + ["--out", out]
    if mesh:
        cmd += ["--mesh", os.path.join(OUT, slug(name) + ".npz")]
    if light:
        cmd.append("--light")
    if plain:
        cmd.append("--plain-medial")
    env = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "python"),
               CADMEDIAL_CORE_DIR=os.path.join(build, "python", "cadmedial"),
               PYTHONDONTWRITEBYTECODE="1")
    t = time.time()
    try:
        p = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=limit)
    except subprocess.TimeoutExpired:
        return {"name": name, "target_samples": samples, "refused": "time limit %d s" % limit,
                "wall_process": time.time() - t}
    if p.returncode != 0 or not os.path.exists(out):
        lines = (p.stderr or p.stdout).strip().splitlines()
        how = ("killed by signal %d" % -p.returncode) if p.returncode < 0 else "exit %d" % p.returncode
        # Python's fault handler (results_part.py) names the signal, then the innermost frame.
        fatal = [ln for ln in lines if ln.startswith("Fatal Python error")]
        where = [ln.strip().replace(ROOT + os.sep, "") for ln in lines if ln.strip().startswith("File ")]
        if fatal:
            what = fatal[0] + (" (%s)" % where[0] if where else "")
        else:
            what = ("after: " + lines[-1][:200]) if lines else "without a message"
        return {"name": name, "target_samples": samples, "wall_process": time.time() - t,
                "refused": "process ended (%s) %s" % (how, what)}
    rec = json.load(open(out))
    rec["wall_process"] = time.time() - t
    os.remove(out)
    return rec


def bench_pipeline(build, part, counts):
    exe = os.path.join(build, "bench_pipeline")
    js = os.path.join(OUT, "bench_pipeline.json")
    p = subprocess.run([exe, os.path.join(MODELS, part), "--samples", ",".join(map(str, counts)),
                        "--json", js], capture_output=True, text=True)
    if p.returncode != 0:
        return None, p.stderr.strip()
    return json.load(open(js)), None


# ---------------------------------------------------------------- formatting

def f(x, nd=2):
    if x is None:
        return "n/a"
    if isinstance(x, (int, np.integer)):
        return str(x)
    return ("%%.%df" % nd) % x


def pct(x, nd=1):
    return "n/a" if x is None else ("%%.%df %%%%" % nd) % (100 * x)


def table(head, rows, align=None):
    align = align or ["---"] + ["---:"] * (len(head) - 1)
    out = ["| " + " | ".join(head) + " |", "|" + "|".join(align) + "|"]
    out += ["| " + " | ".join(str(c) for c in r) + " |" for r in rows]
    return "\n".join(out)


def timing(rec, stage):
    t = rec.get("stats", {}).get("timings", {})
    return t.get(stage)


# ---------------------------------------------------------------- pictures

def picture(name, path, title):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection
    d = np.load(os.path.join(OUT, slug(name) + ".npz"))
    V, R, T, P, Tp = d["V"], d["R"], d["T"], d["P"], d["Tp"]
    rng = np.random.default_rng(0)
    fig = plt.figure(figsize=(10, 4.6), dpi=80)
    lo, hi = P.min(0), P.max(0)
    mid, span = (lo + hi) / 2, 0.42 * (hi - lo).max()
    for k, what in enumerate(["part", "axis"]):
        ax = fig.add_subplot(1, 2, k + 1, projection="3d")
        if what == "part":
            tp = Tp if len(Tp) < 40000 else Tp[rng.choice(len(Tp), 40000, replace=False)]
            pc = Poly3DCollection(P[tp], facecolor=(0.7, 0.75, 0.85), edgecolor="none", alpha=1.0)
            n = np.cross(P[tp[:, 1]] - P[tp[:, 0]], P[tp[:, 2]] - P[tp[:, 0]])
            n /= np.linalg.norm(n, axis=1)[:, None] + 1e-30
            shade = 0.45 + 0.55 * np.abs(n @ np.array([0.3, -0.5, 0.8]) / np.linalg.norm([0.3, -0.5, 0.8]))
            pc.set_facecolor(np.c_[0.65 * shade, 0.7 * shade, 0.85 * shade])
            ax.add_collection3d(pc)
            ax.set_title("part (%d triangles)" % len(Tp), fontsize=9)
        else:
            # The largest triangles cover most of the axis: draw those when there are many.
            area = np.linalg.norm(np.cross(V[T[:, 1]] - V[T[:, 0]], V[T[:, 2]] - V[T[:, 0]]), axis=1)
            t = T if len(T) < 60000 else T[np.argsort(-area)[:60000]]
            r = R[t].mean(1)
            cmap = plt.get_cmap("viridis")
            pc = Poly3DCollection(V[t], facecolor=cmap(r / max(R.max(), 1e-12)), edgecolor="none",
                                  alpha=0.9)
            ax.add_collection3d(pc)
            sm = plt.cm.ScalarMappable(cmap=cmap, norm=plt.Normalize(0, R.max()))
            fig.colorbar(sm, ax=ax, shrink=0.6, label="medial radius")
            ax.set_title("medial axis coloured by radius (%s of %d triangles: the largest)"
                         % ("all" if len(t) == len(T) else str(len(t)), len(T)), fontsize=9)
        ax.set_xlim(mid[0] - span, mid[0] + span)
        ax.set_ylim(mid[1] - span, mid[1] + span)
        ax.set_zlim(mid[2] - span, mid[2] + span)
        ax.view_init(40, -58)
        ax.set_axis_off()
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def sweep_plot(sweeps, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axs = plt.subplots(1, 3, figsize=(12, 3.6), dpi=80)
    for name, recs in sweeps.items():
        recs = [r for r in recs if "refused" not in r]
        if not recs:
            continue
        n = [r["stats"]["samples"] for r in recs]
        axs[0].plot(n, [100 * r["recon"]["hausdorff"] / r["diag"] for r in recs], "o-", label=name)
        axs[1].plot(n, [100 * r["completeness"].get("edge_reached", np.nan) for r in recs], "o-", label=name)
        axs[2].plot(n, [r["stats"]["timings"]["total"] for r in recs], "o-", label=name)
    for ax, yl in zip(axs, ["Hausdorff(surface, union of balls), % of diagonal",
                            "convex-edge points reached within h, %", "engine time, s"]):
        ax.set_xscale("log")
        ax.set_xlabel("samples")
        ax.set_ylabel(yl, fontsize=8)
        ax.grid(alpha=0.3)
    axs[0].set_yscale("log")
    axs[2].set_yscale("log")
    axs[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


# ---------------------------------------------------------------- main

def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--full", action="store_true")
    ap.add_argument("--only")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--page", default=os.path.join(ROOT, "docs", "RESULTS.md"))
    a = ap.parse_args()
    os.makedirs(OUT, exist_ok=True)
    os.makedirs(IMG, exist_ok=True)
    t_start = time.time()
    parts = analytic.NAMES + [m["path"] for m in manifest() if a.full or m["path"] not in SLOW_PARTS]
    if a.only:
        parts = [p for p in parts if p in a.only.split(",")]
    meta = {m["path"]: m for m in manifest()}
    limit = TIME_LIMIT_FULL if a.full else TIME_LIMIT

    def one(name):
        r = run_part(name, DEFAULT_SAMPLES, a.build, mesh=name in PICTURE_PARTS, limit=limit)
        print("%-45s %s" % (name, r.get("refused") or "%.1f s" % r.get("wall_process", 0)), flush=True)
        return r
    with ThreadPoolExecutor(a.jobs) as ex:
        recs = list(ex.map(one, parts))

    # The default run (no density given) samples a solid again where its topology is wrong: the
    # parts right at 20,000 samples give the same result by default; the others are run so.
    def one_default(name):
        r = run_part(name, None, a.build, limit=limit)
        print("%-45s %s" % (name + " (default density)", r.get("refused") or "%.1f s" % r.get("wall_process", 0)),
              flush=True)
        return r
    with ThreadPoolExecutor(a.jobs) as ex:
        refined = list(ex.map(one_default, [r["name"] for r in recs if not topology_right(r)]))

    # Ablation: plain MEDIAL on the same samples as CAD_MEDIAL (same target, same spacing).
    ablation_names = [p for p in ABLATION_PARTS if p in parts]

    def one_plain(name):
        r = run_part(name, DEFAULT_SAMPLES, a.build, tag="_plain", plain=True)
        print("%-45s %s" % (name + " (plain MEDIAL)", r.get("refused") or "%.1f s" % r.get("wall_process", 0)),
              flush=True)
        return r
    with ThreadPoolExecutor(a.jobs) as ex:
        plain = list(ex.map(one_plain, ablation_names))

    sweep_counts = [5000, 10000, 20000, 40000] + ([80000, 160000] if a.full else [])
    sweep_names = [p for p in SWEEP_PARTS if p in parts]
    sweeps = {}
    with ThreadPoolExecutor(a.jobs) as ex:
        for name in sweep_names:
            sweeps[name] = list(ex.map(lambda n, nm=name: run_part(nm, n, a.build, tag="_sweep", light=True,
                                                                   limit=limit),
                                       sweep_counts))
    # Timing runs are sequential (one job) so that they do not compete with each other.
    speed_counts = [10000, 66686] + ([250000] if a.full else [])
    speed, speed_err = bench_pipeline(a.build, SPEED_PART, speed_counts)
    paper_counts = sorted({p[1] for p in PAPER_TABLE1})
    paper, paper_err = bench_pipeline(a.build, SPEED_PART, paper_counts)
    for name in PICTURE_PARTS:
        if os.path.exists(os.path.join(OUT, slug(name) + ".npz")):
            picture(name, os.path.join(IMG, "results_%s.png" % slug(os.path.basename(name)).lower()),
                    "%s: %d samples" % (name, next((r["stats"]["samples"] for r in recs
                                                     if r["name"] == name and "stats" in r), 0)))
    if sweeps:
        sweep_plot(sweeps, os.path.join(IMG, "results_density_sweep.png"))
    elapsed = time.time() - t_start
    json.dump({"parts": recs, "default_density": refined, "plain_medial": plain, "sweeps": sweeps, "speed": speed,
               "paper": paper}, open(os.path.join(OUT, "results.json"), "w"), default=float)
    write_page(a, recs, refined, plain, meta, sweeps, speed, speed_err, paper, paper_err, elapsed)


def topology_right(r):
    """Whether every solid of a computed part came in one piece with the solid's Euler characteristic."""
    return "refused" not in r and all(t["euler"] == t["solid_euler"] and t["components"] == 1
                                      for t in r["topology"])


def write_page(a, recs, refined, plain, meta, sweeps, speed, speed_err, paper, paper_err, elapsed):
    cpu = "?"
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    git = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True,
                         text=True).stdout.strip()
    now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    L = []
    L.append("# Results: quality and speed of the inner medial axis\n")
    L.append("Generated by `/usr/bin/python3 bench/results.py%s` on %s, commit %s (plus uncommitted "
             "changes if any), on %s (%d cores, %s), in %.0f s. Every number below comes from that "
             "command; nothing is typed by hand. Raw records: `bench/out/results.json` (not committed)."
             % (" --full" if a.full else "", now, git, cpu, os.cpu_count(), platform.platform(), elapsed))
    L.append("")
    L.append("Default density: %d samples per part (the engine's default; `samples=` is the total over "
             "the part's solids). h is the sample spacing the engine calibrated. Each part runs in "
             "its own process (%d at a time) with a %d s limit; the machine is shared, so times are "
             "indicative." % (DEFAULT_SAMPLES, a.jobs, TIME_LIMIT_FULL if a.full else TIME_LIMIT))
    L.append("")
    L.append("## How each figure is measured\n")
    L.append("""- **Reconstruction error** (as in MATFP, Q-MAT, Coverage Axis): the solid's surface S is sampled
  at 30,000 random points of FreeCAD's tessellation (deflection 5e-4 of the bounding-box diagonal: points within 0.05 % of the diagonal of the exact surface);
  U is the union of the balls B(c_i, r_i) at every output vertex. *Uncovered*: max over surface
  points y of max(0, min_i |y - c_i| - r_i) (surface no ball reaches; exact distance to a union
  of balls, the minimum taken over candidate balls: the 8 centres nearest y and the 4 nearest
  y + d n within d of it, n the surface normal on either side, for d from h/2 up to the
  largest radius in steps of ratio 1.5; a missed ball can only make the figure larger).
  *Stick-out*: max over balls of r_i - d(c_i, S), d from the surface sample (k-d query within 1 % of it; underestimates by at
  most the sample spacing, given per part). *Hausdorff*: max of stick-out and max_y min_i
  | |y - c_i| - r_i | (distance to the nearest ball sphere: a lower bound of the distance to the
  union's boundary). Not measured: parts of the union's boundary deep inside the solid.
  All in % of the bounding-box diagonal.
- **Accuracy** (analytic solids): exact inner medial axis densely sampled (bench/analytic.py);
  output -> axis over output vertices and face centroids, axis -> output over the axis samples
  to a sampling of the output faces at h/3; p95 and max in units of h. The C++ tests' tolerances
  are h / (1 - max cos between face normals) for polytopes (box, plate: h; wedge: larger) and
  2.2 h for curved walls.
- **Completeness**: points every h/2 along the convex edges (analytic: exact; parts: B-rep edges
  whose faces' normals turn by more than 10 degrees, convex when p + eps (n2 - n1) is outside),
  and non-concave corners (vertices of those edges); share within h of the output (sampled at
  h/3).
- **Topology**: per solid, connected components of the output and V - E + F of its polygons,
  against the solid's Euler characteristic (half that of its boundary: V - E + sum over faces of
  (2 - wires), degenerate edges not counted; 1 - genus for a handlebody). The inner medial axis is
  homotopy equivalent to the solid, so they should match.
- **Leakage**: share of 1,500 random output vertices outside every solid. A vertex farther than 3
  surface-sample spacings from its 3 nearest surface samples, in front of all three tangent
  planes (within 60 degrees of their normals) and on the same side of them, is settled by that
  side (outward normals: each face's triangles are turned to agree with FreeCAD's `normalAt`);
  every other vertex, and all of them for a part of several solids, by OpenCASCADE's solid
  classifier (tolerance 1e-6 of the diagonal, boundary counts as inside; the same classifier as
  FreeCAD's `isInside`, built once per solid; a vertex it calls outside that lies within that
  tolerance of a solid is on the boundary: it misses such points next to an edge once the solid
  carries a tessellation). The "classifier" column counts the latter.
- **Parts**: STEP, IGES and BREP files read by FreeCAD (IGES faces sewn into solids, as the
  engine does); FCStd documents opened with PartDesign loaded, their solid being the top-level
  objects' (a Body's tip).
""")

    ok = [r for r in recs if "refused" not in r]
    bad = [r for r in recs if "refused" in r]

    def rel(r, key):
        return 100 * r["recon"][key] / r["diag"]

    L.append("## Summary\n")
    if ok:
        hs = np.array([rel(r, "hausdorff") for r in ok])
        un = np.array([rel(r, "uncovered_max") for r in ok])
        so = np.array([rel(r, "stick_out_max") for r in ok])
        lk = np.array([r["leakage"]["outside_fraction"] for r in ok])
        er = np.array([r["completeness"].get("edge_reached", np.nan) for r in ok])
        topo_ok = sum(topology_right(r) for r in ok)
        topo_default = topo_ok + sum(topology_right(r) for r in refined)
        L.append(table(["figure", "median", "worst", "parts"], [
            ["Hausdorff(S, boundary of U), % diag", f(np.median(hs), 3), f(hs.max(), 3), len(ok)],
            ["uncovered surface, % diag", f(np.median(un), 3), f(un.max(), 3), len(ok)],
            ["balls sticking out, % diag", f(np.median(so), 3), f(so.max(), 3), len(ok)],
            ["convex-edge points reached within h", pct(np.nanmedian(er)), pct(np.nanmin(er)),
             int(np.isfinite(er).sum())],
            ["vertices outside the solid", pct(np.median(lk), 2), pct(lk.max(), 2), len(ok)],
            ["parts whose every solid has 1 component and the solid's Euler characteristic", "", "",
             "%d of %d" % (topo_ok, len(ok))],
            ["the same by default (sampled finer where the topology is wrong: below)", "", "",
             "%d of %d" % (topo_default, len(ok))],
        ]))
        L.append("")
    L.append("%d parts computed, %d refused or failed (listed below)%s.\n" % (len(ok), len(bad),
             "" if a.full else "; default run: the analytic solids and %d of the %d parts of "
             "/work/shared/data/models (all but %d whose engine run is slow here), `--full` for all"
             % (len(meta) - len(SLOW_PARTS), len(meta), len(SLOW_PARTS))))

    L.append("## Reconstruction error and cost per part (%d samples)\n" % DEFAULT_SAMPLES)
    rows = []
    for r in ok:
        st = r["stats"]
        rows.append([r["name"], r["solids"], st["samples"], f(r["h"], 3), r["vertices"], r["faces"],
                     f(rel(r, "hausdorff"), 3), f(rel(r, "uncovered_max"), 3),
                     f(rel(r, "stick_out_max"), 3), f(100 * r["recon"]["surface_sample_spacing"] / r["diag"], 3),
                     f(timing(r, "delaunay")), f(timing(r, "total")), f(st.get("peak_rss_mb"), 0),
                     f(sum(r.get("measure_seconds", {}).values()), 1), f(r.get("wall_process"), 1)])
    L.append(table(["part", "solids", "samples", "h", "vertices", "faces", "Hausdorff %", "uncovered %",
                    "stick-out %", "surface sample spacing %", "Delaunay s", "engine total s",
                    "peak RSS MiB", "measures s", "process s"], rows))
    L.append("")
    L.append("Peak RSS is that of the part's process right after the engine ran (the FreeCAD reader "
             "included). \"measures s\": this page's measures of the part (reconstruction error, "
             "accuracy, completeness, topology, leakage); \"process s\": the part's whole process, "
             "loading included.")
    L.append("")
    stages = []
    for r in ok:
        for k in r["stats"].get("timings", {}):
            if k not in stages:
                stages.append(k)
    L.append("### Time per stage (s)\n")
    L.append("\"check\" (OpenCASCADE's validity check), \"reconstruction\" and \"walls\" (the "
             "thin-wall check of a sampling that it leaves as it is) run on a second thread during "
             "\"delaunay\"; a check that refines the sampling counts as \"sampling\". \"total\" is "
             "the wall-clock time of the whole computation.\n")
    L.append(table(["part"] + stages, [[r["name"]] + [f(timing(r, s)) for s in stages] for r in ok]))
    L.append("")

    L.append("## Accuracy against the exact medial axis (analytic solids)\n")
    rows = [[r["name"], r["stats"]["samples"], f(r["h"], 3), f(r["accuracy"]["out_to_axis_p95_h"]),
             f(r["accuracy"]["out_to_axis_max_h"]), f(r["accuracy"]["axis_to_out_p95_h"]),
             f(r["accuracy"]["axis_to_out_max_h"])] for r in ok if "accuracy" in r]
    L.append(table(["solid", "samples", "h", "output->axis p95 (h)", "output->axis max (h)",
                    "axis->output p95 (h)", "axis->output max (h)"], rows))
    L.append("")

    L.append("## Completeness, topology, leakage\n")
    rows = []
    for r in ok:
        c = r["completeness"]
        topo = r["topology"]
        comps = ",".join(str(t["components"]) for t in topo[:6]) + (",..." if len(topo) > 6 else "")
        eul = ",".join("%d/%s" % (t["euler"], t["solid_euler"]) for t in topo[:6]) + (",..." if len(topo) > 6 else "")
        nmatch = sum(t["euler"] == t["solid_euler"] for t in topo)
        genus = ""
        m = meta.get(r["name"])
        if m and "genus" in m["description"]:
            genus = m["description"].split("genus", 1)[1].split(",")[0].split(";")[0].strip()
        rows.append([r["name"], f(c.get("convex_edge_length"), 1) if c.get("convex_edge_length") is not None else "",
                     c["edge_points"], pct(c.get("edge_reached")),
                     f(c.get("edge_max_h")), c["corners"], pct(c.get("corner_reached")),
                     comps, eul, "%d/%d" % (nmatch, len(topo)), genus,
                     pct(r["leakage"]["outside_fraction"], 2), r["leakage"].get("classifier", "")])
    L.append(table(["part", "convex-edge length", "convex-edge points", "reached", "farthest (h)", "corners",
                    "reached", "components per solid", "Euler out/solid", "solids matching", "genus (MANIFEST)",
                    "vertices outside", "classifier"], rows))
    L.append("")

    L.append("## Refused or failed parts\n")
    if bad:
        L.append(table(["part", "format", "message"],
                       [[r["name"], meta.get(r["name"], {}).get("format", ""), r["refused"].replace("|", "/")]
                        for r in bad], ["---", "---", "---"]))
    else:
        L.append("None.")
    L.append("")

    skipped = [m for m in meta if m not in {r["name"] for r in recs}]
    if skipped:
        L.append("Not run by this invocation (only with `--full`, which runs every part of the "
                 "MANIFEST; the default run leaves out the parts whose engine run alone takes tens of "
                 "seconds to minutes here): " + ", ".join(skipped) + ".\n")
    L.append("## The default density: sampled finer where the topology is wrong\n")
    L.append("With no density given (`cadmedial compute PART`, `cadmedial.compute(part)`; the workbench's "
             "task panel ticks its \"Sample finer\" box by default) the engine starts at %d samples and samples a solid again, at a spacing "
             "sqrt(2.5) times finer (about 2.5 times the samples), at most twice, where its axis's Euler "
             "characteristic is not the solid's or the axis came in pieces. The parts above whose "
             "topology is right at %d samples are computed once that way too; the others:\n"
             % (DEFAULT_SAMPLES, DEFAULT_SAMPLES))
    by_name = {r["name"]: r for r in ok}
    rows = []
    for d in refined:
        r = by_name.get(d["name"])
        if r is None:
            continue
        before = "; ".join("%d (%d), %d" % (t["euler"], t["solid_euler"], t["components"]) for t in r["topology"])
        if "refused" in d:
            rows.append([d["name"], r["stats"]["samples"], before, "failed: " + d["refused"], "", "", "", "", "", ""])
            continue
        after = "; ".join("%d (%d), %d" % (t["euler"], t["solid_euler"], t["components"]) for t in d["topology"])
        steps = max(s.get("refinements", 0) for s in d["stats"]["solids"])
        rows.append([d["name"], r["stats"]["samples"], before, d["stats"]["samples"], steps, f(d["h"], 3), after,
                     f(rel(d, "uncovered_max"), 3), pct(d["completeness"].get("edge_reached")),
                     f(d["stats"]["timings"]["total"])])
    L.append(table(["part", "samples at %d" % DEFAULT_SAMPLES, "Euler (solid's), pieces", "samples by default",
                    "refinements", "finest h", "Euler (solid's), pieces", "uncovered %", "convex edges reached",
                    "engine s"], rows) if rows else "None: every part is right at %d samples." % DEFAULT_SAMPLES)
    L.append("")
    L.append("## Worst parts\n")
    if ok:
        worst = sorted(ok, key=lambda r: -rel(r, "hausdorff"))[:5]
        L.append("By Hausdorff error (the largest term named):\n")
        for r in worst:
            terms = {"uncovered surface": rel(r, "uncovered_max"), "balls sticking out": rel(r, "stick_out_max"),
                     "surface to nearest sphere": 100 * r["recon"]["to_union_boundary_max"] / r["diag"]}
            k = max(terms, key=terms.get)
            L.append("- %s: %.3f %% of the diagonal (%s; h = %.3g, %.2f %% of the diagonal)"
                     % (r["name"], rel(r, "hausdorff"), k, r["h"], 100 * r["h"] / r["diag"]))
        L.append("")
        leaky = [r for r in ok if r["leakage"]["outside_fraction"] > 0]
        if leaky:
            L.append("Vertices outside the solid: " + ", ".join(
                "%s %s" % (r["name"], pct(r["leakage"]["outside_fraction"], 2))
                for r in sorted(leaky, key=lambda r: -r["leakage"]["outside_fraction"])) + ".\n")
        mism = [r for r in ok if any(t["euler"] != t["solid_euler"] or t["components"] != 1 for t in r["topology"])]
        if mism:
            L.append("Topology differs from the solid's: " + ", ".join(r["name"] for r in mism) + ".\n")
        lowc = [r for r in ok if r["completeness"].get("edge_reached", 1) < 0.99]
        if lowc:
            L.append("Convex edges reached below 99 %: " + ", ".join(
                "%s %s" % (r["name"], pct(r["completeness"]["edge_reached"])) for r in lowc) + ".\n")

    warned = [r for r in ok if r["stats"].get("warnings")]
    if warned:
        L.append("## Thin-wall warnings against the exact wall\n")
        L.append("Where the engine warns that walls are thinner than two sample spacings, it names the "
                 "thinnest (`thinnest_wall`, from its samples' shrinking balls) and where it found it "
                 "(`thinnest_wall_at`). \"exact\": twice the radius of the largest ball in the solid "
                 "that touches the boundary at that point from a face's side, its centre on the face's "
                 "inward normal (bisected with FreeCAD's `distToShape` to the boundary and `isInside`; "
                 "on an edge, the smaller over its two faces, as the engine takes it). Exact below reported: the wall there is thinner still than the warning "
                 "says. Above: the engine measured the wall beside the point thinner than at it (near a "
                 "sharp wedge's edge, where the wedge thins to nothing).\n")
        rows = []
        for r in warned:
            for w in r.get("thin_walls", []):
                if w["exact"] is None:
                    continue
                rows.append([r["name"], w["solid"] + 1, f(r["h"], 3), f(w["reported"], 3), f(w["exact"], 3),
                             f(w["exact"] / w["reported"], 2) if w["reported"] > 0 else ""])
        L.append(table(["part", "solid", "h", "reported thickness", "exact thickness there",
                        "exact / reported"], rows))
        L.append("")

    L.append("## Density sweep (the paper's Figure 12)\n")
    if sweeps:
        L.append("![density sweep](img/results_density_sweep.png)\n")
        rows = []
        for name, rs in sweeps.items():
            for r in rs:
                if "refused" in r:
                    rows.append([name, r["target_samples"], "failed: " + r["refused"], "", "", "", ""])
                    continue
                rows.append([name, r["stats"]["samples"], f(r["h"], 3), f(rel(r, "hausdorff"), 3),
                             pct(r["completeness"].get("edge_reached")),
                             f(r["accuracy"]["out_to_axis_max_h"]) if "accuracy" in r else "",
                             f(r["stats"]["timings"]["total"])])
        L.append(table(["part", "samples", "h", "Hausdorff %", "convex edges reached",
                        "output->axis max (h)", "engine s"], rows))
        L.append("")

    def speed_rows(rows):
        out = []
        for s in rows:
            out.append([s.get("target"), s.get("samples"), f(s.get("bare_delaunay")),
                        f(s.get("total")), f(s["total"] / s["bare_delaunay"]) if s.get("bare_delaunay") else "n/a",
                        f(s.get("median_try_ratio")), s.get("vertices"), s.get("faces")])
        return out
    L.append("## Speed: the pipeline beside CGAL's bare Delaunay (`build/bench_pipeline`)\n")
    L.append("On %s (one solid), run sequentially after the parts." % SPEED_PART)
    if speed:
        L.append("")
        L.append(table(["target", "samples", "bare Delaunay s", "pipeline total s", "total / bare",
                        "per try (median of total / bare within a try)", "vertices", "faces"], speed_rows(speed)))
    else:
        L.append("\nbench_pipeline failed: %s" % speed_err)
    L.append("")
    L.append("## Beside the paper's Table 1\n")
    L.append("The paper's seven models are not available; our times are for %s calibrated to the "
             "same sample counts (within 3 %%). Paper: 933 MHz PC, CGAL 2.3, g++ -O1; "
             "\"in all\" = Delaunay + reconstruction + filtering. Ours: this machine, CGAL 5.5, "
             "Release; \"in all\" = every stage of the pipeline (features, sampling, "
             "reconstruction, Delaunay, selection, completion, inner extraction).\n" % SPEED_PART)
    if paper:
        by = {}
        for s in paper:
            by[s["target"]] = s
        rows = []
        for nm, n, dl, rc, fl in sorted(PAPER_TABLE1, key=lambda p: p[1]):
            s = by.get(n, {})
            rows.append([nm, n, f(dl), f(rc), f(dl + rc + fl), s.get("samples", "n/a"),
                         f(s.get("bare_delaunay")), f(stage_of(s, "delaunay")),
                         f(s.get("reconstruction")), f(s.get("total"))])
        L.append(table(["paper model", "points", "paper Delaunay s", "paper recon. s", "paper in all s",
                        "our samples", "our bare Delaunay s", "our Delaunay stage s", "our recon. s",
                        "our in all s"], rows))
    else:
        L.append("bench_pipeline failed: %s" % paper_err)
    L.append("")

    L.append("## Pictures\n")
    for name in PICTURE_PARTS:
        png = "results_%s.png" % slug(os.path.basename(name)).lower()
        if os.path.exists(os.path.join(IMG, png)):
            L.append("![%s](img/%s)\n" % (name, png))
    ablation_section(L, recs, plain)
    L.append("## Known weaknesses of these measurements\n")
    L.append("""- The Hausdorff figure does not see pockets of the union's boundary inside the solid (interior
  regions no ball covers that do not reach the surface), and its S -> boundary term is a lower bound
  (distance to the nearest ball sphere).
- Completeness for the parts depends on a convexity test at each edge's midpoint: an edge that is
  convex on part of its length only is classified by its midpoint.
- Times come from a shared 2-core machine; ratios within one run are more meaningful than absolute
  values.
""")
    open(a.page, "w").write("\n".join(L))
    print("wrote", a.page)


def ablation_section(L, recs, plain):
    L.append("## Ablation: plain MEDIAL against CAD_MEDIAL on the same samples\n")
    L.append("Plain MEDIAL is the paper's section 3 (`cadmedial.compute(..., theta=22.5, "
             "plain_medial=True)`, the program's `--plain-medial --theta 22.5`): umbrellas from the "
             "poles, Angle condition at theta = pi/8, no convex-edge or corner completion. CAD_MEDIAL "
             "is the default (face-by-face umbrellas, theta = 5 degrees, completion at convex edges and "
             "non-concave corners). Both run on the same samples (CAD_MEDIAL's sampler: corners, edges, "
             "triplets and faces; \"same samples\" checks the counts and spacings agree) and the same "
             "inner-axis stage; the measures are those above. Each cell is CAD_MEDIAL / plain MEDIAL.\n")
    cad = {r["name"]: r for r in recs}
    rows, bad = [], []
    for p in plain:
        c = cad.get(p["name"])
        if c is None:
            continue
        if "refused" in p or "refused" in c:
            bad.append([p["name"], c.get("refused", ""), p.get("refused", "")])
            continue

        def both(fn, nd=3):
            return "%s / %s" % (fn(c, nd), fn(p, nd))

        def relf(key):
            return lambda r, nd: f(100 * r["recon"][key] / r["diag"], nd)

        def reached(key):
            return lambda r, nd: pct(r["completeness"].get(key))

        def edges(r, nd):
            c = r["completeness"]
            if c.get("edge_reached") is None:
                return "n/a"
            return "%s (%s h)" % (pct(c["edge_reached"]), f(c.get("edge_max_h")))

        def topo(r, nd):
            t = r["topology"]
            ok = sum(x["components"] == 1 and x["euler"] == x["solid_euler"] for x in t)
            return "%s, %d/%d" % (",".join(str(x["components"]) for x in t[:3]) + (",..." if len(t) > 3 else ""),
                                  ok, len(t))
        same = (c["stats"]["samples"] == p["stats"]["samples"] and c["h"] == p["h"])
        kinds = p.get("face_kinds", [0, 0, 0])
        rows.append([p["name"], c["stats"]["samples"], "yes" if same else "**no**",
                     both(relf("hausdorff")), both(relf("uncovered_max")), both(relf("stick_out_max")),
                     both(edges), both(reached("corner_reached")), both(topo),
                     both(lambda r, nd: pct(r["leakage"]["outside_fraction"], 2)),
                     "%s / %s" % (c["faces"], p["faces"]),
                     "%d" % (kinds[1] + kinds[2]),
                     both(lambda r, nd: f(timing(r, "total")))])
    if rows:
        L.append(table(["part", "samples", "same samples", "Hausdorff %", "uncovered %", "stick-out %",
                        "convex edges reached (farthest point)", "corners reached",
                        "components, solids matching Euler",
                        "vertices outside", "faces", "completion faces in plain", "engine s"], rows))
        L.append("")
        # Counts drawn from the rows: where completion changes the figures.
        pairs = [(cad[p["name"]], p) for p in plain if p["name"] in cad and "refused" not in p
                 and "refused" not in cad[p["name"]]]
        if pairs:
            def count(pred):
                return sum(1 for c, p in pairs if pred(c, p))
            def er(r):
                return r["completeness"].get("edge_reached")
            def far(r):
                return r["completeness"].get("edge_max_h")
            L.append("Over these %d parts: plain MEDIAL has the larger uncovered surface on %d, reaches fewer "
                     "convex-edge points on %d (of %d with convex edges) and leaves its farthest convex-edge "
                     "point farther on %d, reaches fewer corners on %d, and matches "
                     "the solid's topology (1 component, its Euler characteristic) on %d against %d for "
                     "CAD_MEDIAL.\n" % (
                         len(pairs),
                         count(lambda c, p: p["recon"]["uncovered_max"] > c["recon"]["uncovered_max"]),
                         count(lambda c, p: er(c) is not None and er(p) is not None and er(p) < er(c)),
                         count(lambda c, p: er(c) is not None),
                         count(lambda c, p: far(c) is not None and far(p) is not None and far(p) > far(c)),
                         count(lambda c, p: (p["completeness"].get("corner_reached") or 0)
                               < (c["completeness"].get("corner_reached") or 0)),
                         count(lambda c, p: all(t["components"] == 1 and t["euler"] == t["solid_euler"]
                                                for t in p["topology"])),
                         count(lambda c, p: all(t["components"] == 1 and t["euler"] == t["solid_euler"]
                                                for t in c["topology"]))))
    if bad:
        L.append(table(["part", "CAD_MEDIAL", "plain MEDIAL"], bad, ["---", "---", "---"]))
        L.append("")


def stage_of(s, name):
    m = s.get("medial") if isinstance(s, dict) else None
    if isinstance(m, dict):
        return m.get(name)
    if isinstance(m, list):
        for k, v in m:
            if k == name:
                return v
    return s.get(name) if isinstance(s, dict) else None


if __name__ == "__main__":
    main()
