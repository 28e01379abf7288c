#!/usr/bin/env bash
# Quick start, command 2: install what is missing, build, and run the whole test suite.
# MATEVO_SANITIZE=1 builds an ASan+UBSan tree in build-sanitize/ and tests that instead.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
if [[ "${MATEVO_SANITIZE:-0}" == 1 ]]; then
    export BUILD_DIR=build-sanitize BUILD_TYPE=RelWithDebInfo CMAKE_ARGS="-DMATEVO_SANITIZE=ON"
    # The Vulkan loader unloads lavapipe and the validation layer at vkDestroyInstance; memory
    # they still point to from their own globals then looks leaked to LeakSanitizer, from an
    # unknown module. Keeping both resident lets it see those pointers and name the module of
    # what they really leak (scripts/lsan-suppressions.txt).
    libdir=/usr/lib/$(dpkg-architecture -qDEB_HOST_MULTIARCH)
    export LD_PRELOAD="$libdir/libvulkan_lvp.so $libdir/libVkLayer_khronos_validation.so"
    export ASAN_OPTIONS=verify_asan_link_order=0
    export LSAN_OPTIONS=suppressions=$PWD/scripts/lsan-suppressions.txt
fi
build_dir=${BUILD_DIR:-build}
scripts/build.sh
ctest --test-dir "$build_dir" --output-on-failure -j"$(nproc)" "$@"
