#!/usr/bin/env bash
# Quick start, command 1: install what is missing, build, and run the main job on the built-in
# default preset (validation metal), writing its result to out/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
# Only what the main job runs (the executable, which brings its OpenImageIO module), not the
# test suite: scripts/test.sh builds the rest.
scripts/build.sh matevo
./build/matevo evolve --out out "$@"
echo "matevo: written to out/: result.json, target.png, candidates/ and heatmaps/ (best first)"
