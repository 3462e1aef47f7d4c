"""What the GUI plugs into the document objects, and how to recognise them."""

import FreeCAD as App

# Proxy type name -> callable(view_object) that attaches a view provider. Filled by cadmedial.gui;
# empty headless.
view_provider_factories = {}


def attach_view_provider(obj, type_name):
    factory = view_provider_factories.get(type_name)
    if App.GuiUp and factory is not None and obj.ViewObject is not None:
        factory(obj.ViewObject)


def is_medial_axis(obj):
    """True for a MedialAxis document object."""
    return getattr(getattr(obj, "Proxy", None), "Type", None) == "MedialAxis"
