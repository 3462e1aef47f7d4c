#!/usr/bin/env bash
# Fresh machine to green: installs the packages, builds, and runs every test (C++ through ctest,
# pytest on the Python package, FreeCAD headless and GUI under Xvfb).
set -euo pipefail
cd "$(dirname "$0")/.."
[ "${CADMEDIAL_SKIP_SETUP:-0}" = 1 ] || bash tools/setup.sh
bash tools/build.sh
ctest --test-dir build --output-on-failure -j2
