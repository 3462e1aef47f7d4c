"""Cancellation latency of cadmedial.compute: the time from a cancel request (the progress
callback returning False) to the cadmedial.Cancelled exception, and the memory left after it.

    /usr/bin/python3 bench/cancel_latency.py [--part PATH] [--samples N] [--delays S,S,...] [--json FILE]

Run from the repository root with build/ built (the package finds build/python/cadmedial), or
with PYTHONPATH=python and CADMEDIAL_CORE_DIR=build/python/cadmedial as the tests do.

Every measurement runs in a fresh child process (the same script with --child), so that the RSS
figures of one run are not those of the previous one:
  1. a profile run, not cancelled: every progress call's time, hence each stage's span and the
     longest gap between two calls (the worst latency a cancel request can meet in that stage);
  2. a cancel at the first progress call of each stage name the profile saw;
  3. a cancel requested from another thread 0.02 s into the longest silence (no progress call) of
     each stage, timed from the call that starts it (so that a slower or faster run still hits
     it), and at fixed delays from the start: latency = from the request to the exception, which
     waits for the next progress call.
RSS (VmRSS of /proc/self/status): before compute, after the exception, and after gc.collect()
plus glibc's malloc_trim(0) (freed heap that glibc keeps for reuse is not returned to the system
until trimmed); peak = VmHWM.
"""

import argparse
import ctypes
import gc
import json
import os
import subprocess
import sys
import threading
import time

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir))
DEFAULT_PART = os.path.normpath(os.path.join(REPO, os.pardir, "shared", "data", "models", "freecad",
                                             "Y_Rod_Mount.brep"))
GOAL_S = 1.0


def rss_mib(field="VmRSS"):
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith(field + ":"):
                return int(line.split()[1]) / 1024.0
    return float("nan")


def child(args):
    """One compute in this process; prints one JSON object."""
    sys.path.insert(0, os.path.join(REPO, "python"))
    import cadmedial

    shape = cadmedial.read_shape(args.part)
    calls = []            # (time, stage, fraction) of every progress call
    request = {}          # time and stage of the cancel request
    flag = threading.Event()
    mode, value = args.child, args.value

    seen = {}             # progress calls so far, by stage
    if mode == "after":
        after_stage, after_k, after_delay = value.split(":")
        after_k, after_delay = int(after_k), float(after_delay)

    def progress(stage, fraction):
        now = time.perf_counter()
        calls.append((now, stage, fraction))
        k = seen.get(stage, 0)
        seen[stage] = k + 1
        if mode == "stage" and stage == value and not request:
            request.update(t=time.perf_counter(), stage=stage)
            return False
        if mode == "after" and stage == after_stage and k == after_k:
            threading.Thread(target=requester, args=(after_delay,), daemon=True).start()
        if mode in ("delay", "after") and flag.is_set():
            return False
        return True

    def requester(delay):
        time.sleep(delay)
        request.update(t=time.perf_counter(), stage=calls[-1][1] if calls else "")
        flag.set()

    rss_before = rss_mib()
    t0 = time.perf_counter()
    if mode == "delay":
        threading.Thread(target=requester, args=(float(value),), daemon=True).start()
    out = {"mode": mode, "value": value, "rss_before_mib": rss_before}
    try:
        result = cadmedial.compute(shape, samples=args.samples, progress=progress)
        out["cancelled"] = False
        out["samples"] = result.stats.get("samples")
        out["timings"] = result.stats.get("timings")
        del result
    except cadmedial.Cancelled:
        t_end = time.perf_counter()
        out["cancelled"] = True
        if request:
            out["latency_s"] = t_end - request["t"]
            out["request_at_s"] = request["t"] - t0
            out["stage_at_request"] = request["stage"]
    out["total_s"] = time.perf_counter() - t0
    out["stage_at_end"] = calls[-1][1] if calls else ""
    out["rss_after_mib"] = rss_mib()
    gc.collect()
    ctypes.CDLL("libc.so.6").malloc_trim(0)
    out["rss_after_trim_mib"] = rss_mib()
    out["rss_peak_mib"] = rss_mib("VmHWM")
    if mode == "profile":
        out["calls"] = [(t - t0, s, f) for t, s, f in calls]
    print(json.dumps(out))


