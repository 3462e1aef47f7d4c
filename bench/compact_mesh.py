"""The compact mesh on the shared models: faces, error and time at a few tolerances.

    /usr/bin/python3 bench/compact_mesh.py [--build DIR] [--only NAME,...] [--tolerances 0.1%,0.5%,1%]
                                           [--timeout S] [-o OUT.json]

Runs `cadmedial compute PART -o /tmp/... --simplify TOL --stats` once per part and tolerance (the
default density) and prints a markdown table: the full axis's polygons (and the triangles
they fan into), the compact mesh's triangles and the ratio of polygons to them, the largest
|dc| + |dr| both ways against the tolerance, whether the Euler characteristic and the pieces
stayed, and the time of the axis (total less snap and compact) beside the snap's and the
compact step's. FreeCAD parts (.fcstd) need FreeCAD and are left out.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
MODELS = os.path.normpath(os.path.join(ROOT, os.pardir, "shared", "data", "models"))


def parts(only):
    with open(os.path.join(MODELS, "MANIFEST.tsv")) as f:
        rows = [line.split("\t")[0] for line in f.read().splitlines()[1:] if line.strip()]
    rows = [r for r in rows if not r.lower().endswith(".fcstd")]
    if only:
        rows = [r for r in rows if any(o in r for o in only)]
    return rows


def run(cli, part, tol, timeout):
    with tempfile.TemporaryDirectory() as tmp:
        out, stats = os.path.join(tmp, "c.ply"), os.path.join(tmp, "s.json")
        try:
            p = subprocess.run([cli, "compute", os.path.join(MODELS, part), "-o", out, "--simplify", tol,
                                "--stats", stats, "--quiet"], capture_output=True, text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            return {"part": part, "tolerance": tol, "error": "timeout %d s" % timeout}
        if p.returncode != 0:
            return {"part": part, "tolerance": tol, "error": p.stderr.strip().splitlines()[-1][:120]}
        with open(stats) as f:
            s = json.load(f)
    t = s["timings"]
    c = s["simplify"]
    return {"part": part, "tolerance": tol, "tol": c["tolerance"], "polygons": c["faces_before"],
            "triangles": c["faces_after"], "max_error": c["max_error"], "max_containment": c["max_containment"],
            "euler": [c["euler_before"], c["euler_after"]], "pieces": [c["components_before"], c["components_after"]],
            "axis_s": t["total"] - t.get("snap", 0) - t.get("compact", 0), "snap_s": t.get("snap", 0),
            "compact_s": t.get("compact", 0), "snapped": s.get("snap", {}).get("snapped", 0),
            "vertices": s.get("snap", {}).get("vertices", 0)}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--only", default="")
    ap.add_argument("--tolerances", default="0.1%,0.5%,1%")
    ap.add_argument("--timeout", type=int, default=300)
    ap.add_argument("-o", "--output", default="")
    a = ap.parse_args()
    cli = os.path.join(a.build, "cadmedial")
    rows = []
    print("| part | tolerance | polygons | compact triangles | polygons / triangles | full->compact | "
          "compact->full | Euler, pieces kept | axis s | snap s | compact s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for part in parts([o for o in a.only.split(",") if o]):
        for tol in a.tolerances.split(","):
            r = run(cli, part, tol, a.timeout)
            rows.append(r)
            if "error" in r:
                print("| %s | %s | %s |" % (part, tol, r["error"]))
            else:
                print("| %s | %s | %d | %d | %.1f | %.2f tol | %.2f tol | %s | %.2f | %.2f | %.2f |" % (
                    part, tol, r["polygons"], r["triangles"], r["polygons"] / max(1, r["triangles"]),
                    r["max_error"] / r["tol"], r["max_containment"] / r["tol"],
                    "yes" if r["euler"][0] == r["euler"][1] and r["pieces"][0] == r["pieces"][1] else
                    "NO %s %s" % (r["euler"], r["pieces"]), r["axis_s"], r["snap_s"], r["compact_s"]))
            sys.stdout.flush()
    if a.output:
        with open(a.output, "w") as f:
            json.dump(rows, f, indent=1)


if __name__ == "__main__":
    main()
