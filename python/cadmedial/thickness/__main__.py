"""cadmedial thickness PART --min T [--max T] [--corners zero|exclude] [-o values.ply|csv]
[--report r.html] [--regions-csv F] [--faces-csv F] [--json F] [--samples N | --spacing S]

Exit status (for CI gates): 0 the part passes, 3 it is thinner than --min or thicker than
--max somewhere (outside the corner band), 2 bad input or option, 1 an internal error. The C++
program dispatches `cadmedial thickness ...` here; `python3 -m cadmedial.thickness ...` is the same.
"""

import argparse
import json
import os
import sys

from cadmedial.thickness.exit_status import BAD_INPUT, INTERNAL, OUT_OF_LIMITS, PASS


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # one line, as the C++ program's errors, and status 2
        sys.stderr.write("cadmedial: error: thickness: %s\n" % message)
        sys.exit(BAD_INPUT)


def _parser():
    p = _Parser(prog="cadmedial thickness", description="Wall thickness of the solids of a "
                "STEP, IGES or BREP file (sphere method, from the medial axis).")
    p.add_argument("part", help="STEP, IGES or BREP file")
    p.add_argument("--min", type=float, help="minimum wall: thinner regions fail (exit 3)")
    p.add_argument("--max", type=float, help="maximum wall: thicker regions fail (exit 3)")
    p.add_argument("--corners", choices=["exclude", "zero"], default="exclude",
                   help="exclude (default): leave the band next to convex edges out; zero: count "
                        "it, with the thickness going to zero at the edge")
    p.add_argument("-o", "--output", help="per-point values: .ply (mesh, thickness, colours) or .csv")
    p.add_argument("--report", help="one-page HTML report")
    p.add_argument("--regions-csv", help="CSV, one row per thin or thick region")
    p.add_argument("--faces-csv", help="CSV, one row per B-rep face")
    p.add_argument("--json", help="statistics and regions as JSON")
    density = p.add_mutually_exclusive_group()
    density.add_argument("--samples", type=float, help="medial axis samples (as cadmedial compute)")
    density.add_argument("--spacing", type=float, help="medial axis sample spacing")
    p.add_argument("--quiet", action="store_true", help="no summary on stdout")
    return p


def _fmt(x):
    return "%.4g" % x


def summary(result, part):
    """The lines printed on stdout."""
    st, s = result.statistics, result.settings
    lines = ["cadmedial thickness: %s: %d surface points, thickness %s to %s (area-weighted mean "
             "%s) in %.3g s (medial axis %.3g s)" % (part, len(result.points), _fmt(st["min"]),
                                                     _fmt(st["max"]), _fmt(st["mean"]),
                                                     result.timings["total"],
                                                     result.timings["medial_axis"])]
    for regions, label, limit in ((result.thin_regions, "thinner than --min", s["min"]),
                                  (result.thick_regions, "thicker than --max", s["max"])):
        if limit is None:
            continue
        lines.append("  %d region(s) %s %s" % (len(regions), label, _fmt(limit)))
        for g in regions[:10]:
            lines.append("    %s %s at (%s) on %s, area %s" % (
                g["kind"], _fmt(g["extreme"]), ", ".join("%.6g" % x for x in g["at"]),
                " ".join(g["faces"][:6]) + (" ..." if len(g["faces"]) > 6 else ""),
                _fmt(g["area"])))
        if len(regions) > 10:
            lines.append("    ... and %d more" % (len(regions) - 10))
    lines.append("  %s" % ("PASS" if result.passed else "FAIL"))
    return "\n".join(lines)


def main(argv=None):
    args = _parser().parse_args(argv)
    from .. import _core
    from .analysis import check_settings, thickness
    from .writers import write_faces_csv, write_points, write_regions_csv
    try:
        check_settings(args.min, args.max, args.corners)
        if args.min is None and args.max is None:
            raise _core.InvalidInput("give --min, --max or both: the limits the part must meet")
        if args.output and os.path.splitext(args.output)[1].lower() not in (".ply", ".csv"):
            raise _core.InvalidInput("-o %s: the values are written as .ply or .csv" % args.output)
        if not os.path.isfile(args.part):
            raise _core.InvalidInput("%s: no such file" % args.part)
        samples = None if args.samples is None else args.samples
        result = thickness(args.part, min=args.min, max=args.max, corners=args.corners,
                           samples=samples, spacing=args.spacing)
        if args.output:
            write_points(result, args.output)
        if args.report:
            from .report import write_report
            write_report(result, args.report, os.path.basename(args.part))
        if args.regions_csv:
            write_regions_csv(result, args.regions_csv)
        if args.faces_csv:
            write_faces_csv(result, args.faces_csv)
        if args.json:
            with open(args.json, "w") as f:
                json.dump(result.to_dict(), f, indent=1)
    except (_core.InvalidInput, _core.GeometryError, OSError) as error:
        sys.stderr.write("cadmedial: error: %s\n" % str(error).replace("\n", " "))
        return BAD_INPUT
    except _core.Cancelled:
        sys.stderr.write("cadmedial: error: cancelled\n")
        return INTERNAL
    if not args.quiet:
        print(summary(result, args.part))
    return PASS if result.passed else OUT_OF_LIMITS


if __name__ == "__main__":
    try:
        code = main()
    except SystemExit:
        raise
    except Exception as error:  # noqa: BLE001 - the contract is one line and status 1
        sys.stderr.write("cadmedial: error: internal: %s: %s\n" % (type(error).__name__, error))
        code = INTERNAL
    sys.exit(code)
