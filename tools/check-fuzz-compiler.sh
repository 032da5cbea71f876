#!/bin/sh
# make fuzz needs clang with libFuzzer (-fsanitize=fuzzer). Says what to
# install when it is missing; the rest of the build does not need clang.
set -u
cc=${1:-clang}
if ! command -v "$cc" >/dev/null 2>&1; then
    echo "make fuzz needs $cc, with libFuzzer. On Debian or Ubuntu:" >&2
    echo "    apt-get install clang libclang-rt-dev   (or libclang-rt-NN-dev for clang-NN)" >&2
    exit 1
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
printf '%s\n' '#include <stddef.h>' '#include <stdint.h>' \
    'int LLVMFuzzerTestOneInput(const uint8_t *d, size_t n) { (void)d; (void)n; return 0; }' \
    >"$tmp/probe.c"
if ! "$cc" -fsanitize=fuzzer,address,undefined "$tmp/probe.c" -o "$tmp/probe" 2>"$tmp/err"; then
    echo "make fuzz: $cc cannot build a libFuzzer target:" >&2
    head -3 "$tmp/err" >&2
    echo "install libFuzzer's runtime: apt-get install libclang-rt-dev (or libclang-rt-NN-dev)" >&2
    exit 1
fi
