#!/bin/sh
# test-hints.sh BINARY LOG: what to look at after a test binary failed.
#
# For each failed test that tests/<group>/points.txt lists, one line with what
# the test checks: that text begins with the function it exercises, so a
# student with a handout reads which function to write (docs/teaching.md).
# Then the diff pictures that its failed image tests wrote.
# run-tests.sh calls it with the binary's log; it prints nothing when it has
# nothing to say, and never changes the outcome.
set -u
[ $# -eq 2 ] || exit 0
group=$(basename "$(dirname "$1")")
log=$2
points="tests/$group/points.txt"

if [ -f "$points" ]; then
    sed -n 's/^\[  FAILED  \] \([A-Za-z_][A-Za-z0-9_]*\)$/\1/p' "$log" | sort -u |
        awk -v points="$points" '
            BEGIN {
                while ((getline l < points) > 0) {
                    if (l ~ /^[ \t]*(#|$)/) continue
                    split(l, f, /[ \t]+/)
                    what = l
                    sub(/^[ \t]*[^ \t]+[ \t]+[^ \t]+[ \t]*/, "", what)
                    checks[f[1]] = what
                }
            }
            # A test worth 0 passes without the student'"'"'s work: when it fails,
            # something it relies on broke, not a function still to write.
            $0 in checks {
                what = checks[$0]
                if (sub(/^\(passes without the student'"'"'s work[^)]*\) /, "", what))
                    printf "hint: %s checks %s; it passes on the untouched handout, so a change outside the TODO(student) functions broke it\n", $0, what
                else
                    printf "hint: %s checks %s\n", $0, what
            }'
fi

# expect_image prints "  diff:     <path>  (magenta: ...)" for each one.
diffs=$(sed -n 's/^  diff: *\([^ ]*\.diff\.png\).*/\1/p' "$log")
if [ -n "$diffs" ]; then
    echo "hint: the differences, in magenta, are in:"
    echo "$diffs" | sed 's/^/  /'
fi
exit 0
