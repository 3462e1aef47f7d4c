"""The Simplify property of a MedialAxis object: the compact mesh it shows (issue 35, item 2).

    Simplify    percent of the solid's bounding-box diagonal (0.2 for new objects): the Mesh,
                RadiusColors and ResultFile hold cadmedial.simplify(full, "0.2%", source): the
                full axis's vertices moved onto the source's exact axis, then simplified so that
                every ball of it lies within the tolerance (|dc| + |dr|), with its Euler
                characteristic and components; 0: the
                full axis (what a document saved before the property holds, and keeps)
    Simplified  read-only: what the last compute gave ("1,922 faces from 54,436, every ball
                within 0.785 mm"), empty for the full axis

The default, measured on the Y-rod mount and NIST CTC 01 at their automatic density
(docs/workbench.md, Compact mesh): 0.2 % keeps 1/14 and 1/10 of the polygons (1/36 and 1/26 of
the triangles) in files 31 and 21 times smaller, which open 19 and 13 times faster; 0.5 % halves
the faces again for 2.5 times the error and is no faster, 1 % takes twice as long.
"""

import cadmedial

INPUTS = "Medial Axis"
DEFAULT_PERCENT = 0.2
MAX_PERCENT = 50.0
STEP = 0.1
SIMPLIFY_DOC = ("Compact mesh: tolerance in % of the solid's bounding-box diagonal. The mesh keeps "
                "vertices of the full axis (exact position and radius) and every ball of the full "
                "axis within this distance (centre plus radius difference), with the same "
                "topology. 0: the full axis. Changing it redoes only the simplification while the "
                "full axis is in memory (after reopening a document the axis is computed again)")
SIMPLIFIED_DOC = "What Simplify gave: faces kept of the full axis's, and the largest ball error"


def add_simplify(obj, percent):
    """Adds the Simplify property to obj (set to percent) if it lacks it, and gives it its range
    (a document keeps the value of a constrained float, not its range)."""
    if "Simplify" not in obj.PropertiesList:
        obj.addProperty("App::PropertyFloatConstraint", "Simplify", INPUTS, SIMPLIFY_DOC)
    else:
        percent = float(obj.Simplify)
    touched = "Touched" in obj.State
    obj.Simplify = (min(max(float(percent), 0.0), MAX_PERCENT), 0.0, MAX_PERCENT, STEP)
    if not touched:
        obj.purgeTouched()  # the range is not a change: reopening needs no recompute


def simplify_of(obj):
    """obj's Simplify in percent (0: the full axis; 0 for an object without the property)."""
    if "Simplify" not in obj.PropertiesList:
        return 0.0
    percent = float(obj.Simplify)
    if not 0.0 <= percent <= MAX_PERCENT:
        raise cadmedial.InvalidInput("Simplify must be between 0 and %g (%% of the diagonal), got %g"
                                     % (MAX_PERCENT, percent))
    return percent


def compact_of(full, percent, source=None, progress=None):
    """The MedialAxisResult to show: cadmedial.simplify(full, "percent%", source), its vertices
    first moved onto the exact axis of source when given (as compute(simplify=) does), or full
    itself for 0 (and for an axis without faces: nothing to simplify)."""
    if not percent or not full.num_faces:
        return full
    return cadmedial.simplify(full, "%r%%" % float(percent), source=source, progress=progress)


def summary(result):
    """The Simplified line of a result: "1,922 faces from 54,436, every ball within 0.785 mm"
    for a compact one, "" for a full one."""
    figures = (result.stats or {}).get("simplify")
    if not figures:
        return ""
    return "{:,} faces from {:,}, every ball within {:.4g} mm (tolerance {:.4g} mm)".format(
        int(figures["faces_after"]), int(figures["faces_before"]), float(figures["max_error"]),
        float(figures["tolerance"]))


def simplify_seconds(result):
    """Seconds the simplification of result took (0 for a full one)."""
    return float(((result.stats or {}).get("simplify") or {}).get("seconds", 0.0))
