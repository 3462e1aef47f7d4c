"""The compact medial mesh (issue 35, item 2): the axis simplified within a tolerance.

    import cadmedial
    full = cadmedial.compute("part.step")
    small = cadmedial.simplify(full, "0.5%")    # or a length in model units: simplify(full, 0.2)
    small.stats["simplify"]                     # faces_before/after, max_error, euler_before/after, ...

compute(..., simplify=) first moves the Voronoi vertices onto the exact axis of the B-rep
(snap_to_axis); simplify(result, ...) works on the result as it is. Every vertex of the compact
mesh is then a vertex of that (snapped or given) mesh, with its radius; every
ball of the full axis lies within the tolerance of the compact mesh's ball at the nearest point
(|dc| + |dr|), the compact mesh within it of the full one, with the same components and Euler
characteristic; borders (rims) and seams keep their kind and their ends. See docs/compact.md.
"""

import numpy as np

from . import _core
from .result import MedialAxisResult


def parse_tolerance(tolerance):
    """(value, relative): a number in model units, or "P%" as a share of the diagonal."""
    if isinstance(tolerance, str):
        text = tolerance.strip()
        if not text.endswith("%"):
            raise ValueError("tolerance must be a number or a share like '0.1%%', got %r" % (tolerance,))
        try:
            share = float(text[:-1]) / 100.0
        except ValueError:
            raise ValueError("tolerance must be a number or a share like '0.1%%', got %r" % (tolerance,))
        if not 0 < share < 1:
            raise ValueError("tolerance must be between 0%% and 100%%, got %r" % (tolerance,))
        return share, True
    value = float(tolerance)
    if not (value >= 0 and np.isfinite(value)):
        raise ValueError("tolerance must be a finite number >= 0, got %r" % (tolerance,))
    return value, False


def tolerance_of(result, tolerance):
    """The tolerance in model units: a number as given, or "P%" of the solid's bounding-box
    diagonal (stats["diagonal"]; for a loaded file, the axis's own)."""
    value, relative = parse_tolerance(tolerance)
    if not relative:
        return value
    diagonal = (result.stats or {}).get("diagonal")
    if not diagonal:
        v = np.asarray(result.vertices)
        diagonal = float(np.linalg.norm(v.max(axis=0) - v.min(axis=0))) if len(v) else 0.0
    return value * float(diagonal)


def simplify(result, tolerance, source=None, progress=None):
    """The compact MedialAxisResult of ``result`` within ``tolerance`` (model units or "P%").

    source    None, or the shape ``result`` was computed from (a path, BREP text, a Part.Shape
              or a _core.Shape): the vertices are then first moved onto its exact medial axis,
              as compute(..., simplify=) and the program's --simplify do (stats["snap"]), within
              half the result's spacing. Without it the Voronoi vertices' zig-zag about each
              sheet stays within the tolerance, and fewer of them go.
    progress  None or callable(stage, fraction) as for compute(); returning False cancels
              (raises Cancelled).

    Its faces are triangles, each with the kind and solid of the polygon it lies in; its stats
    are the full result's with "simplify" added (tolerance, max_error, max_containment,
    vertices/faces/edges before and after, euler and components before and after, seconds) and
    "vertices", "faces" and "edges" the compact mesh's.
    """
    from .api import read_shape
    tol = tolerance_of(result, tolerance)
    stats = dict(result.stats or {})
    mesh = result.mesh
    if source is not None:
        spacing = stats.get("spacing")
        if not spacing:
            raise ValueError("simplify(source=...) needs the result's stats['spacing'] (a computed result)")
        mesh, snapped = _core.snap_to_axis(read_shape(source), mesh, 0.5 * float(spacing))
        stats["snap"] = dict(snapped)
    mesh, figures = _core.simplify_mesh(mesh, tol, progress)
    stats["simplify"] = dict(figures)
    stats["vertices"], stats["faces"], stats["edges"] = mesh.num_vertices, mesh.num_faces, mesh.num_edges
    return MedialAxisResult(mesh, stats)
