#!/usr/bin/env bash
# Builds fuzz/build/fuzz_read_brep with clang-14 and libFuzzer + AddressSanitizer + UBSan. Separate
# from the CMake build: it compiles the core sources the target needs (reading, checking, healing
# in src/core/io/) and links OpenCASCADE's (uninstrumented) libraries.
set -euo pipefail
cd "$(dirname "$0")"
mkdir -p build
CXX=${CXX:-clang++-14}
FLAGS=(-std=c++17 -g -O1 -fno-omit-frame-pointer -fsanitize=fuzzer,address,undefined
       -Wno-deprecated-declarations -I../src -I/usr/include/opencascade)
LIBS=(-lTKernel -lTKMath -lTKG2d -lTKG3d -lTKGeomBase -lTKBRep -lTKGeomAlgo -lTKTopAlgo -lTKPrim
      -lTKBO -lTKShHealing -lTKMesh -lTKXSBase -lTKSTEPBase -lTKSTEPAttr -lTKSTEP209 -lTKSTEP -lTKIGES)
IO=(read_shape extract_solids check_solid check_geometry heal_shape shape_text)
"$CXX" "${FLAGS[@]}" fuzz_read_brep.cpp $(printf "../src/core/io/%s.cpp " "${IO[@]}") -o build/fuzz_read_brep "${LIBS[@]}"
echo "built fuzz/build/fuzz_read_brep"
