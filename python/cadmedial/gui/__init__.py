"""The workbench GUI: commands, task panel, view provider, radius legend. Imports FreeCADGui.

Importing this package registers the commands (MedialAxis_Create, MedialAxis_Export,
MedialAxis_MakeShape, MedialAxis_WallThickness, MedialAxis_Batch) and plugs the view providers
into cadmedial.app, so that cadmedial.app.make_medial_axis() in the Python console gets the
coloured view too.
"""

from cadmedial.app import registry, view_provider_factories

from . import commands, picking
from .busy import breathe, run_with_progress
from .view_provider import ViewProviderMedialAxis, ViewProviderMedialShape

view_provider_factories["MedialAxis"] = ViewProviderMedialAxis
view_provider_factories["MedialShape"] = ViewProviderMedialShape
registry.background_runner = run_with_progress
registry.breathe = breathe
commands.register()
picking.install()
from . import thickness_command  # noqa: E402
thickness_command.register()
from . import batch_command  # noqa: E402
batch_command.register()

__all__ = ["ViewProviderMedialAxis", "ViewProviderMedialShape", "commands"]
