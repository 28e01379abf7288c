#!/usr/bin/env bash
# Installs the Debian 12 packages matevo needs, only those missing. Uses sudo when not root.
#   scripts/install-deps.sh          what building and running matevo needs
#   scripts/install-deps.sh --tests  that, plus the test stack (scripts/test.sh asks for it)
set -euo pipefail

# DejaVu Sans is the font of the charts and contact sheets matevo draws (core/image/Font.h).
packages=(
    build-essential cmake ninja-build pkg-config
    libvulkan-dev mesa-vulkan-drivers glslang-tools glslang-dev
    libglfw3-dev libimgui-dev libglm-dev libopenimageio-dev libpng-dev nlohmann-json3-dev
    libtinygltf-dev fonts-dejavu-core
)
# GoogleTest, the validation layer every GPU test runs under, a virtual display and input for
# the editor test, screenshots, the Python peers the tests and benchmarks compare with,
# jsonschema for the presets' schema, clang with its sanitizer runtimes for scripts/fuzz.sh,
# libxml2 to re-read exported MaterialX, GNU parallel and a single-node Slurm cluster (slurm-wlm,
# munge) for docs/batch.md's examples, ccache, which lets the install test's second,
# out-of-tree build reuse what the suite's build compiled, and clang-format for the layout check.
test_packages=(
    libgtest-dev vulkan-validationlayers clang libclang-rt-14-dev
    xvfb xauth imagemagick xdotool
    python3-skimage python3-deap python3-numpy python3-jsonschema
    libxml2-dev parallel slurm-wlm munge ccache clang-format
)
tests=0
case "${1:-}" in
    "") ;;
    --tests)
        tests=1
        packages+=("${test_packages[@]}")
        # The Khronos glTF validator (tests/export) comes from npm; Debian's only when none is there.
        command -v npm >/dev/null || packages+=(nodejs npm)
        ;;
    *) echo "usage: scripts/install-deps.sh [--tests]" >&2; exit 2 ;;
esac

missing=()
for package in "${packages[@]}"; do
    status=$(dpkg-query -W -f='${Status}' "$package" 2>/dev/null || true)
    [[ "$status" == "install ok installed" ]] || missing+=("$package")
done
if [[ ${#missing[@]} -gt 0 ]]; then
    echo "matevo: installing ${missing[*]}" >&2
    sudo=""
    [[ $(id -u) -eq 0 ]] || sudo="sudo"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends \
        "${missing[@]}"
fi

validator="$(dirname "$0")/../tests/export/gltf-validator"
if [[ $tests == 1 && ! -d "$validator/node_modules/gltf-validator" ]]; then
    echo "matevo: installing the glTF validator (npm) into tests/export/gltf-validator" >&2
    npm ci --prefix "$validator" --no-audit --no-fund --loglevel=error
fi
