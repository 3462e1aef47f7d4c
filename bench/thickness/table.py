"""The markdown table of docs/thickness.md from a run.py JSON file.

    /usr/bin/python3 bench/thickness/table.py bench/out/thickness.json
"""

import json
import math
import sys


def pct(x):
    return "nan" if x is None or not math.isfinite(x) else "%.2f" % (100 * x)


def main(path):
    print("| part | points | counted area | p50 % | p95 % | max % | medial reading p95 % | max % "
          "| medial s | analysis s | x | x CPU | refine s | refined | ref ms/pt | ref all s | min | ref at min |")
    print("|---" * 18 + "|")
    for r in json.load(open(path)):
        if "refused" in r:
            print("| %s | refused: %s |" % (r["part"], r["refused"][:90]))
            continue
        cpu = r.get("total_over_medial_cpu")
        print("| %s | %d | %.0f %% | %s | %s | %s | %s | %s | %.2f | %.2f | %.2f | %s | %.2f | %.0f %% "
              "| %.1f | %.0f | %.4g | %.4g |"
              % (r["part"], r["points"], 100 * r["counted_share"], pct(r["p50"]), pct(r["p95"]),
                 pct(r["max"]), pct(r["medial_reading_p95"]), pct(r["medial_reading_max"]),
                 r["medial_s"], r["analysis_s"], r["total_over_medial"],
                 "-" if cpu is None else "%.2f" % cpu, r["refine_s"],
                 100 * r["refined_share"], 1e3 * r["reference_s_per_point"],
                 r["reference_s_all_points"], r["min"] or float("nan"), r["min_reference"]))


if __name__ == "__main__":
    main(sys.argv[1])
