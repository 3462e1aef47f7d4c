#!/usr/bin/env bash
# Runs the BREP fuzzer for SECONDS (default 300) on one core, seeded with the project's BREP files.
# New interesting inputs go to fuzz/build/corpus (not committed). It keeps going after a crash
# (-fork=1 -ignore_*): each crash, OOM or timeout is written to fuzz/build/artifacts/;
# copy each into tests/data/bad/fuzz/ with a regression test (see tests/python/test_bad_inputs.py).
set -euo pipefail
cd "$(dirname "$0")"
SECONDS_TO_RUN=${1:-300}
[ -x build/fuzz_read_brep ] || bash build.sh
mkdir -p build/corpus build/seeds build/artifacts
find ../tests/data ../tests/python/data ../examples -name '*.brep' -size -64k -not -path '*fuzz-slow*' -exec cp {} build/seeds/ \; 2>/dev/null || true
# detect_leaks=0: OpenCASCADE keeps its handles in global caches (the messenger, the type registry)
# that LeakSanitizer reports at exit on every run.
ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=0} \
  build/fuzz_read_brep build/corpus build/seeds -max_total_time="$SECONDS_TO_RUN" -max_len=16384 \
  -timeout=20 -rss_limit_mb=2048 -artifact_prefix=build/artifacts/ -print_final_stats=1 \
  -fork=1 -ignore_crashes=1 -ignore_ooms=1 -ignore_timeouts=1
