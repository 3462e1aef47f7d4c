"""The colour range of a MedialAxis object: which radii the two ends of the colour map stand for.

    AutoColorRange  True (default, and for documents saved before these properties): the range
                    is RadiusMin..RadiusMax, and ColorRangeMin/ColorRangeMax follow them at each
                    compute, so that they show what the colours span
    ColorRangeMin   setting either turns AutoColorRange off; radii outside the range get the
    ColorRangeMax   end colours. A range with ColorRangeMax <= ColorRangeMin spans the radii.

A new range recolours from the radii of the result at once (results.recolour, no engine run):
the three properties and RadiusColors are output properties, so that changing them does not
mark the object for a recompute. The colours are computed with numpy and handed over as packed
ints (colormap.packed_colors): 0.24 to 0.25 s for 930,288 vertices in the GUI, where FreeCAD's
mesh view then takes them in and redraws (docs/workbench.md, Colour range).
"""

from contextlib import contextmanager

from cadmedial.colormap import colors_of, packed_colors

GROUP = "Colours"
PROPERTIES = [
    ("App::PropertyBool", "AutoColorRange",
     "Colours span the radii (RadiusMin..RadiusMax); off: ColorRangeMin..ColorRangeMax"),
    ("App::PropertyLength", "ColorRangeMin",
     "Radius of the first (violet) colour; smaller radii get it too. Setting it turns "
     "AutoColorRange off"),
    ("App::PropertyLength", "ColorRangeMax",
     "Radius of the last (yellow) colour; larger radii get it too. Setting it turns "
     "AutoColorRange off"),
]
NAMES = [name for _kind, name, _doc in PROPERTIES]


def add_color_range(obj):
    """Adds the properties obj lacks (AutoColorRange on, the range the radii's) and makes them
    and RadiusColors output properties (before any value is set: a value set touches the object
    otherwise)."""
    with quiet(obj):
        for kind, name, doc in PROPERTIES:
            if name not in obj.PropertiesList:
                obj.addProperty(kind, name, GROUP, doc)
                obj.setPropertyStatus(name, "Output")
                if name == "AutoColorRange":
                    obj.AutoColorRange = True
        for name in NAMES + ["RadiusColors"]:
            if name in obj.PropertiesList:
                obj.setPropertyStatus(name, "Output")
        follow_radii(obj)


def color_range(obj):
    """(low, high): the radii of the colour map's ends for obj."""
    own = set_range(obj)
    return own if own is not None else (float(obj.RadiusMin.Value), float(obj.RadiusMax.Value))


def set_range(obj):
    """(low, high) set by hand, or None when the colours span the radii (AutoColorRange, or an
    empty range set)."""
    if "AutoColorRange" not in obj.PropertiesList or obj.AutoColorRange:
        return None
    low, high = float(obj.ColorRangeMin.Value), float(obj.ColorRangeMax.Value)
    return (low, high) if high > low else None


def follow_radii(obj):
    """With AutoColorRange, ColorRangeMin/ColorRangeMax := RadiusMin/RadiusMax."""
    if "AutoColorRange" in obj.PropertiesList and obj.AutoColorRange:
        with quiet(obj):
            obj.ColorRangeMin, obj.ColorRangeMax = obj.RadiusMin, obj.RadiusMax


def radius_colors(radius, low, high):
    """What RadiusColors takes for (V,) radii and a range: a list of V packed colours."""
    return packed_colors(colors_of(radius, low, high)).tolist()


def range_changed(obj, prop):
    """For the proxy's onChanged: whether obj's colours must be made again for its colour range
    after prop changed (setting ColorRangeMin/Max by hand turns AutoColorRange off here)."""
    if prop not in NAMES or getattr(obj.Proxy, "quiet_colors", False) or not _restored(obj):
        return False
    if prop != "AutoColorRange" and obj.AutoColorRange:
        with quiet(obj):
            obj.AutoColorRange = False  # a range typed in is meant to be used
    follow_radii(obj)
    return "VertexCount" in obj.PropertiesList and obj.VertexCount > 0


@contextmanager
def quiet(obj):
    """with quiet(obj): changes of the colour range's properties do not recolour (they are ours:
    the restore, a compute keeping ColorRangeMin/Max on the radii)."""
    proxy = obj.Proxy
    before = getattr(proxy, "quiet_colors", False)
    proxy.quiet_colors = True
    try:
        yield
    finally:
        proxy.quiet_colors = before


def _restored(obj):
    # While a document loads, properties arrive one by one: colours are loaded, not made.
    return "Restore" not in obj.State and not getattr(obj.Document, "Restoring", False)
