#!/usr/bin/env bash
# Quick start, command 2: install what is missing, build, and run the whole test suite.
# MATEVO_SANITIZE=1 builds the ASan + UBSan tree build-sanitize/ (scripts/build.sh) and tests
# that instead, then fuzzes each parser briefly (scripts/fuzz.sh, MATEVO_FUZZ_SECONDS each,
# default 10) with the fuzz targets that build made. .ci/run runs both, in that order.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --tests
build_dir=build
test_environment=()
if [[ "${MATEVO_SANITIZE:-0}" == 1 ]]; then
    build_dir=build-sanitize
    # Keep the Vulkan driver and layer mapped, so that LeakSanitizer can name the module of
    # their own leaks and we suppress exactly those (tests/sanitize/PinVulkanModules.c).
    test_environment=(
        LD_PRELOAD="$PWD/build-sanitize/libmatevo_pin_vulkan_modules.so"
        # A failed allocation returns null as in a normal build (lavapipe then reports
        # VK_ERROR_OUT_OF_DEVICE_MEMORY, which a test provokes) instead of aborting the process.
        ASAN_OPTIONS=verify_asan_link_order=0:allocator_may_return_null=1
        # The "suppressions used" table would read as validation output to the editor's test.
        LSAN_OPTIONS="suppressions=$PWD/scripts/lsan-suppressions.txt:print_suppressions=0"
    )
fi
scripts/build.sh
env "${test_environment[@]}" ctest --test-dir "$build_dir" --output-on-failure -j"$(nproc)" "$@"
if [[ "${MATEVO_SANITIZE:-0}" == 1 ]]; then
    # A short libFuzzer run of every parser (clang, ASan + UBSan), from the seed corpus.
    scripts/fuzz.sh "${MATEVO_FUZZ_SECONDS:-10}"
fi
