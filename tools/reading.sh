#!/bin/sh
# reading.sh [--tsv]: what a reader opens to follow each lesson (make reading).
#
# Per lesson:
#   reading path  main.c, the taught files (every other file at the top of the
#                 lesson, raster.h, raster.c, ..., but those the lesson before
#                 has too, unchanged), then the headers they include directly,
#                 of the lesson (extras/extras.h, an inherited scanline.h) or
#                 of common/, each once, in the order first included, each
#                 named where it lives. Lines are counted as the files stand,
#                 comments and markers included.
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
regions=tools/solution-regions.awk
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# True when file $1 reads the same (solution markers aside) as file $2.
same_as() {
    [ -f "$2" ] || return 1
    cmp -s "$1" "$2" && return 0 # the same bytes: the same without markers too
    awk -v mode=clean -f "$regions" "$1" >"$tmp/a" && awk -v mode=clean -f "$regions" "$2" >"$tmp/b" &&
        cmp -s "$tmp/a" "$tmp/b"
}

# The reading path of lesson directory $1 (whose predecessor is $2, or
# nothing), one file per line, each where it lives (an inherited file in the
# lesson that owns it: tools/lesson-tree.sh). A file the lesson carries
# unchanged from its predecessor is not taught again: it is on the path only
# if a taught file includes it.
reading_path() {
    dir=$1 prev=$2
    sh tools/lesson-tree.sh list "${dir#lessons/}" >"$tmp/files"
    : >"$tmp/prev_files"
    [ -z "$prev" ] || sh tools/lesson-tree.sh list "${prev#lessons/}" >"$tmp/prev_files"
    start="main.c"
    # (the headers first, then the sources, each in name order)
    for rel in $(awk '$1 !~ /\// && $1 ~ /\.h$/ { print $1 }' "$tmp/files") \
               $(awk '$1 !~ /\// && $1 ~ /\.c$/ && $1 != "main.c" { print $1 }' "$tmp/files"); do
        src=$(awk -v f="$rel" '$1 == f { print $2 }' "$tmp/files")
        prev_src=$(awk -v f="$rel" '$1 == f { print $2 }' "$tmp/prev_files")
        [ -n "$prev_src" ] && same_as "$src" "$prev_src" && continue
        start="$start $rel"
    done
    # shellcheck disable=SC2086
    awk -v files="$tmp/files" -v start="$start" '
        function add(f) { if (!(f in seen)) { seen[f] = 1; order[++n] = f } }
        function norm(p,    k, i, part, out, m) {
            m = split(p, part, "/"); k = 0
            for (i = 1; i <= m; i++) {
                if (part[i] == "." || part[i] == "") continue
                if (part[i] == ".." && k > 0) { k--; continue }
                out[++k] = part[i]
            }
            p = ""; for (i = 1; i <= k; i++) p = p (i > 1 ? "/" : "") out[i]
            return p
        }
        BEGIN {
            while ((getline l < files) > 0) { split(l, f, " "); src[f[1]] = f[2] }
            m = split(start, first, " ")
            for (i = 1; i <= m; i++) add(src[first[i]])
            for (i = 1; i <= m; i++) {
                rel = first[i]; base = rel; if (!sub(/\/[^\/]*$/, "", base)) base = ""
                while ((getline line < src[rel]) > 0) {
                    if (line !~ /^#include "/) continue
                    name = line; sub(/^#include "/, "", name); sub(/".*/, "", name)
                    near = norm((base == "" ? "" : base "/") name)
                    if (near in src) add(src[near])
                    else if (norm(name) in src) add(src[norm(name)])
                    else if ((getline x < ("common/" name)) >= 0) { close("common/" name); add("common/" name) }
                }
                close(src[rel])
            }
            for (i = 1; i <= n; i++) print order[i]
        }'
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
    # shellcheck disable=SC2086 # the path's files, one word each
    total=$(($(cat $path | wc -l)))
    main=$(lines_of "$dir/main.c")
    sol=$(solution_lines "$dir")
    next="-" diff_lines="-" replacing="-"
    if [ $# -gt 0 ]; then
        next=${1#lessons/}
        # The diff's lines, apart from the files shown whole because they
        # replace one (with the note that says so at its top).
        counts=$(sh tools/lesson-diff.sh "${name%%_*}" "${next%%_*}" | awk '
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
