"""The public entry points: compute, plan_sampling, load, read_shape."""

import json
import math
import os
from typing import NamedTuple

import numpy as np

from . import _core
from .result import MedialAxisResult


class SamplingPlan(NamedTuple):
    """The sample spacing that the parameters give for a shape, and about how many samples."""
    spacing: float
    estimated_samples: int


def _is_brep_text(text):
    # Shape.exportBrepToString() starts with a blank line, then this header; DBRep's with its own.
    head = text.lstrip()[:64]
    return head.startswith("CASCADE Topology") or head.startswith("DBRep_DrawableShape")


def read_shape(source):
    """The shape of ``source`` as a ``cadmedial._core.Shape``.

    ``source`` is a path (str or os.PathLike) to a STEP, IGES or BREP file, BREP text (str),
    an object with ``exportBrepToString()`` (a FreeCAD ``Part.Shape``), or a ``_core.Shape``.
    Raises InvalidInput when the file or text cannot be read.
    """
    if isinstance(source, _core.Shape):
        return source
    if hasattr(source, "exportBrepToString"):
        return _core.read_brep_string(source.exportBrepToString())
    if isinstance(source, os.PathLike):
        return _core.read_shape_file(os.fspath(source))
    if isinstance(source, bytes):
        source = source.decode("utf-8", errors="replace")
    if not isinstance(source, str):
        raise TypeError("source must be a file path, BREP text or a shape, got "
                        + type(source).__name__)
    if _is_brep_text(source):
        return _core.read_brep_string(source)
    return _core.read_shape_file(source)


def _number(name, value):
    """float(value), or InvalidInput naming the parameter (float() would raise a bare ValueError
    or TypeError that does not say which one)."""
    if isinstance(value, bool):
        raise _core.InvalidInput("%s must be a number, got %r" % (name, value))
    try:
        return float(value)
    except (TypeError, ValueError, OverflowError):
        raise _core.InvalidInput("%s must be a number, got %r" % (name, value)) from None


# The engine's own limit is 2e7 samples; past the range of a C long long the binding could not
# even pass the number on.
_MAX_SAMPLES = 2 ** 62


def _density(spacing, samples):
    # None means "not given"; the engine takes 0 for that.
    if samples is not None:
        count = _number("samples", samples)
        if not math.isfinite(count) or count != int(count):
            raise _core.InvalidInput("samples must be a whole number, got %r" % (samples,))
        if abs(int(count)) > _MAX_SAMPLES:
            raise _core.InvalidInput("samples must be at most 20000000, got %r" % (samples,))
        if count <= 0:
            raise _core.InvalidInput("samples must be > 0, got %r" % (samples,))
        samples = int(count)
    if spacing is not None:
        spacing = _number("spacing", spacing)
        # The engine reads 0 as "derive from samples": an explicit 0 is a mistake, say so.
        if not spacing > 0:
            raise _core.InvalidInput("spacing must be > 0, got %r" % (spacing,))
    return (0.0 if spacing is None else spacing,
            0 if samples is None else samples)


def _min_feature(size):
    """SamplingParams::min_feature from compute()'s argument (None: no minimum)."""
    return 0.0 if size is None else _number("min_feature", size)


def plan_sampling(source, spacing=None, samples=None, min_feature=None):
    """SamplingPlan(spacing, estimated_samples) for ``source`` (see read_shape) and the density
    parameters, without computing anything else: fast enough for a live preview."""
    spacing, samples = _density(spacing, samples)
    return SamplingPlan(*_core.plan_sampling(read_shape(source), spacing, samples,
                                             _min_feature(min_feature)))


def _flag(name, value):
    """value if it is a bool (numpy's too), else InvalidInput naming the parameter: a string such
    as "no" would otherwise be read as true."""
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    raise _core.InvalidInput("%s must be True or False, got %r" % (name, value))


def refines_by_default(spacing, samples):
    """Whether compute() refines for the topology when its ``refine`` is None: only when no density
    is given (None for both), as the program does without --spacing or --samples."""
    return spacing is None and samples is None


def compute(source, spacing=None, samples=None, theta=5.0, rho=8.0, progress=None,
            plain_medial=False, adapt=True, refine=None, min_feature=None, simplify=None):
    """The inner medial axis of every solid of ``source``.

    source    a STEP/IGES/BREP file path, BREP text, a FreeCAD Part.Shape or a _core.Shape
    spacing   sample spacing in model units; None derives it from ``samples``
    samples   approximate total number of boundary samples; None with no spacing = 20000
    theta     Angle condition threshold in degrees, in (0, 90) (section 3 of the paper)
    rho       Ratio condition threshold, > 0
    progress  None or callable(stage: str, fraction: float); returning False (any falsy value
              but None) cancels and raises Cancelled; an exception it raises cancels the work
              and propagates unchanged. It is called with the GIL held.
    plain_medial  True runs the paper's plain MEDIAL (section 3: umbrellas from the poles, no
              convex-edge or corner completion) instead of CAD_MEDIAL, on the same samples, for
              comparison. Like the program's --plain-medial it leaves theta as given: the paper
              uses theta=22.5 for MEDIAL.
    adapt     True (default) samples walls thinner than the spacing allows more densely, down to
              a quarter of the spacing, or to what the thinnest wall needs (at most a 32nd)
              where that takes at most 3 times the samples (a second sampling pass); False,
              like the program's --uniform, keeps one spacing everywhere.
    refine    True samples a solid again with 2.5 times the samples, at most twice, where its
              axis comes out with an Euler characteristic other than the solid's (holes or extra
              loops: too few samples for its walls); like the program's --refine. None (default)
              refines only when neither spacing nor samples is given: a density you chose is kept.
              Each solid's stats say how often it was refined ("refinements") and at what
              spacing ("spacing").
    min_feature  None (default) or a size in model units: walls thinner than it are not
              sampled finer than it needs ("ignore features below 0.01 mm"); a warning names the
              thinnest of them and where it is. Like the program's --min-feature.

    simplify  None (default) or a tolerance (model units, or "P%" of the bounding-box diagonal):
              returns the compact mesh (docs/compact.md), its vertices first moved onto the
              exact axis of the B-rep; stats gain "snap" and "simplify". Like the program's
              --simplify.

    Returns a MedialAxisResult. Raises InvalidInput (bad file, shape or parameter; also a
    ValueError), GeometryError (a stage failed; also a RuntimeError) or Cancelled.
    """
    shape = read_shape(source)
    refine = refines_by_default(spacing, samples) if refine is None else _flag("refine", refine)
    spacing, samples = _density(spacing, samples)
    plain_medial = _flag("plain_medial", plain_medial)
    adapt = _flag("adapt", adapt)
    from .compact import parse_tolerance
    tolerance, relative = parse_tolerance(simplify) if simplify is not None else (0.0, False)
    mesh, stats = _core.compute_medial_axis(shape, spacing, samples, _number("theta", theta),
                                            _number("rho", rho), progress, plain_medial, adapt,
                                            refine, min_feature=_min_feature(min_feature),
                                            simplify=tolerance, simplify_relative=relative)
    return MedialAxisResult(mesh, json.loads(stats))


def load(path):
    """A MedialAxisResult read from a .ply, .obj or .ma file (stats are empty)."""
    return MedialAxisResult(_core.read_medial_mesh(os.fspath(path)), {})
