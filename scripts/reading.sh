#!/bin/sh
# reading.sh [--tsv]: what a reader opens to follow each lesson (make reading).
#
# Per lesson:
#   reading path  main.c, the taught files (every other file at the top of the
#                 lesson directory, raster.h, raster.c, ..., but those carried
#                 unchanged from the lesson before), then the headers they
#                 include directly, of the lesson (extras/extras.h) or of
#                 common/, each once, in the order first included. Lines are
#                 counted as the files stand, comments and markers included.
#   solution      lines inside SOLUTION BEGIN/END regions (make handout's stubs
#                 replace them), over every file of the lesson.
#   diff to next  lines of `make diff FROM=<this> TO=<next>`; where the next
#                 lesson replaces a file whole (its REPLACES), the lines of
#                 everything else, with the replacing files (and the note that
#                 names them) counted apart.
# --tsv prints one line per lesson, tab-separated, for tests:
#   lesson  files  path_lines  main_lines  solution_lines  next  diff_lines  replacing_lines
set -eu
tsv=0
[ "${1:-}" = "--tsv" ] && tsv=1
regions=scripts/solution-regions.awk
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# True when file $1 reads the same (solution markers aside) as file $2.
same_as() {
    [ -f "$2" ] || return 1
    awk -v mode=clean -f "$regions" "$1" >"$tmp/a" && awk -v mode=clean -f "$regions" "$2" >"$tmp/b" &&
        cmp -s "$tmp/a" "$tmp/b"
}

# The reading path of lesson directory $1 (whose predecessor is $2, or
# nothing), one file per line. A file the lesson carries unchanged from its
# predecessor is not taught again: it is on the path only if a taught file
# includes it.
reading_path() {
    dir=$1 prev=$2
    start="$dir/main.c"
    for f in "$dir"/*.h "$dir"/*.c; do
        [ -f "$f" ] && [ "$f" != "$dir/main.c" ] || continue
        [ -n "$prev" ] && same_as "$f" "$prev/${f##*/}" && continue
        start="$start $f"
    done
    # shellcheck disable=SC2086
    awk -v dir="$dir" '
        function add(f) { if (!(f in seen)) { seen[f] = 1; order[++n] = f } }
        BEGIN { for (i = 1; i < ARGC; i++) add(ARGV[i]) }
        /^#include "/ {
            name = $2; gsub(/"/, "", name)
            base = FILENAME; sub(/\/[^\/]*$/, "", base)
            if ((getline line < (base "/" name)) >= 0) { close(base "/" name); add(base "/" name) }
            else if ((getline line < (dir "/" name)) >= 0) { close(dir "/" name); add(dir "/" name) }
            else if ((getline line < ("common/" name)) >= 0) { close("common/" name); add("common/" name) }
        }
        END { for (i = 1; i <= n; i++) print order[i] }' $start | sed 's|/\./|/|g; s|[^/]*/\.\./||g'
}

lines_of() { wc -l <"$1" | tr -d ' '; }

solution_lines() {
    find "$1" -type f \( -name '*.c' -o -name '*.h' \) -exec awk '
        /SOLUTION BEGIN/ { inside = 1; hint = ($0 !~ /\*\//); next }
        hint { if ($0 ~ /\*\//) hint = 0; next } # the rest of the hint comment
        /SOLUTION STUB/ { inside = 0 }
        /SOLUTION END/ { inside = 0; next }
        inside { n++ }
        END { print n + 0 }' {} + | awk '{ s += $1 } END { print s + 0 }'
}

lessons=$(ls -d lessons/[0-9][0-9]_* | sort)
set -- $lessons
[ "$tsv" -eq 1 ] || printf '%-24s %5s %6s %6s %8s  %s\n' lesson files lines main.c solution "diff to next"
prev=""
while [ $# -gt 0 ]; do
    dir=$1; shift
    name=${dir#lessons/}
    path=$(reading_path "$dir" "$prev")
    prev=$dir
    files=$(echo "$path" | grep -c .)
    total=0
    for f in $path; do total=$((total + $(lines_of "$f"))); done
    main=$(lines_of "$dir/main.c")
    sol=$(solution_lines "$dir")
    next="-" diff_lines="-" replacing="-"
    if [ $# -gt 0 ]; then
        next=${1#lessons/}
        # The diff's lines, apart from the files shown whole because they
        # replace one (with the note that says so at its top).
        counts=$(sh scripts/lesson-diff.sh "${name%%_*}" "${next%%_*}" | awk '
            /^# .* replaces .*: shown whole below$/ {
                f = $2; sub(/.*\//, "", f); whole[f] = 1; r++; next }
            /^diff / { f = $NF; sub(/.*\//, "", f); in_whole = (f in whole) }
            { if (in_whole) r++; else o++ }
            END { printf "%d %d", o, r }')
        diff_lines=${counts% *}
        replacing=${counts#* }
    fi
    if [ "$tsv" -eq 1 ]; then
        printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$name" "$files" "$total" "$main" "$sol" \
            "$next" "$diff_lines" "$replacing"
        continue
    fi
    d="$diff_lines"
    [ "$replacing" != "-" ] && [ "$replacing" -gt 0 ] && d="$diff_lines (+ $replacing in files shown whole)"
    [ "$next" = "-" ] || d="$d to ${next%%_*}"
    printf '%-24s %5s %6s %6s %8s  %s\n' "$name" "$files" "$total" "$main" "$sol" "$d"
    echo "$path" | while read -r f; do printf '    %-44s %5s\n' "$f" "$(lines_of "$f")"; done
done
