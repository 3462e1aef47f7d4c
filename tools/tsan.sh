#!/usr/bin/env bash
# Builds the CLI with ThreadSanitizer in build-tsan/ (CADMEDIAL_SANITIZE_THREAD=ON) and runs it on
# parts of ../shared/data/models: the medial stages, the thin-wall check and the exact
# classification split their work over two threads, and a data race there would make the output
# differ from run to run. OpenCASCADE's and the system's libraries are not instrumented: only our
# code and the header-only CGAL are watched. Not part of CI (the build alone takes minutes).
#   bash tools/tsan.sh [PART ...] [-- cadmedial options]   default: three parts at --samples 20000
# Exit status: the number of runs that failed or reported a race (0: none).
set -uo pipefail
cd "$(dirname "$0")/.."
JOBS=${JOBS:-2}
cmake -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCADMEDIAL_SANITIZE_THREAD=ON \
      -DCADMEDIAL_BUILD_PYTHON=OFF -DCADMEDIAL_BUILD_TESTS=OFF >/dev/null || exit 1
cmake --build build-tsan -j"$JOBS" --target cadmedial >/dev/null || exit 1
parts=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do parts+=("$1"); shift; done
[ "${1:-}" = "--" ] && shift
opts=("$@")
[ ${#opts[@]} -gt 0 ] || opts=(--samples 20000)
[ ${#parts[@]} -gt 0 ] || parts=(freecad/Y_Rod_Mount.brep nist/nist_ctc_01_asme1_rd.stp freecad/refine_breaks_cylinder.brep)
export TSAN_OPTIONS=${TSAN_OPTIONS:-halt_on_error=1:exitcode=66:report_signal_unsafe=0}
out=$(mktemp -d)
failed=0
for part in "${parts[@]}"; do
  log="$out/$(basename "$part").log"
  build-tsan/cadmedial compute "../shared/data/models/$part" -o "$out/axis.ply" "${opts[@]}" >"$log" 2>&1
  status=$?
  races=$(grep -c "WARNING: ThreadSanitizer" "$log")
  echo "$part: exit $status, $races race reports"
  if [ $status -ne 0 ] || [ "$races" -ne 0 ]; then failed=$((failed + 1)); echo "  log: $log"; fi
done
exit $failed
