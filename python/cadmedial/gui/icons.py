"""Where the SVG icons are, in an installed addon (Mod/MedialAxis/Resources/icons, beside the
package), in the package itself (cadmedial/Resources/icons, as `cmake --install` puts it) and in a
source checkout (Resources/icons at the repository root, python/ beside it)."""

import os

_PACKAGE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def icon_path(name):
    """Absolute path of Resources/icons/<name>; the first candidate when none exists."""
    candidates = [os.path.join(_PACKAGE, os.pardir, "Resources", "icons", name),
                  os.path.join(_PACKAGE, "Resources", "icons", name),  # the .deb's package
                  os.path.join(_PACKAGE, os.pardir, os.pardir, "Resources", "icons", name)]
    for path in candidates:
        if os.path.isfile(path):
            return os.path.normpath(path)
    return os.path.normpath(candidates[0])
