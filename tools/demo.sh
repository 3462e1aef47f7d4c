#!/usr/bin/env bash
# Fresh machine to result: installs the packages, builds, and computes the inner medial axis of a
# bundled STEP part (NIST FTC 11), writing out/nist_ftc_11.ply and out/nist_ftc_11.json.
set -euo pipefail
cd "$(dirname "$0")/.."
[ "${CADMEDIAL_SKIP_SETUP:-0}" = 1 ] || bash tools/setup.sh
bash tools/build.sh
mkdir -p out
./build/cadmedial compute examples/data/nist_ftc_11_asme1_rb.stp -o out/nist_ftc_11.ply --stats out/nist_ftc_11.json
