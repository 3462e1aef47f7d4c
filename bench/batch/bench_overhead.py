"""The batch runner's own cost per part: N copies of a small part through cadmedial.batch on an
already running local cluster, beside an `xargs -P J` loop of `cadmedial compute` over the same
copies (the hand-made loop issue 36 compares with).

    nice -n 10 /usr/bin/python3 bench/batch/bench_overhead.py [--copies 100] [--jobs 2]
        [--part tests/python/data/box_10x20x30.step] [--samples 3000] [--cli build/cadmedial]

Prints both wall times, the batch's time per part beyond the part's own (wall x J - sum of part
times) / N, and the ratio of the two throughputs. Needs PYTHONPATH=python (and CADMEDIAL_CORE_DIR
when the module is not in build/).
"""

import argparse
import os
import shutil
import subprocess
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, os.pardir, os.pardir))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--copies", type=int, default=100)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--part", default=os.path.join(REPO, "tests", "python", "data", "box_10x20x30.step"))
    ap.add_argument("--samples", type=int, default=3000)
    ap.add_argument("--cli", default=os.path.join(REPO, "build", "cadmedial"))
    ap.add_argument("--out", default=os.path.join(REPO, "bench", "out", "batch_overhead"))
    a = ap.parse_args()

    import distributed
    import cadmedial

    shutil.rmtree(a.out, ignore_errors=True)
    inputs = os.path.join(a.out, "in")
    os.makedirs(inputs)
    suffix = os.path.splitext(a.part)[1]
    # Copies, not links: the batch counts a file once by its real path.
    paths = []
    for i in range(a.copies):
        paths.append(os.path.join(inputs, "part%04d%s" % (i, suffix)))
        shutil.copy(a.part, paths[-1])

    xargs_out = os.path.join(a.out, "xargs")
    os.makedirs(xargs_out)
    start = time.monotonic()
    subprocess.run(["xargs", "-P", str(a.jobs), "-I{}", "sh", "-c",
                    '"$0" compute "$1" -o "$2/$(basename "$1").ply" --stats "$2/$(basename "$1").json" '
                    '--quiet --samples "$3"', a.cli, "{}", xargs_out, str(a.samples)],
                   input="\n".join(paths) + "\n", text=True, check=True, stdout=subprocess.DEVNULL)
    xargs_wall = time.monotonic() - start

    cluster = distributed.LocalCluster(n_workers=a.jobs, threads_per_worker=1, processes=True,
                                       dashboard_address=None)
    client = distributed.Client(cluster)
    try:
        start = time.monotonic()
        result = cadmedial.batch(inputs, os.path.join(a.out, "batch"), client=client, samples=a.samples,
                                 cli=a.cli, progress=False)
        batch_wall = time.monotonic() - start
    finally:
        client.close()
        cluster.close()
    busy = sum(r["time_s"] for r in result.records)
    print("%d copies of %s, --samples %d, %d jobs" % (a.copies, os.path.basename(a.part), a.samples, a.jobs))
    print("xargs -P%d cadmedial compute: %.2f s (%.1f parts/s)" % (a.jobs, xargs_wall, a.copies / xargs_wall))
    print("cadmedial.batch on a running cluster: %.2f s (%.1f parts/s), %s" % (
        batch_wall, a.copies / batch_wall, result.counts))
    print("sum of part times %.2f s; batch time per part beyond the part's own: %.1f ms" % (
        busy, 1000 * (batch_wall * a.jobs - busy) / a.copies))
    print("batch throughput / xargs throughput: %.3f" % (xargs_wall / batch_wall))


if __name__ == "__main__":
    main()
