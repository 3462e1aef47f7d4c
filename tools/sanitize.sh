#!/usr/bin/env bash
# Builds the C++ engine, CLI and C++ tests with AddressSanitizer + UndefinedBehaviorSanitizer in
# build-asan/ (CADMEDIAL_SANITIZE=ON; no Python module: under ASan it needs LD_PRELOAD of libasan
# into the interpreter) and runs the C++ ctest suite there. Not part of CI (.ci/run): the build
# alone takes longer than the whole normal test run. Result of the last run: docs/hardening.md.
#   bash tools/sanitize.sh [ctest args...]      e.g. bash tools/sanitize.sh -R CliRefusal
set -euo pipefail
cd "$(dirname "$0")/.."
JOBS=${JOBS:-2}
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCADMEDIAL_SANITIZE=ON \
      -DCADMEDIAL_BUILD_PYTHON=OFF -DCADMEDIAL_BUILD_TESTS=ON >/dev/null
cmake --build build-asan -j"$JOBS"
# halt_on_error / abort_on_error: the first report fails the test that triggered it, with its trace.
# detect_leaks=0: OpenCASCADE keeps shapes and handles in static caches that LeakSanitizer reports
# at every exit (a flood, none of ours); set ASAN_OPTIONS yourself to look at leaks.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=0:halt_on_error=1:abort_on_error=1:strict_string_checks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
ctest --test-dir build-asan -j"$JOBS" --output-on-failure "$@"
