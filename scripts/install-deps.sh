#!/usr/bin/env bash
# Installs the Debian 12 packages matevo needs, only those missing. Uses sudo when not root.
set -euo pipefail

packages=(
    build-essential cmake ninja-build pkg-config
    libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers glslang-tools glslang-dev
    libglfw3-dev libimgui-dev libglm-dev libopenimageio-dev nlohmann-json3-dev libtinygltf-dev
    libgtest-dev libbenchmark-dev clang libclang-rt-14-dev
    xvfb xauth imagemagick xdotool
    python3-skimage python3-deap python3-numpy
)

missing=()
for package in "${packages[@]}"; do
    status=$(dpkg-query -W -f='${Status}' "$package" 2>/dev/null || true)
    [[ "$status" == "install ok installed" ]] || missing+=("$package")
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

echo "matevo: installing ${missing[*]}" >&2
sudo=""
[[ $(id -u) -eq 0 ]] || sudo="sudo"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
