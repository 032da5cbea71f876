#!/bin/sh
# Runs each cmocka test binary given on the command line, shows its output,
# and ends with one line over all of them: "N passed, M failed".
# Exit status 0 only when every test passed and every binary exited cleanly.
set -u
passed=0
failed=0
broken=""
for t in "$@"; do
    log=$(mktemp)
    "$t" >"$log" 2>&1
    status=$?
    cat "$log"
    # After a failure: the function each failed test checks, the diff pictures.
    if [ "$status" -ne 0 ]; then sh scripts/test-hints.sh "$t" "$log"; fi
    p=$(sed -n 's/^\[  PASSED  \] \([0-9][0-9]*\) test(s)\.$/\1/p' "$log" | awk '{s+=$1} END {print s+0}')
    f=$(sed -n 's/^\[  FAILED  \] \([0-9][0-9]*\) test(s), listed below:$/\1/p' "$log" | awk '{s+=$1} END {print s+0}')
    rm -f "$log"
    passed=$((passed + p))
    failed=$((failed + f))
    # A binary that crashed, or failed without cmocka counting it, still fails the run.
    if [ "$status" -ne 0 ] && [ "$f" -eq 0 ]; then
        failed=$((failed + 1))
        broken="$broken $t(exit $status)"
    fi
done
[ -n "$broken" ] && echo "broken test binaries:$broken"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ] && [ "$passed" -gt 0 ]
