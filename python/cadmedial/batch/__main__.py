"""The command line of `cadmedial batch` (src/cli hands `batch` over to this):

    python3 -m cadmedial.batch INPUTS... -o OUTDIR [--jobs N] [--scheduler ADDRESS] [--timeout S]
        [--memory GB] [--force] [--format ply|obj|ma] [compute options] [--thickness --min T]

Exit status: 0 every part ok; 3 the batch ran but some parts failed (summary.csv says which and
why); 2 bad arguments or inputs; 1 an internal error. Errors are one 'cadmedial: error:' line.
"""

import argparse
import sys

from .run import DEFAULT_MEMORY, DEFAULT_TIMEOUT, FORMATS, batch

EXIT_SOME_FAILED = 3


class _Parser(argparse.ArgumentParser):
    def error(self, message):
        # One line in the program's own style, and its status for bad arguments.
        sys.stderr.write("cadmedial: error: batch: %s (try 'cadmedial batch --help')\n" % message)
        sys.exit(2)


def parser():
    p = _Parser(prog="cadmedial batch", description=(
        "Computes the medial axis of many parts on Dask: locally (one worker per core) or on a "
        "running cluster (--scheduler). Resumes: parts whose outputs are newer than their input are "
        "skipped."))
    p.add_argument("inputs", nargs="+", metavar="INPUT",
                   help="CAD file (STEP, IGES, BREP, FCStd), folder searched for them, or list file "
                        "(.txt/.lst/.list: one path a line, '#' comments)")
    p.add_argument("-o", "--output", required=True, metavar="OUTDIR", help="output folder")
    p.add_argument("--jobs", type=int, metavar="N", help="local workers (default: one per core)")
    p.add_argument("--scheduler", metavar="ADDRESS",
                   help="submit to a running Dask scheduler (tcp://host:8786) instead of a local cluster")
    p.add_argument("--timeout", type=float, default=DEFAULT_TIMEOUT, metavar="S",
                   help="wall seconds per part (default %(default)g; 0: none)")
    p.add_argument("--memory", type=float, default=DEFAULT_MEMORY, metavar="GB",
                   help="address-space limit per part in GB (default %(default)g; 0: none)")
    p.add_argument("--force", action="store_true", help="redo parts that are already done")
    p.add_argument("--format", choices=FORMATS, default="ply", help="mesh format (default ply)")
    p.add_argument("--quiet", action="store_true", help="no progress or summary on stderr")
    c = p.add_argument_group("compute options (as cadmedial compute)")
    c.add_argument("--spacing", type=float, metavar="S")
    c.add_argument("--samples", type=float, metavar="N")
    c.add_argument("--theta", type=float, metavar="DEG")
    c.add_argument("--rho", type=float, metavar="R")
    c.add_argument("--refine", action="store_true")
    c.add_argument("--uniform", action="store_true")
    c.add_argument("--plain-medial", action="store_true")
    c.add_argument("--min-feature", type=float, metavar="F")
    t = p.add_argument_group("wall thickness (issue 34; needs the cadmedial.thickness module)")
    t.add_argument("--thickness", action="store_true", help="also analyse each part's wall thickness")
    t.add_argument("--min", type=float, metavar="T", help="minimum wall (with --thickness)")
    t.add_argument("--max", type=float, metavar="T", help="maximum wall (with --thickness)")
    return p


def main(argv=None):
    args = parser().parse_args(argv)
    if (args.min is not None or args.max is not None) and not args.thickness:
        parser().error("--min and --max go with --thickness")
    from .. import Error
    try:
        result = batch(args.inputs, args.output, jobs=args.jobs, scheduler=args.scheduler,
                       timeout=args.timeout, memory=args.memory, force=args.force, format=args.format,
                       spacing=args.spacing, samples=args.samples, theta=args.theta, rho=args.rho,
                       refine=args.refine, uniform=args.uniform, plain_medial=args.plain_medial,
                       min_feature=args.min_feature,
                       thickness={"min": args.min, "max": args.max} if args.thickness else None,
                       progress=not args.quiet)
    except Error as e:  # InvalidInput and its kin: bad arguments or inputs
        sys.stderr.write("cadmedial: error: batch: %s\n" % str(e).replace("\n", " "))
        return 2
    except KeyboardInterrupt:
        sys.stderr.write("cadmedial: error: batch: interrupted; finished parts are kept, rerun to resume\n")
        return 130
    return 0 if set(result.counts) <= {"ok"} else EXIT_SOME_FAILED


if __name__ == "__main__":
    try:
        sys.exit(main())
    except SystemExit:
        raise
    except BaseException as e:  # noqa: BLE001 - one line, as the program promises
        sys.stderr.write("cadmedial: error: batch: internal error: %s: %s\n" % (type(e).__name__, e))
        sys.exit(1)
