#!/usr/bin/env bash
# Quick start, command 2: install what is missing, build, and run the whole test suite.
# MATEVO_SANITIZE=1 builds an ASan+UBSan tree in build-sanitize/ and tests that instead.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
if [[ "${MATEVO_SANITIZE:-0}" == 1 ]]; then
    export BUILD_DIR=build-sanitize BUILD_TYPE=RelWithDebInfo CMAKE_ARGS="-DMATEVO_SANITIZE=ON"
fi
build_dir=${BUILD_DIR:-build}
scripts/build.sh
ctest --test-dir "$build_dir" --output-on-failure -j"$(nproc)" "$@"
