#!/bin/sh
# lesson-diff.sh FROM TO: the source difference between two lessons, which is
# what the later lesson teaches. FROM and TO are lesson numbers (02) or names
# (02_zbuffer). With --stat, one line per file: "<added> <removed> <file>".
set -eu
stat=0
if [ "${1:-}" = "--stat" ]; then stat=1; shift; fi
if [ $# -ne 2 ]; then
    echo "usage: make diff FROM=NN TO=NN   (e.g. make diff FROM=02 TO=03)" >&2
    exit 2
fi
find_lesson() {
    for d in lessons/"$1"*; do
        [ -d "$d" ] && { echo "$d"; return 0; }
    done
    echo "lesson-diff: error: no lesson '$1' in lessons/" >&2
    exit 2
}
from=$(find_lesson "$1")
to=$(find_lesson "$2")
if [ "$stat" -eq 0 ]; then
    # -N: a file that exists in one lesson only shows as wholly added or removed.
    diff -ruN "$from" "$to" || [ $? -eq 1 ]
    exit 0
fi
for f in $( (ls "$from"; ls "$to") | sort -u); do
    counts=$(diff -uN "$from/$f" "$to/$f" | awk '
        /^(\+\+\+|---) / { next }
        /^\+/ { a++ } /^-/ { r++ }
        END { printf "%d %d", a, r }') || true
    echo "$counts $f"
done
