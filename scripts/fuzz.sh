#!/usr/bin/env bash
# Fuzzes each libFuzzer target (tests/fuzz) for SECONDS (default 10), starting from the committed
# seed corpus. The targets come from the sanitizer build (build-sanitize/: clang, ASan + UBSan;
# MATEVO_SANITIZE=1 scripts/build.sh), built here if needed. New corpus entries go to
# build-sanitize/corpus/, never into the repository; a crash leaves its input in
# build-sanitize/findings/ and fails the script.
#   scripts/fuzz.sh [SECONDS] [TARGET...]     e.g. scripts/fuzz.sh 600 fuzz_preset
# Long runs: nice -n 19 scripts/fuzz.sh 3600 (with the kernel's autogroup scheduling, nice ranks a
# process only within its session: `echo 19 > /proc/self/autogroup` first to yield to others).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-10}
shift || true
targets=("$@")
[[ ${#targets[@]} -gt 0 ]] || targets=(fuzz_preset fuzz_genome fuzz_editor_script fuzz_table_cache fuzz_image
                                       fuzz_gltf fuzz_glb fuzz_obj fuzz_checkpoint fuzz_shard_report)

build_dir=build-sanitize
MATEVO_SANITIZE=1 scripts/build.sh "${targets[@]}"

declare -A corpus_of=([fuzz_preset]=preset [fuzz_genome]=genome
                      [fuzz_editor_script]=editor_script [fuzz_table_cache]=table_cache
                      [fuzz_image]=image [fuzz_gltf]=gltf [fuzz_glb]=glb [fuzz_obj]=obj
                      [fuzz_checkpoint]=checkpoint [fuzz_shard_report]=shard_report)
mkdir -p "$build_dir/findings"
status=0
for target in "${targets[@]}"; do
    seeds=tests/fuzz/corpus/${corpus_of[$target]}
    corpus=$build_dir/corpus/${corpus_of[$target]}
    mkdir -p "$corpus"
    log=$build_dir/$target.log
    # -rss_limit_mb: our readers must stay bounded; -timeout: no input may hang a parser. A
    # small ASan quarantine, so that freed memory does not count towards the RSS limit.
    asan_options=quarantine_size_mb=16
    if ! ASAN_OPTIONS=$asan_options LSAN_OPTIONS="suppressions=$PWD/scripts/lsan-suppressions.txt" \
            "$build_dir/$target" -max_total_time="$seconds" -timeout=10 \
            -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 \
            -artifact_prefix="$build_dir/findings/$target-" "$corpus" "$seeds" >"$log" 2>&1; then
        status=1
        echo "$target: FINDING (see $log and $build_dir/findings/)" >&2
        tail -30 "$log" >&2
    fi
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    echo "$target: ${runs:-?} executions in ${seconds} s, corpus $(ls "$corpus" | wc -l) files"
done
exit $status
