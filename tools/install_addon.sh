#!/usr/bin/env bash
# Installs the MedialAxis addon where FreeCAD 0.20 finds it: ~/.local/share/FreeCAD/Mod/MedialAxis
# (FreeCAD's -M option crashes on Debian's 0.20: the addon must be in a Mod folder).
#
#   tools/install_addon.sh [--build-dir DIR] [--dest DIR]
#
# --build-dir  the CMake build folder holding python/cadmedial/_core*.so (default: build); it is
#              built first if the module is missing (cmake -S . -B DIR && cmake --build DIR -j2)
# --dest       the addon folder to (re)create (default: $HOME/.local/share/FreeCAD/Mod/MedialAxis)
#
# Layout made: Init.py InitGui.py package.xml Resources/icons/ cadmedial/ (with _core*.so), and
# bin/cadmedial, the program the batch dialog's workers run on each part, with lib/cadmedial/python
# pointing back at the addon (where the program looks for the package of `cadmedial thickness`).
set -euo pipefail

repo=$(cd "$(dirname "$0")/.." && pwd)
build="$repo/build"
dest="${HOME}/.local/share/FreeCAD/Mod/MedialAxis"
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) build=$(realpath -m "$2"); shift 2 ;;
    --dest) dest=$(realpath -m "$2"); shift 2 ;;
    -h|--help) sed -n '2,12p' "$0"; exit 0 ;;
    *) echo "install_addon.sh: unknown argument '$1' (try --help)" >&2; exit 2 ;;
  esac
done

module() { find "$build/python/cadmedial" -maxdepth 1 -name '_core*.so' 2>/dev/null | head -n 1; }
if [ -z "$(module)" ] || [ ! -x "$build/cadmedial" ]; then
  echo "Building the module and the program in $build ..."
  cmake -S "$repo" -B "$build" >/dev/null
  cmake --build "$build" -j2 --target _core cadmedial
fi
so=$(module)
if [ -z "$so" ]; then
  echo "install_addon.sh: no _core*.so in $build/python/cadmedial" >&2
  exit 2
fi

rm -rf "$dest"
mkdir -p "$dest/Resources/icons"
cp "$repo/Init.py" "$repo/InitGui.py" "$repo/package.xml" "$dest/"
cp "$repo"/Resources/icons/*.svg "$dest/Resources/icons/"
# The package without caches, then the compiled module beside it.
(cd "$repo/python" && find cadmedial \( -name '*.py' -o -name '*.pyi' -o -name 'py.typed' \) -print0 |
  xargs -0 -I{} install -D -m 644 {} "$dest/{}")
install -m 755 "$so" "$dest/cadmedial/"
install -D -m 755 "$build/cadmedial" "$dest/bin/cadmedial"
mkdir -p "$dest/lib/cadmedial"
ln -s ../.. "$dest/lib/cadmedial/python"
echo "Installed the MedialAxis addon in $dest"
