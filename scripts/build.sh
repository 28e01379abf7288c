#!/usr/bin/env bash
# Configures (once) and builds matevo into build/ (Release unless BUILD_TYPE says otherwise).
# MATEVO_SANITIZE=1: the sanitizer build instead, in build-sanitize/: clang, ASan + UBSan, the
# fuzz targets as libFuzzer binaries (CMakeLists.txt's MATEVO_SANITIZE); scripts/test.sh and
# scripts/fuzz.sh both use it.
#   scripts/build.sh [TARGET...]     all targets when none is named
set -euo pipefail
cd "$(dirname "$0")/.."
if [[ "${MATEVO_SANITIZE:-0}" == 1 ]]; then
    build_dir=build-sanitize
    configure=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DMATEVO_SANITIZE=ON
               -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++)
else
    build_dir=build
    configure=(-DCMAKE_BUILD_TYPE="${BUILD_TYPE:-Release}")
fi
if [[ ! -f "$build_dir/CMakeCache.txt" ]]; then
    cmake -S . -B "$build_dir" -G Ninja "${configure[@]}" >/dev/null
fi
targets=()
[[ $# -eq 0 ]] || targets=(--target "$@")
cmake --build "$build_dir" -j"$(nproc)" "${targets[@]}"
