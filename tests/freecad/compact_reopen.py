# Run by test_compact.py in a fresh freecadcmd (freecadcmd passes no arguments: the environment):
#   CADMEDIAL_DOC       the .FCStd to open
#   CADMEDIAL_OUT       where to write the JSON report
#   CADMEDIAL_SIMPLIFY  optional: a new Simplify for the MedialAxis, then a recompute
# Reports how long importing cadmedial.app and openDocument took, and what the MedialAxis holds
# before and after (also compact_bench.py runs it).
import json
import os
import time
import traceback

import FreeCAD

# FreeCAD restores a Python proxy only from a module already imported ("module not permitted"
# otherwise): as a script using the objects would, import them first. Timed apart from the open.
started = time.perf_counter()
import cadmedial.app  # noqa: E402,F401
IMPORT_SECONDS = time.perf_counter() - started


def figures(obj):
    return {"facets": obj.Mesh.CountFacets, "points": obj.Mesh.CountPoints,
            "colors": len(obj.RadiusColors), "vertex_count": obj.VertexCount,
            "simplify": float(obj.Simplify), "simplified": obj.Simplified, "status": obj.Status,
            "state": list(obj.State), "full_in_memory": obj.Proxy.full is not None}


report = {"import_seconds": IMPORT_SECONDS}
try:
    started = time.perf_counter()
    doc = FreeCAD.openDocument(os.environ["CADMEDIAL_DOC"])
    report["open_seconds"] = time.perf_counter() - started
    obj = doc.getObject("MedialAxis")
    report["opened"] = figures(obj)
    if os.environ.get("CADMEDIAL_SIMPLIFY"):
        obj.Simplify = float(os.environ["CADMEDIAL_SIMPLIFY"])
        started = time.perf_counter()
        doc.recompute()
        report["recompute_seconds"] = time.perf_counter() - started
        report["changed"] = figures(obj)
except Exception:
    report["exception"] = traceback.format_exc()
with open(os.environ["CADMEDIAL_OUT"], "w") as out:
    json.dump(report, out)
os._exit(0)
