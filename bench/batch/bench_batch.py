"""Throughput of `cadmedial batch` on the shared models, with --jobs 1 and --jobs 2.

    nice -n 10 /usr/bin/python3 bench/batch/bench_batch.py [--cli build/cadmedial] [--samples 20000]
        [--jobs 1 2] [--models /work/shared/data/models] [--out bench/out/batch]

Runs `cadmedial batch LIST -o OUT/jobsN --jobs N --force` on every model of MANIFEST.tsv, and
prints per N: the wall time of the whole command (the local cluster's start included), parts per
minute, the sum of the per-part times of summary.json, that sum over (wall x N) (how busy the
workers were), and the counts by status. Writes the table as JSON to OUT/results.json.
"""

import argparse
import json
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, os.pardir, os.pardir))


def models(folder):
    with open(os.path.join(folder, "MANIFEST.tsv"), encoding="utf-8") as f:
        rows = [line.rstrip("\n").split("\t") for line in f][1:]
    return [os.path.join(folder, r[0]) for r in rows if r and r[0]]


def run(cli, list_file, out, jobs, samples, timeout):
    argv = [cli, "batch", list_file, "-o", out, "--jobs", str(jobs), "--force", "--quiet",
            "--timeout", str(timeout)]
    if samples:
        argv += ["--samples", str(samples)]
    start = time.monotonic()
    p = subprocess.run(argv, capture_output=True, text=True)
    wall = time.monotonic() - start
    if p.returncode not in (0, 3):
        sys.exit("bench_batch: %s failed (%d): %s" % (" ".join(argv), p.returncode, p.stderr.strip()))
    with open(os.path.join(out, "summary.json"), encoding="utf-8") as f:
        summary = json.load(f)
    parts = summary["parts"]
    busy = sum(r["time_s"] or 0 for r in parts)
    return {"jobs": jobs, "parts": len(parts), "wall_s": round(wall, 2),
            "parts_per_min": round(60 * len(parts) / wall, 2), "sum_part_s": round(busy, 2),
            "busy": round(busy / (wall * jobs), 3), "counts": summary["counts"], "argv": argv}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--cli", default=os.path.join(REPO, "build", "cadmedial"))
    ap.add_argument("--models", default="/work/shared/data/models")
    ap.add_argument("--samples", type=int, default=20000, help="0: the default density (with refinement)")
    ap.add_argument("--jobs", type=int, nargs="+", default=[1, 2])
    ap.add_argument("--timeout", type=float, default=600)
    ap.add_argument("--out", default=os.path.join(REPO, "bench", "out", "batch"))
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    list_file = os.path.join(a.out, "models.txt")
    with open(list_file, "w", encoding="utf-8") as f:
        f.write("\n".join(models(a.models)) + "\n")
    results = []
    print("%5s %6s %8s %9s %10s %6s  %s" % ("jobs", "parts", "wall s", "parts/min", "sum part s", "busy", "status"))
    for jobs in a.jobs:
        r = run(a.cli, list_file, os.path.join(a.out, "jobs%d" % jobs), jobs, a.samples, a.timeout)
        results.append(r)
        print("%5d %6d %8.1f %9.2f %10.1f %6.2f  %s" % (
            r["jobs"], r["parts"], r["wall_s"], r["parts_per_min"], r["sum_part_s"], r["busy"],
            ", ".join("%d %s" % (n, s) for s, n in r["counts"].items())), flush=True)
    with open(os.path.join(a.out, "results.json"), "w", encoding="utf-8") as f:
        json.dump(results, f, indent=1)


if __name__ == "__main__":
    main()