def run_child(args, mode, value=""):
    cmd = [sys.executable, os.path.abspath(__file__), "--child", mode, "--value", str(value),
           "--part", args.part, "--samples", str(args.samples)]
    out = subprocess.run(cmd, check=True, stdout=subprocess.PIPE, text=True).stdout
    return json.loads(out.strip().splitlines()[-1])


def stage_spans(calls):
    """[stage, first call, last call, longest silence after a call of this stage, when that silence
    starts] in order. The silence after a stage's last call runs into the next stage (or an unnamed
    one: the Delaunay triangulation runs between the last 'reconstruction' call and the first
    'selection' call)."""
    spans = []
    for k, (t, stage, _) in enumerate(calls):
        gap = calls[k + 1][0] - t if k + 1 < len(calls) else 0.0
        if not spans or spans[-1][0] != stage:
            spans.append([stage, t, t, gap, t])
        else:
            spans[-1][2] = t
            if gap > spans[-1][3]:
                spans[-1][3], spans[-1][4] = gap, t
    return spans


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--part", default=DEFAULT_PART)
    parser.add_argument("--samples", type=int, default=250000)
    parser.add_argument("--delays", default="0.5,1,2,4,8,12,16",
                        help="seconds after the start at which another thread requests the cancel")
    parser.add_argument("--json", help="also write every run's figures to this file")
    parser.add_argument("--child", help=argparse.SUPPRESS)
    parser.add_argument("--value", default="", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.child:
        child(args)
        return

    runs = []
    profile = run_child(args, "profile")
    runs.append(profile)
    spans = stage_spans(profile["calls"])
    print("part %s, %s samples, full run %.2f s, peak RSS %.0f MiB" %
          (os.path.relpath(args.part, REPO), profile["samples"], profile["total_s"], profile["rss_peak_mib"]))
    print("\nprofile: each stage's calls and the longest silence (no progress call) after one of them")
    print("| stage (progress name) | first call s | last call s | longest silence after a call s |")
    print("|---|---:|---:|---:|")
    for stage, first, last, gap, _ in spans:
        print("| %s | %.3f | %.3f | %.3f |" % (stage, first, last, gap))

    stages = []
    for stage, _, _, _, _ in spans:
        if stage not in stages:
            stages.append(stage)
    requests = [("stage", s) for s in stages]
    # Just inside the longest silence after a call of each stage, if longer than 0.2 s: such a
    # request waits for the call that ends the silence. Timed from that call (its index among the
    # stage's calls), not from the start.
    for stage, first, last, gap, gap_start in spans:
        if gap > 0.2:
            k = sum(1 for t, st, _ in profile["calls"] if st == stage and t < gap_start)
            requests.append(("after", "%s:%d:0.02" % (stage, k)))
    requests += [("delay", float(d)) for d in args.delays.split(",") if d]

    print("\n| request | stage at request | stage at exception | latency s | RSS before MiB | "
          "RSS after MiB | after trim MiB | peak MiB |")
    print("|---|---|---|---:|---:|---:|---:|---:|")
    worst = 0.0
    for mode, value in requests:
        r = run_child(args, mode, value)
        runs.append(r)
        if mode == "stage":
            label = "first '%s' call" % value
        elif mode == "after":
            st, k, d = value.split(":")
            label = "%s s after '%s' call %s" % (d, st, k)
        else:
            label = "at %.3f s" % float(value)
        if not r["cancelled"]:
            print("| %s | (finished first, %.2f s) | | | %.0f | %.0f | %.0f | %.0f |" %
                  (label, r["total_s"], r["rss_before_mib"], r["rss_after_mib"], r["rss_after_trim_mib"],
                   r["rss_peak_mib"]))
            continue
        worst = max(worst, r["latency_s"])
        print("| %s | %s | %s | %.3f%s | %.0f | %.0f | %.0f | %.0f |" %
              (label, r["stage_at_request"], r["stage_at_end"], r["latency_s"],
               " **" if r["latency_s"] > GOAL_S else "", r["rss_before_mib"], r["rss_after_mib"],
               r["rss_after_trim_mib"], r["rss_peak_mib"]))
    print("\nworst latency %.3f s (goal %.1f s); ** marks a miss" % (worst, GOAL_S))
    if args.json:
        with open(args.json, "w") as f:
            json.dump(runs, f, indent=1)


if __name__ == "__main__":
    main()
