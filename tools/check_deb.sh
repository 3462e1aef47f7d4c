#!/usr/bin/env bash
# Builds the .deb (cpack in the build folder), checks what it holds and depends on, unpacks it
# into a scratch root (dpkg -x: no root rights, no chroot) and runs from there the program on the
# bundled example and the FreeCAD document tests (tests/freecad/test_app.py in freecadcmd) with
# only the unpacked Python package on the path.
#
#   tools/check_deb.sh [BUILD_DIR]      (default: build; it must be configured and built)
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
build=$(realpath "${1:-$repo/build}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

(cd "$build" && cpack -G DEB -B "$work/pkg" >/dev/null)
deb=$(ls "$work"/pkg/freecad-medialaxis_*.deb)
echo "built $(basename "$deb")"
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
for needed in freecad libocct-foundation python3-numpy; do
  case "$depends" in *"$needed"*) ;; *) echo "check_deb.sh: Depends lacks $needed" >&2; exit 1 ;; esac
done
contents=$(dpkg-deb -c "$deb" | awk '{print $6}')
for path in ./usr/bin/cadmedial ./usr/share/freecad/Mod/MedialAxis/InitGui.py \
            ./usr/share/freecad/Mod/MedialAxis/Init.py ./usr/lib/python3/dist-packages/cadmedial/app/medial_axis.py \
            ./usr/lib/python3/dist-packages/cadmedial/Resources/icons/MedialAxis_Create.svg; do
  grep -qx "$path" <<<"$contents" || { echo "check_deb.sh: $path missing from the package" >&2; exit 1; }
done
grep -q "dist-packages/cadmedial/_core.*\.so$" <<<"$contents" || { echo "check_deb.sh: no _core*.so" >&2; exit 1; }
if grep -q -e "__pycache__" -e "/tests/" -e "gtest" <<<"$contents"; then
  echo "check_deb.sh: the package holds test or cache files" >&2; exit 1
fi

root="$work/root"
dpkg -x "$deb" "$root"
"$root/usr/bin/cadmedial" compute "$repo/examples/data/nist_ftc_11_asme1_rb.stp" -o "$work/ftc11.ply" --samples 5000 --quiet
test -s "$work/ftc11.ply" || { echo "check_deb.sh: the program wrote nothing" >&2; exit 1; }
echo "the packaged program wrote $(stat -c %s "$work/ftc11.ply") bytes of PLY"

# The document tests, importing cadmedial from the unpacked package only.
env -u CADMEDIAL_CORE_DIR PYTHONDONTWRITEBYTECODE=1 \
  PYTHONPATH="$root/usr/lib/python3/dist-packages:$repo/tests/freecad" \
  CADMEDIAL_EXPECT_PACKAGE="$root/usr/lib/python3/dist-packages/cadmedial" \
  CADMEDIAL_PYTEST_ARGS="[\"$repo/tests/freecad/test_app.py\", \"-q\", \"-x\"]" \
  freecadcmd "$repo/tests/freecad/run_pytest.py"
echo "check_deb.sh: ok"
