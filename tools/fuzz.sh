#!/bin/sh
# Runs libFuzzer targets, one after the other (make fuzz).
#
#   tools/fuzz.sh BUILD_DIR SECONDS NAME...
#
# Target NAME is BUILD_DIR/fuzz/fuzz_NAME. It starts from the committed seeds
# in tests/fuzz/corpus/NAME/ (read only) plus what earlier runs found in
# BUILD_DIR/corpus/NAME/ (where new inputs go). An input that crashes, leaks,
# hangs for 10 s or trips a sanitizer is saved in BUILD_DIR/crashes/NAME/;
# the script then stops with status 1 and names it. The whole libFuzzer log
# is BUILD_DIR/logs/NAME.log; one line per target sums it up.
set -u
build=$1
seconds=$2
shift 2
for name in "$@"; do
    bin=$build/fuzz/fuzz_$name
    corpus=$build/corpus/$name
    crashes=$build/crashes/$name
    log=$build/logs/$name.log
    rm -rf "$crashes"
    mkdir -p "$corpus" "$crashes" "$build/logs" "tests/fuzz/corpus/$name"
    start=$(date +%s)
    "$bin" -max_total_time="$seconds" -timeout=10 -print_final_stats=1 \
        -artifact_prefix="$crashes/" "$corpus" "tests/fuzz/corpus/$name" >"$log" 2>&1
    status=$?
    took=$(($(date +%s) - start))
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    size=$(ls "$corpus" | wc -l)
    echo "fuzz_$name: ${runs:-?} runs in $took s, corpus $size inputs, exit status $status"
    if [ -n "$(ls "$crashes")" ] || [ "$status" -ne 0 ]; then
        grep -E '^(==[0-9]+==|SUMMARY|.*runtime error|artifact_prefix|Test unit written)' "$log" | head -20
        echo "fuzz_$name failed: inputs in $crashes/, log in $log" >&2
        exit 1
    fi
done
