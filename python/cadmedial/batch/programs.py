"""Finding the cadmedial program the per-part tasks run, installed or in a build tree."""

import os
import shutil

from .._core import InvalidInput

_PACKAGE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))  # .../cadmedial


def _candidates():
    # 1. The program that launched this batch (src/cli's dispatcher sets it), or the user's choice.
    yield os.environ.get("CADMEDIAL_CLI", "")
    # 2. Installed beside this package: <prefix>/lib/cadmedial/python/cadmedial -> <prefix>/bin.
    yield os.path.normpath(os.path.join(_PACKAGE, os.pardir, os.pardir, os.pardir, os.pardir, "bin", "cadmedial"))
    # 3. A source checkout: <repo>/python/cadmedial -> <repo>/build/cadmedial.
    yield os.path.normpath(os.path.join(_PACKAGE, os.pardir, os.pardir, "build", "cadmedial"))
    # 4. The FreeCAD addon (tools/install_addon.sh): Mod/MedialAxis/cadmedial -> Mod/MedialAxis/bin.
    yield os.path.join(os.path.dirname(_PACKAGE), "bin", "cadmedial")
    # 5. Whatever PATH offers.
    yield shutil.which("cadmedial") or ""


def is_program(path):
    return bool(path) and os.path.isfile(path) and os.access(path, os.X_OK)


def find_cli(preferred=None):
    """The path of the cadmedial program: ``preferred`` if it is one, else the first found."""
    if preferred:
        if is_program(preferred):
            return os.path.abspath(preferred)
        raise InvalidInput("cli: %s is not an executable program" % preferred)
    for path in _candidates():
        if is_program(path):
            return os.path.abspath(path)
    raise InvalidInput("cannot find the cadmedial program (set CADMEDIAL_CLI, or build it: tools/build.sh)")
