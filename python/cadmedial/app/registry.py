"""What the GUI plugs into the document objects, and how to recognise them."""

import FreeCAD as App

# Proxy type name -> callable(view_object) that attaches a view provider. Filled by cadmedial.gui;
# empty headless.
view_provider_factories = {}


# None headless. The GUI sets a callable(text, work) that runs work(progress) in a thread while
# the GUI keeps answering, with a progress dialog and Stop, and returns its value (raises its
# error). progress(stage, fraction) -> bool is a cadmedial.compute progress callback.
background_runner = None


# None headless. The GUI sets a callable() that lets it draw and run its timers (no user input)
# between the slow property assignments of one result: each one then stalls it alone.
breathe = None


def let_gui_breathe():
    if App.GuiUp and breathe is not None:
        breathe()


def run_long(text, work):
    """work(progress) through the GUI's background_runner, or here and now (headless)."""
    if App.GuiUp and background_runner is not None:
        return background_runner(text, work)
    return work(None)


def attach_view_provider(obj, type_name):
    factory = view_provider_factories.get(type_name)
    if App.GuiUp and factory is not None and obj.ViewObject is not None:
        factory(obj.ViewObject)


def is_medial_axis(obj):
    """True for a MedialAxis document object."""
    return getattr(getattr(obj, "Proxy", None), "Type", None) == "MedialAxis"
