#!/usr/bin/env bash
# The install, as a new user would do it: a build folder outside the source tree, configured from
# scratch with the tests off and only the executable built (its OpenImageIO module comes with
# it), `cmake --install` into a temporary prefix, then every command of the installed matevo run
# from an unrelated working directory. Also: that build tree's own matevo runs from anywhere, a
# lone copy of the executable says where it looked for its resources (exit 2), and
# MATEVO_DATA_DIR points it at them. Exits non-zero on the first failure, naming it.
#   scripts/check-install.sh [CMAKE_ARGUMENT...]
#   scripts/check-install.sh --built BUILD_DIR
# With --built, the already built tree BUILD_DIR is installed instead of a fresh build: ctest's
# install_and_run_from_anywhere passes the suite's own build folder, so the suite checks the
# install without compiling the program a second time.
set -euo pipefail
source_dir=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/matevo-install-check.XXXXXX")
trap 'rm -rf "$work"' EXIT

fail() { echo "check-install: $*" >&2; exit 1; }
expect_file() { [[ -s "$1" ]] || fail "$2 did not write $1"; }

if [[ "${1:-}" == --built ]]; then
    build_dir=$(cd "$2" && pwd)
    [[ -x "$build_dir/matevo" ]] || fail "$build_dir holds no built matevo"
else
    build_dir="$work/build"
    cmake -S "$source_dir" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release \
          -DMATEVO_BUILD_TESTS=OFF "$@" >"$work/build.log" 2>&1 \
        && cmake --build "$build_dir" --target matevo -j"$(nproc)" >>"$work/build.log" 2>&1 \
        || { cat "$work/build.log" >&2; fail "the out-of-tree build"; }
fi
cmake --install "$build_dir" --prefix "$work/prefix" >/dev/null
[[ -f "$work/prefix/share/doc/matevo/LICENSE" ]] || fail "LICENSE not installed"
[[ -f "$work/prefix/share/matevo/preset.schema.json" ]] || fail "the presets' schema not installed"

matevo="$work/prefix/bin/matevo"
mkdir -p "$work/elsewhere" "$work/data/matevo/presets"
cd "$work/elsewhere"
export XDG_DATA_HOME="$work/data"  # the user's preset folder, ours alone
cp "$work/prefix/share/matevo/presets/validation_metal.json" "$work/data/matevo/presets/mine.json"

"$matevo" --version | grep -q '^matevo [0-9]' || fail "--version"
"$matevo" --help >/dev/null || fail "--help"
"$matevo" presets | grep -q '^mine ' || fail "presets does not list the user's preset"
"$matevo" evolve --preset mine --population 6 --generations 1 --size 24 --backend cpu \
    --out evolved >/dev/null || fail "evolve"
expect_file evolved/result.json evolve
"$matevo" render --preset validation_painted_metal --size 24 --backend cpu --out painted.png \
    || fail "render (a textured preset: its textures come from share/matevo)"
expect_file painted.png render
"$matevo" compare evolved/target.png evolved/candidates/candidate_000.png --json >/dev/null \
    || fail "compare"
# Formats other than PNG come through the OpenImageIO module, installed in PREFIX/lib/matevo.
"$matevo" render --preset validation_painted_metal --size 24 --backend cpu --out painted.EXR \
    || fail "render to OpenEXR"
"$matevo" compare painted.png painted.EXR --fail-above 1 >/dev/null \
    || fail "compare a PNG with an OpenEXR file"
"$matevo" variants --count 2 --band 1,4 --size 24 --fitness-size 16 --max-evaluations 200 \
    --backend cpu --out variants >/dev/null || fail "variants"
expect_file variants/report.json variants
"$matevo" scene --variants variants --size 48x32 --out scene.png >/dev/null || fail "scene"
expect_file scene.png scene
"$matevo" experiment --runs 2 --population 4 --generations 1 --metric euclidean --size 16 \
    --backend cpu --out experiment >/dev/null 2>&1 || fail "experiment"
expect_file experiment/results.csv experiment
"$matevo" bench --help >/dev/null || fail "bench --help"
if command -v xvfb-run >/dev/null; then
    xvfb-run -a "$matevo" edit mine --frames 3 --backend cpu || fail "edit under Xvfb"
fi

# The build tree's own executable finds the source tree's resources.
"$build_dir/matevo" presets | grep -q '^validation_metal ' || fail "build-tree presets"

# A lone copy finds nothing, says where it looked, exits 2; MATEVO_DATA_DIR rescues it.
mkdir -p "$work/lone/bin"
cp "$matevo" "$work/lone/bin/matevo"
status=0
message=$("$work/lone/bin/matevo" render --out lone.png 2>&1 >/dev/null) || status=$?
[[ $status -eq 2 ]] || fail "a lone executable exited $status, not 2"
[[ "$message" == "matevo render: cannot find the 'presets' folder; looked in "*"$work/lone/bin/share/matevo/presets"* ]] \
    || fail "unexpected message: $message"
status=0
message=$("$work/lone/bin/matevo" compare painted.png painted.EXR 2>&1 >/dev/null) || status=$?
[[ $status -eq 2 && "$message" == *"OpenImageIO module is not installed (looked in "*"$work/lone/lib/matevo/"* ]] \
    || fail "a lone executable reading OpenEXR: exit $status, $message"
MATEVO_DATA_DIR="$work/prefix/share/matevo" "$work/lone/bin/matevo" render --size 16 \
    --backend cpu --out lone.png || fail "MATEVO_DATA_DIR"
expect_file lone.png "render with MATEVO_DATA_DIR"
echo "check-install: ok"
