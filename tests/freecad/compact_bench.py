# The figures of docs/workbench.md (Compact mesh): for each part, a MedialAxis at the automatic
# density, then Simplify 0.2, 0.5 and 1 % (simplified again from the full axis in memory) and 0;
# faces, seconds of each recompute, size of the saved .FCStd and seconds to open it in a fresh
# freecadcmd (compact_reopen.py, best of 3). Not a test: run by hand,
#   CADMEDIAL_BENCH_PARTS=a.brep:b.stp CADMEDIAL_BENCH_OUT=/tmp/bench \
#     freecadcmd tests/freecad/compact_bench.py        (from the repository's root folder)
# (with PYTHONPATH and CADMEDIAL_CORE_DIR as for the tests, tests/freecad/CMakeLists.txt).
import json
import os
import subprocess
import time

import FreeCAD
import Part

import cadmedial.app as medial_app

# freecadcmd may run a script without __file__: then from the repository's root folder.
HERE = (os.path.dirname(os.path.abspath(__file__)) if "__file__" in globals()
        else os.path.join(os.getcwd(), "tests", "freecad"))
PERCENTS = (0.2, 0.5, 1.0, 0.0)


def open_seconds(path, out):
    best = None
    for _ in range(3):
        report = os.path.join(out, "reopen.json")
        env = dict(os.environ, CADMEDIAL_DOC=path, CADMEDIAL_OUT=report)
        env.pop("CADMEDIAL_SIMPLIFY", None)
        subprocess.run(["freecadcmd", os.path.join(HERE, "compact_reopen.py")], env=env,
                       capture_output=True, timeout=600)
        with open(report) as f:
            seconds = json.load(f)["open_seconds"]
        best = seconds if best is None else min(best, seconds)
    return best


def bench(path, out):
    doc = FreeCAD.newDocument("Bench")
    part = doc.addObject("Part::Feature", "Part")
    part.Shape = Part.read(path)
    doc.recompute()
    started = time.perf_counter()
    feature = medial_app.make_medial_axis(part, simplify=0)
    rows = [{"simplify": "axis", "seconds": time.perf_counter() - started,
             "faces": feature.FaceCount, "triangles": feature.Mesh.CountFacets}]
    full = feature.Proxy.full
    for percent in PERCENTS:
        feature.Simplify = percent
        started = time.perf_counter()
        doc.recompute()
        seconds = time.perf_counter() - started
        saved = os.path.join(out, "%s-%g.FCStd" % (os.path.basename(path), percent))
        doc.saveAs(saved)
        rows.append({"simplify": percent, "seconds": seconds, "faces": feature.FaceCount,
                     "triangles": feature.Mesh.CountFacets, "simplified": feature.Simplified,
                     "bytes": os.path.getsize(saved), "open_seconds": open_seconds(saved, out),
                     "engine_ran": feature.Proxy.full is not full})
    FreeCAD.closeDocument(doc.Name)
    return rows


out = os.environ.get("CADMEDIAL_BENCH_OUT", "/tmp/cadmedial-compact-bench")
os.makedirs(out, exist_ok=True)
for part_path in os.environ["CADMEDIAL_BENCH_PARTS"].split(":"):
    for row in bench(part_path, out):
        print("BENCH %s %s" % (os.path.basename(part_path), json.dumps(row)), flush=True)
os._exit(0)
