#!/bin/sh
# page_numbers.sh: every number a lesson page quotes in its text or tables
# from a program's output is what that program prints today.
# tests/tools/test_page_numbers.c runs it; by hand, from the top of the tree:
#
#     sh tests/tools/page_numbers.sh [LIST [WORK_DIR]]
#
# LIST (default tests/tools/page_numbers.txt) has one line per quoted number:
#
#     docs/PAGE.md | QUOTED | PRINTED | COMMAND [| SCALE]
#
# and each line holds when
#   - some line of the page contains QUOTED verbatim;
#   - COMMAND (sh, from the top of the tree, $OUT a scratch directory for its
#     pictures; build/bin/ and build/tools/ stand for BIN_DIR and TOOL_DIR, as
#     make test sets them) prints PRINTED verbatim within one line of its output (stdout
#     and stderr together), whatever its status;
#   - the first number of QUOTED (commas in it dropped) equals the last
#     number of PRINTED times SCALE (1 if not given), rounded to as many
#     decimals as the quoted number has.
# Each distinct command runs once. Output: one line per failure, then
# "page numbers: N checked, M failed"; exit status 1 on a failure.
set -u
list=${1:-tests/tools/page_numbers.txt}
work=${2:-build/test-output/page-numbers}
rm -rf "$work"
mkdir -p "$work/out" "$work/runs" || exit 1
OUT=$work/out
export OUT

# ---- each distinct command, run once: runs/N.cmd and runs/N.txt ----
awk -F ' [|] ' '!/^#/ && NF >= 4 { print $4 }' "$list" | sort -u > "$work/commands"
# The programs as the tests run them: build/bin/ is BIN_DIR, build/tools/ TOOL_DIR.
bin=${BIN_DIR:-build/bin}
tools=${TOOL_DIR:-build/tools}
n=0
while IFS= read -r cmd; do
    n=$((n + 1))
    printf '%s\n' "$cmd" > "$work/runs/$n.cmd"
    run=$(printf '%s\n' "$cmd" | sed "s#build/bin/#$bin/#g; s#build/tools/#$tools/#g")
    sh -c "$run" > "$work/runs/$n.txt" 2>&1 < /dev/null
done < "$work/commands"

# ---- every line of the list ----
awk -F ' [|] ' -v runs="$work/runs" -v n="$n" '
    function first_number(s,   m) {
        if (!match(s, /[0-9][0-9,]*(\.[0-9]+)?([eE][-+]?[0-9]+)?/)) return ""
        m = substr(s, RSTART, RLENGTH); gsub(",", "", m); return m
    }
    function last_number(s,   m, rest) {
        m = ""
        rest = s
        while (match(rest, /-?[0-9]+(\.[0-9]+)?([eE][-+]?[0-9]+)?/)) {
            m = substr(rest, RSTART, RLENGTH)
            rest = substr(rest, RSTART + RLENGTH)
        }
        return m
    }
    function decimals(s) { return index(s, ".") && s !~ /[eE]/ ? length(s) - index(s, ".") : 0 }
    function page_has(page, text,   line, found) {
        found = 0
        while ((getline line < page) > 0)
            if (index(line, text)) found = 1
        close(page)
        return found
    }
    function output_has(k, text,   line, found, f) {
        found = 0; f = runs "/" k ".txt"
        while ((getline line < f) > 0)
            if (index(line, text)) found = 1
        close(f)
        return found
    }
    function bad(why) { printf "%s:%d: %s: %s\n", FILENAME, FNR, $1, why; failed++ }
    BEGIN {
        for (k = 1; k <= n; k++) {
            f = runs "/" k ".cmd"; getline c < f; close(f); run_of[c] = k
        }
    }
    /^#/ || NF == 0 { next }
    {
        checked++
        if (NF < 4 || NF > 5) { bad("not four or five fields"); next }
        page = $1; quoted = $2; printed = $3; cmd = $4; scale = NF == 5 ? $5 + 0 : 1
        if (!page_has(page, quoted)) { bad("the page has no line with \"" quoted "\""); next }
        if (!output_has(run_of[cmd], printed)) {
            bad("\"" cmd "\" no longer prints \"" printed "\"; it prints:")
            f = runs "/" run_of[cmd] ".txt"
            while ((getline line < f) > 0) print "    " line
            close(f)
            next
        }
        q = first_number(quoted); p = last_number(printed)
        if (q == "" || p == "") { bad("no number in \"" quoted "\" or \"" printed "\""); next }
        want = sprintf("%." decimals(q) "f", p * scale)
        if (want + 0 != q + 0)
            bad("the page quotes " q " where the program prints " p \
                (scale != 1 ? " (times " scale ": " want ")" : ""))
    }
    END {
        printf "page numbers: %d checked, %d failed\n", checked, failed
        exit failed > 0
    }' "$list"
