#!/usr/bin/env bash
# Quick start, command 1: install what is missing, build, and run the main job on the built-in
# default preset (validation metal), writing its result to out/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
./build/matevo evolve --out out "$@"
echo "matevo: written to out/: result.json, target.png, candidates/ and heatmaps/ (best first)"
