#!/bin/sh
# lesson-diff.sh FROM TO: the source difference between two lessons, which is
# what the later lesson teaches. FROM and TO are lesson numbers (02) or names
# (02_zbuffer). With --stat, one line per file: "<added> <removed> <file>".
#
# Compared: the sources at the top of each lesson (main.c and the taught
# files), those it inherits included, as make builds it. Not compared: extras/, what a lesson shows but does not hand
# on (bug modes, comparisons), and the REPLACES list. A file that TO's
# REPLACES names as replacing one of FROM's is shown whole, as added, and the
# file it replaces is left out: it is a new algorithm, not an edit.
set -eu
stat=0
if [ "${1:-}" = "--stat" ]; then stat=1; shift; fi
if [ $# -ne 2 ]; then
    echo "usage: make diff FROM=NN TO=NN   (e.g. make diff FROM=02 TO=03)" >&2
    exit 2
fi
# Each a lesson's number or name, never a path: the copies below are made
# under the lesson's name, and FROM=../.. once wrote over files outside the
# tree (tools/lesson-name.sh).
prog=lesson-diff
. "$(dirname "$0")/lesson-name.sh"
lesson_name FROM "$1"
from=lessons/$lesson_name
lesson_name TO "$2"
to=lessons/$lesson_name
if [ "$from" = "$to" ]; then
    echo "$prog: error: FROM=$1 and TO=$2 are the same lesson, ${from#lessons/}: nothing to compare" >&2
    exit 2
fi
# "new old" pairs: TO's files that replace one of FROM's.
replaces=""
if [ -f "$to/REPLACES" ]; then
    replaces=$(sed -e 's/#.*//' -e '/^[[:space:]]*$/d' "$to/REPLACES")
fi
replaced_file() { # FROM's files that TO replaces
    echo "$replaces" | awk 'NF == 2 { print $2 }'
}
# The lessons are compared as they read without their solution markers
# (comments for make handout, docs/teaching.md): copies, cleaned, in a
# temporary directory with the same relative paths.
regions="$PWD/tools/solution-regions.awk"
clean=$(mktemp -d)
trap 'rm -rf "$clean"' EXIT
# A lesson's files are its own and those it inherits (tools/lesson-tree.sh),
# each under the lesson's name, where the build links it.
replaced=" $(replaced_file | tr '\n' ' ') "
for d in "$from" "$to"; do
    mkdir -p "$clean/$d"
    sh tools/lesson-tree.sh list "${d#lessons/}" >"$clean/files" || exit 2
    # The files at the top of the lesson, each under its name: in one awk
    # those named as their source is (every file the lesson holds, every
    # file it inherits: lesson-tree.sh check), one awk each for any other.
    srcs=""
    while read -r rel src; do
        case $rel in */*) continue ;; esac
        if [ "$d" = "$from" ]; then
            case $replaced in *" $rel "*) continue ;; esac
        fi
        if [ "${src##*/}" = "$rel" ]; then srcs="$srcs $src"
        else awk -v mode=clean -f "$regions" "$src" >"$clean/$d/$rel" || exit 2; fi
    done <"$clean/files"
    # shellcheck disable=SC2086 # the sources, one word each
    [ -z "$srcs" ] || awk -v mode=clean -v into="$clean/$d" -f "$regions" $srcs || exit 2
    rm -f "$clean/files"
done
cd "$clean"
if [ "$stat" -eq 0 ]; then
    if [ -n "$replaces" ]; then
        echo "$replaces" | awk -v from="$from" -v to="$to" 'NF == 2 {
            printf "# %s/%s replaces %s/%s: shown whole below\n", to, $1, from, $2 }'
    fi
    # -N: a file that exists in one lesson only shows as wholly added or removed.
    # The files' dates are cut from the --- and +++ lines, so that the diff of
    # two lessons (and docs/diffs/, which keeps it) changes only with the code.
    diff -ruN "$from" "$to" | awk '
        /^diff / { header = 2; print; next }
        header > 0 && /^(---|\+\+\+) / { header--; sub(/\t.*/, "") }
        { print }'
    exit 0
fi
for f in $( (ls "$from"; ls "$to") | sort -u); do
    counts=$(diff -uN "$from/$f" "$to/$f" | awk '
        /^(\+\+\+|---) / { next }
        /^\+/ { a++ } /^-/ { r++ }
        END { printf "%d %d", a, r }') || true
    [ "$counts" = "0 0" ] || echo "$counts $f" # a file both take unchanged is no step
done
