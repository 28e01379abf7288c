#!/usr/bin/env bash
# Runs `matevo bench --json` and the Python peers in one run, then prints every median and, for
# each pair below, how many times faster matevo is. With --json: one JSON object instead.
# Peers print one JSON object each; add yours to `peers` and its comparison to `comparisons`.
set -euo pipefail
cd "$(dirname "$0")/.."
[[ -x build/matevo ]] || scripts/build.sh >/dev/null

# Debian's interpreter: python3-deap and python3-skimage live there, not in a pyenv/venv python.
python=/usr/bin/python3

peers=(
    bench/peers/deap_ga.py
    bench/peers/skimage_de00.py
)
# "matevo_key peer_key kind": kind "time" (lower is better) or "rate" (higher is better).
comparisons=(
    "ga_pop100_gen10_ms deap_ga_pop100_gen10_ms time"
    "de00_mpix_s_256 skimage_de00_mpix_s_256 rate"
    "de00_mpix_s_2048 skimage_de00_mpix_s_2048 rate"
    "de00_mpix_s skimage_de00_mpix_s rate"
)

results=("$(./build/matevo bench --json)")
for peer in "${peers[@]}"; do results+=("$("$python" "$peer")"); done

"$python" - "${1:-}" "${comparisons[@]}" -- "${results[@]}" <<'PY'
import json
import sys

args = sys.argv[1:]
as_json = args.pop(0) == "--json"
split = args.index("--")
comparisons = [entry.split() for entry in args[:split]]
figures = {}
for result in args[split + 1:]:
    figures.update(json.loads(result))

ratios = {}
for ours, peer, kind in comparisons:
    if ours in figures and peer in figures and figures[ours] > 0 and figures[peer] > 0:
        times = figures[peer] / figures[ours] if kind == "time" else figures[ours] / figures[peer]
        ratios[f"{ours}_vs_{peer}"] = times

if as_json:
    print(json.dumps({"figures": figures, "speedups": ratios}, indent=2))
else:
    for key, value in figures.items():
        print(f"{key:32} {value:14.6g}")
    for key, value in ratios.items():
        print(f"{key:64} {value:10.1f}x faster")
PY
