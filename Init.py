# FreeCAD runs this file at startup (GUI or not) for the MedialAxis addon.
# Installed (tools/install_addon.sh), the package `cadmedial` sits beside this file in the addon
# folder, which FreeCAD puts on sys.path. A source checkout used as the addon folder keeps it in
# python/: make that importable too. (FreeCAD gives this file no __file__, hence the search.)
import os
import sys

for _folder in list(sys.path):
    _package = os.path.join(_folder, "python", "cadmedial", "__init__.py")
    if os.path.isfile(os.path.join(_folder, "InitGui.py")) and os.path.isfile(_package):
        if os.path.join(_folder, "python") not in sys.path:
            sys.path.append(os.path.join(_folder, "python"))
        break
