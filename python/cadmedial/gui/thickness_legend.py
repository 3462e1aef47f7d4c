"""The wall thickness legend: the radius legend's widget (legend.py) titled "Wall thickness", in
the top-left corner of each 3D view (the radius legend keeps the bottom left; the axis triad and
navigation cube are on the right), with ticks in mm over each visible WallThickness object's
colour range and the key of its thin / thick / left-out colours."""

from PySide2 import QtCore

from cadmedial.app.thickness_object import (EXCLUDED_COLOUR, THICK_COLOUR, THIN_COLOUR,
                                            is_wall_thickness, legend_range)

from . import legend

OBJECT_NAME = "cadmedial_thickness_legend"


def _swatch(rgb, text):
    r, g, b = (int(255 * c + 0.5) for c in rgb)
    return '<span style="color:#%02x%02x%02x">&#9632;</span> %s' % (r, g, b, text)


def key_of(obj):
    """The colour key under the bar, as rich text."""
    lines = []
    if obj.MinWall.Value:
        lines.append(_swatch(THIN_COLOUR, "thinner than %.4g mm" % obj.MinWall.Value))
    if obj.MaxWall.Value:
        lines.append(_swatch(THICK_COLOUR, "thicker than %.4g mm" % obj.MaxWall.Value))
    if obj.Corners == "exclude":
        lines.append(_swatch(EXCLUDED_COLOUR, "beside convex edges, not counted"))
    return "<br>".join(lines)


def _make(widget):
    return legend.RadiusLegend(widget, title="Wall thickness", name=OBJECT_NAME, top=True)


def refresh(doc, leaving=None):
    """Shows the colour ranges of doc's visible, analysed WallThickness objects (but `leaving`)
    over its 3D views; hides the legend when there is none. Returns whether one shows."""
    shown = [o for o in (doc.Objects if doc is not None else [])
             if o is not leaving and is_wall_thickness(o) and o.Values
             and o.ViewObject is not None and o.ViewObject.Visibility]
    entries = [(o.Label,) + legend_range(o) for o in shown]
    notes = key_of(shown[0]) if len(shown) == 1 else ""
    return legend.show_on_views(doc, entries, _make, OBJECT_NAME, notes)


def legend_on(doc):
    """The thickness legend widget over doc's first 3D view that has one, or None."""
    return legend.first_legend(doc, OBJECT_NAME)


def refresh_later(doc, tries=20):
    # After the current recompute or property change; a document being opened gets its 3D view
    # after its objects: try again a few times.
    def run():
        try:
            if not refresh(doc) and tries > 0 and any(
                    is_wall_thickness(o) and o.Values for o in doc.Objects):
                refresh_later(doc, tries - 1)
        except Exception:  # the document was closed in between: nothing to show
            pass
    QtCore.QTimer.singleShot(0 if tries == 20 else 100, run)
