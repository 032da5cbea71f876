#!/bin/sh
# Runs each cmocka test binary given on the command line, shows its output,
# and ends with one line over all of them: "N passed, M failed".
# Exit status 0 only when every test passed and every binary exited cleanly.
#
# The binaries run in parallel, TEST_JOBS at a time (by default one more than
# the number of cores: some tests spend seconds waiting, on a time limit or a
# child, and the one more keeps every core busy), each into a log of its own. The logs are printed whole, one after
# the other, in the order of the command line, each as soon as it and the
# ones before it are done: the report reads as if they had run one by one.
# The slowest binaries of the last run (their seconds are kept in
# $TEST_OUTPUT/test-times) start first, so that no long one starts last.
# Each binary, when done, writes its index into a pipe that this script
# reads: it sleeps until one is done, and starts no process to wait.
set -u
cores=$(nproc 2>/dev/null || getconf _NPROCESSORS_ONLN 2>/dev/null || echo 1)
case $cores in
    ''|*[!0-9]*|0) cores=1 ;;
esac
jobs=${TEST_JOBS:-$((cores + 1))}
case $jobs in
    ''|*[!0-9]*|0) jobs=1 ;;
esac
times_file=${TEST_OUTPUT:-build/test-output}/test-times

# The tests' scratch, $TEST_OUTPUT/tmp (test_dir): the tools' tests build,
# copy and delete whole trees there, tens of thousands of files a run, which
# on a disk cost seconds of the kernel's time (ext4 without a journal looks at
# every inode deleted in the last minutes before it gives one out again). On
# a file system in memory when the machine has one that runs programs and has
# room (TEST_SCRATCH, /dev/shm by default; TEST_SCRATCH= keeps it on disk):
# $TEST_OUTPUT/tmp is then a link to it, removed when the run ends (an
# interrupt too), but kept after a failure for a look until the next run, or
# `run-tests.sh --remove-scratch` (make clean).
out_dir=${TEST_OUTPUT:-build/test-output}
link="$out_dir/tmp"
remove_kept_scratch() { # the last run's, if kept (only a scratch of ours)
    if [ -L "$link" ]; then
        last=$(readlink "$link")
        case ${last##*/} in hsr-tests.????????) rm -rf "$last" ;; esac
        rm -f "$link"
    fi
}
remove_kept_scratch
[ "${1:-}" = --remove-scratch ] && exit 0
scratch=""
root=${TEST_SCRATCH-/dev/shm}
if [ -n "$root" ] && [ -d "$root" ] && [ -w "$root" ] &&
    [ "$(df -Pk "$root" 2>/dev/null | awk 'NR == 2 { print $4 }')" -gt 2097152 ] 2>/dev/null &&
    scratch=$(mktemp -d "$root/hsr-tests.XXXXXXXX" 2>/dev/null); then
    if printf '#!/bin/sh\nexit 0\n' >"$scratch/can-run" && chmod +x "$scratch/can-run" &&
        "$scratch/can-run" 2>/dev/null && mkdir -p "$out_dir" && rm -rf "$link" &&
        ln -s "$scratch" "$link"; then
        rm -f "$scratch/can-run"
    else
        rm -rf "$scratch"
        scratch=""
    fi
fi
# A make test that a test runs (in a tree of its own, under this scratch) keeps
# its scratch where it is (run_shell, tests/support/shell.c, says so too).
TEST_SCRATCH=
export TEST_SCRATCH
keep=0 # 1: the scratch stays (a failure)

work=$(mktemp -d) || exit 1
# out/ is the student's: a test writes its pictures in a directory of its own.
# What out/ holds before is compared with what it holds after.
list_out() { find out -type f -exec ls -l --time-style=+%s.%N {} + 2>/dev/null | sort; }
trap 'rm -rf "$work"; [ -z "$scratch" ] || [ "$keep" -eq 1 ] || remove_kept_scratch' EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

# "<index> <binary>", in the command line's order; then the order they start
# in: longest last time first, binaries never timed first of all, ties (and
# the first run) in the command line's order.
i=0
for t in "$@"; do
    i=$((i + 1))
    echo "$i $t"
done >"$work/list"
awk -v times="$times_file" '
    BEGIN { while ((getline l < times) > 0) { split(l, f, " "); secs[f[2]] = f[1] } }
    { printf "%d %d %s\n", ($2 in secs) ? secs[$2] : 1000000, $1, $2 }' "$work/list" |
    sort -s -k1,1nr | cut -d' ' -f2- >"$work/start"

# One binary: its output into <index>.log, its exit status into <index>.status
# (written last, by a rename: it says the log is complete), its seconds; then
# its index into the pipe "done". When every binary has run, "end".
# The pipe is held open for reading and writing (3<>): opening it never
# blocks, and a read waits for a line rather than finding the end of a file.
mkfifo "$work/done" || exit 1
exec 3<>"$work/done"
list_out >"$work/out-before"
# shellcheck disable=SC2016 # expanded by the inner sh
{
    [ $# -gt 0 ] && xargs -n 2 -P "$jobs" sh -c '
        start=$(date +%s)
        "$2" >"$0/$1.log" 2>&1
        echo $? >"$0/$1.status.tmp"
        echo "$(($(date +%s) - start)) $2" >"$0/$1.time"
        mv "$0/$1.status.tmp" "$0/$1.status"
        echo "$1" >"$0/done"' "$work" <"$work/start"
    echo end >"$work/done"
} 3<&- &
runner=$!

passed=0
failed=0
broken=""
ended=0
i=0
for t in "$@"; do
    i=$((i + 1))
    # Until binary i is done: a line for each binary that finishes.
    while [ ! -f "$work/$i.status" ]; do
        if [ "$ended" -eq 1 ] || ! read -r line <&3; then
            echo "run-tests: $t did not run" >&2
            break
        fi
        [ "$line" = end ] && ended=1
    done
    log="$work/$i.log"
    read -r status <"$work/$i.status" 2>/dev/null || status=127
    [ -f "$log" ] && cat "$log"
    [ -f "$log" ] || : >"$log"
    # After a failure: the function each failed test checks, the diff pictures.
    if [ "$status" -ne 0 ]; then sh tools/test-hints.sh "$t" "$log"; fi
    # cmocka's counts: "[  PASSED  ] N test(s)." and "[  FAILED  ] N test(s), listed below:".
    read -r p f <<EOF
$(awk '/^\[  PASSED  \] [0-9]+ test\(s\)\.$/ { p += $4 }
       /^\[  FAILED  \] [0-9]+ test\(s\), listed below:$/ { f += $4 }
       END { print p + 0, f + 0 }' "$log")
EOF
    passed=$((passed + p))
    failed=$((failed + f))
    # A binary that crashed, or failed without cmocka counting it, still fails the run.
    if [ "$status" -ne 0 ] && [ "$f" -eq 0 ]; then
        failed=$((failed + 1))
        broken="$broken $t(exit $status)"
    fi
done
wait "$runner"

# This run's seconds replace the last ones of the same binaries.
if [ -d "$(dirname "$times_file")" ] || mkdir -p "$(dirname "$times_file")" 2>/dev/null; then
    cat "$work"/*.time 2>/dev/null >"$work/new-times"
    { cat "$work/new-times"
      [ -f "$times_file" ] && awk 'NR == FNR { seen[$2] = 1; next } !($2 in seen)' \
          "$work/new-times" "$times_file"
    } >"$work/all-times"
    mv "$work/all-times" "$times_file" 2>/dev/null || true
fi

list_out >"$work/out-after"
if ! cmp -s "$work/out-before" "$work/out-after"; then
    echo "run-tests: a test wrote into out/, the student's pictures (it must use test_dir):"
    diff "$work/out-before" "$work/out-after" | sed -n 's/^> .* out\//  out\//p'
    failed=$((failed + 1))
fi
[ -n "$broken" ] && echo "broken test binaries:$broken"
if [ -n "$scratch" ] && [ "$failed" -ne 0 ]; then
    keep=1
    echo "run-tests: the tests' scratch is kept in $scratch ($link) until the next run"
fi
# Nothing ran: a fault of the command line, not a pass (status 1 as ever).
if [ "$passed" -eq 0 ] && [ "$failed" -eq 0 ]; then
    if [ $# -eq 0 ]; then
        echo "run-tests: error: no test program to run" >&2
    elif [ -n "${TEST_FILTER:-}" ]; then
        echo "run-tests: error: no test is named '$TEST_FILTER' (TEST= takes a test's name; * and ? work)" >&2
    else
        echo "run-tests: error: no test ran" >&2
    fi
fi
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ] && [ "$passed" -gt 0 ]
