"""Checks the shortcuts of bench/measures.py against the slow ways they replace, on real output.

    /usr/bin/python3 bench/check_measures.py PART [PART ...]

(PYTHONPATH=python, CADMEDIAL_CORE_DIR=build/python/cadmedial.) PART as in results_part.py. Per
part, one line per check:
  classify  _core.classify_points against FreeCAD's Shape.isInside on 600 points (300 output
            vertices, 300 random points around them): agreement and seconds of each;
  bounded   signed_distance_to_balls with the normal-direction candidates searched within d of
            y + d n against the unbounded search: seconds, and the maxima the page reports;
  surface   side_from_surface against the classifier on 3,000 points (1,500 vertices, 1,500
            around them): how many it settles, disagreements, seconds.
"""
import sys
import time

import numpy as np

sys.path.append("/usr/lib/freecad/lib")
sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))

import FreeCAD  # noqa: E402
import Part  # noqa: E402

import cadmedial  # noqa: E402
import measures  # noqa: E402
import results_part  # noqa: E402


def main():
    for name in sys.argv[1:]:
        source, shape = results_part.load(name)
        r = cadmedial.compute(source, samples=20000)
        V, R, h = np.asarray(r.vertices), np.asarray(r.radius), r.stats["spacing"]
        solids = shape.Solids
        comp = Part.makeCompound(solids)
        diag = comp.BoundBox.DiagonalLength
        tol = 1e-6 * diag
        rng = np.random.default_rng(7)

        X = np.vstack([V[rng.choice(len(V), 300, replace=False)],
                       V[rng.choice(len(V), 300)] + rng.normal(0, 0.03 * diag, (300, 3))])
        t = time.time()
        slow = np.array([any(s.isInside(FreeCAD.Vector(*x), tol, True) for s in solids) for x in X])
        t_slow = time.time() - t
        t = time.time()
        fast = np.logical_or.reduce([st > 0 for st in measures.classify(solids, X, tol)])
        t_fast = time.time() - t
        print("%s classify: %d of %d agree; isInside %.2f s, classify_points %.2f s"
              % (name, int((slow == fast).sum()), len(X), t_slow, t_fast), flush=True)

        # The surface sample of reconstruction_error (same seed).
        P, T, oriented = measures.tessellate(comp, diag)
        Y, area, N = measures.sample_triangles(P, T, 30_000, np.random.default_rng(0), normals=True)
        spacing = np.sqrt(area / len(Y))
        N_out = N if oriented else None
        out = []
        for bounded in (False, True):
            t = time.time()
            e = measures.signed_distance_to_balls(Y, N, V, R, h, bounded=bounded)
            out.append((time.time() - t, 100 * max(e.max(), 0) / diag, 100 * np.abs(e).max() / diag,
                        100 * max(np.percentile(e, 99), 0) / diag, e))
        print("%s bounded: unbounded %.2f s, bounded %.2f s; uncovered / |e| max / p99 %% of diagonal "
              "%.4f %.4f %.4f -> %.4f %.4f %.4f; %d of %d points changed"
              % (name, out[0][0], out[1][0], *out[0][1:4], *out[1][1:4],
                 int((out[0][4] != out[1][4]).sum()), len(Y)), flush=True)

        if N_out is None or len(solids) != 1:
            print("%s surface: not used (%s)" % (name, "faces not oriented" if N_out is None
                                                 else "%d solids" % len(solids)), flush=True)
            continue
        X = np.vstack([V[rng.choice(len(V), 1500, replace=False)],
                       V[rng.choice(len(V), 1500)] + rng.normal(0, 0.03 * diag, (1500, 3))])
        t = time.time()
        exact = measures.classify(solids, X, tol)[0] > 0
        t_exact = time.time() - t
        t = time.time()
        side = measures.side_from_surface(X, Y, N_out, spacing)
        t_side = time.time() - t
        settled = side >= 0
        print("%s surface: settles %d of %d, %d disagree with the classifier; classifier %.2f s, "
              "surface %.2f s" % (name, int(settled.sum()), len(X), int((side[settled] != exact[settled]).sum()),
                                  t_exact, t_side), flush=True)


if __name__ == "__main__":
    main()
