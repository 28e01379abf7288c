#!/usr/bin/env bash
# The C++ sources' layout is .clang-format's: `scripts/format.sh` rewrites every tracked .h/.cpp
# that differs, `scripts/format.sh --check` only lists them and fails (the suite's
# `source_format` test runs that, so a change that skips formatting does not land).
set -euo pipefail
cd "$(dirname "$0")/.."
mode="${1:-}"
[[ "$mode" == "" || "$mode" == --check ]] || { echo "usage: scripts/format.sh [--check]" >&2; exit 2; }
mapfile -t sources < <(git ls-files '*.h' '*.cpp')
if [[ "$mode" == --check ]]; then
    # grep finds nothing when every file is formatted: not a failure of the pipeline.
    unformatted=$(clang-format --dry-run "${sources[@]}" 2>&1 |
        { grep -oE '^[^ :]+:[0-9]+:[0-9]+: (warning|error)' || true; } | cut -d: -f1 | sort -u)
    [[ -z "$unformatted" ]] && exit 0
    sed 's/$/: not formatted (scripts\/format.sh fixes it)/' <<<"$unformatted" >&2
    exit 1
else
    clang-format -i "${sources[@]}"
fi
