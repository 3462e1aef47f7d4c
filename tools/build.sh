#!/usr/bin/env bash
# Configures and builds into build/ (the CLI, the Python module for /usr/bin/python3, the tests).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
