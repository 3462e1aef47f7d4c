"""The wall-thickness step of a batch run (``cadmedial batch --thickness``, cadmedial.batch's
analyses.py): the command that analyses one part, and the summary columns from its files."""

import json
import os

from .exit_status import OUT_OF_LIMITS, PASS

# The summary.csv columns this step adds (summary.json has them too).
BATCH_COLUMNS = ("thickness_passed", "thickness_min", "thickness_max", "thickness_mean",
                 "thin_regions", "thick_regions")


def batch_step(source, work_dir, cli, options):
    """(argv, {suffix: file}): `cadmedial thickness` on ``source`` with the batch's limits,
    writing its statistics and regions into ``work_dir``."""
    files = {"_thickness.json": os.path.join(work_dir, "thickness.json"),
             "_thickness_regions.csv": os.path.join(work_dir, "thickness_regions.csv")}
    argv = [cli, "thickness", source, "--json", files["_thickness.json"],
            "--regions-csv", files["_thickness_regions.csv"], "--quiet"]
    for limit in ("min", "max"):
        if options.get(limit) is not None:
            argv += ["--" + limit, repr(float(options[limit]))]
    return argv, files


def batch_result(returncode, outputs):
    """The part's thickness columns; raises when the analysis itself failed (not when the part
    is out of its limits: that is a result, thickness_passed False)."""
    if returncode not in (PASS, OUT_OF_LIMITS):
        raise RuntimeError("the analysis exited with status %d" % returncode)
    with open(outputs["_thickness.json"]) as f:
        result = json.load(f)
    st = result["statistics"]
    return {"thickness_passed": bool(result["passed"]), "thickness_min": st.get("min"),
            "thickness_max": st.get("max"), "thickness_mean": st.get("mean"),
            "thin_regions": len(result["thin_regions"]), "thick_regions": len(result["thick_regions"])}
