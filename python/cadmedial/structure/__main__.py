"""python -m cadmedial.structure PART [--samples N | --spacing S] [--json OUT] [--repeat K] [--raw]
    [--touches]

Computes the axis of PART, then its structure; prints both times, wall clock and CPU (each the
fastest of K runs: the machine may be shared; the compute runs on two threads, the structure on
one), the counts, the largest sheets, the seams and the curves."""

import argparse
import json
import sys
import time

import cadmedial

from .analysis import structure


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python -m cadmedial.structure", description=__doc__)
    parser.add_argument("part", help="STEP, IGES or BREP file")
    parser.add_argument("--samples", type=int)
    parser.add_argument("--spacing", type=float)
    parser.add_argument("--json", help="write the tables (AxisStructure.to_dict()) here")
    parser.add_argument("--repeat", type=int, default=1, help="time each step K times")
    parser.add_argument("--touches", action="store_true",
                        help="name the B-rep faces each sheet's balls touch (structure(shape=))")
    parser.add_argument("--raw", action="store_true",
                        help="also print the counts without merging slivers (merge_slivers=False)")
    args = parser.parse_args(argv)
    compute_times, compute_cpu = [], []
    for _ in range(max(args.repeat, 1)):
        start, cpu = time.perf_counter(), time.process_time()
        result = cadmedial.compute(args.part, spacing=args.spacing, samples=args.samples)
        compute_times.append(time.perf_counter() - start)
        compute_cpu.append(time.process_time() - cpu)
    compute_s = min(compute_times)
    times, cpus = [], []
    for _ in range(max(args.repeat, 1)):
        start, cpu = time.perf_counter(), time.process_time()
        s = structure(result, shape=args.part if args.touches else None)
        times.append(time.perf_counter() - start)
        cpus.append(time.process_time() - cpu)
    print("%s: %d vertices, %d faces, %d edges; spacing %.4g" % (
        args.part, result.num_vertices, result.num_faces, result.num_edges, s.spacing))
    print("compute %.2f s, structure %.2f s (%.0f %%); CPU compute %.2f s, structure %.2f s"
          " (%.0f %%)" % (compute_s, min(times), 100 * min(times) / compute_s, min(compute_cpu),
                          min(cpus), 100 * min(cpus) / min(compute_cpu)))
    print(", ".join("%d %s" % (n, k) for k, n in s.counts().items()))
    if args.raw:
        raw = structure(result, merge_slivers=False)
        print("raw: " + ", ".join("%d %s" % (n, k) for k, n in raw.counts().items()))
    for k, d in enumerate(s.sheets[:10]):
        print("  sheet %d: %d faces, area %.4g, radius %.4g..%.4g, flatness %.3g, %d seams%s" % (
            k, d["faces"], d["area"], d["radius_min"], d["radius_max"], d["flatness"],
            len(d["seams"]), "".join(", Face%d %.0f %%" % (f + 1, 100 * share)
                                     for f, share in d.get("touches", []))))
    for k, d in enumerate(s.seams[:10]):
        print("  seam %d: length %.4g, sheets %s" % (k, d["length"], d["sheets"]))
    for k, d in enumerate(s.curves[:10]):
        print("  curve %d (%s): length %.4g, radius %.4g..%.4g" % (
            k, d["source"], d["length"], d["radius_min"], d["radius_max"]))
    if args.json:
        with open(args.json, "w") as f:
            json.dump(s.to_dict(), f)
    return 0


if __name__ == "__main__":
    sys.exit(main())
