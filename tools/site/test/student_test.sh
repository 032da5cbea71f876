#!/bin/sh
# student_test.sh: the student edition of the book (make site EDITION=student)
# holds no line of a solution region (make site-test runs it).
#
#   sh tools/site/test/student_test.sh SITE_DIR WORK_DIR   (from the top of the tree)
#
# The solution lines are those tools/solution-regions.awk lists (mode=lines:
# each line only a solution has, in the form make handout looks for). The
# edition is read as a reader gets it: every page as plain text (pandoc), the
# lessons' files, the search index, book.pdf (pdftotext) and book.epub
# (pandoc). A line of any of them that is, as code, a solution line fails.
set -eu
site=$1
work=$2
rm -rf "$work"
mkdir -p "$work/text"
marked=$(grep -rlE 'SOLUTION (BEGIN|STUB|END)' README.md docs lessons | sort)
# shellcheck disable=SC2086 # one word per file
awk -v mode=lines -f tools/solution-regions.awk $marked >"$work/lines"
n=0
find "$site" -type f \( -name '*.html' -o -name '*.c' -o -name '*.h' -o -name '*.diff' \
    -o -name 'search-index.js' \) | sort | while read -r f; do
    n=$((n + 1))
    case $f in
        *.html) pandoc --from html --to plain "$f" -o "$work/text/$n.txt" ;;
        *) cp "$f" "$work/text/$n.txt" ;;
    esac
    echo "$f" >"$work/text/$n.name"
done
pdftotext "$site/book.pdf" "$work/text/pdf.txt"
echo "$site/book.pdf" >"$work/text/pdf.name"
pandoc --from epub --to plain "$site/book.epub" -o "$work/text/epub.txt"
echo "$site/book.epub" >"$work/text/epub.name"
awk -v lines="$work/lines" '
    function trim(s) { sub(/^[ \t\r]+/, "", s); sub(/[ \t\r]+$/, "", s); return s }
    function code_of(s,    i) {
        s = trim(s)
        i = index(s, "/*"); if (i > 1) s = substr(s, 1, i - 1)
        i = index(s, "//"); if (i > 1) s = substr(s, 1, i - 1)
        s = trim(s); sub(/;$/, "", s)
        return s
    }
    BEGIN {
        while ((getline l < lines) > 0) {
            split(l, part, "\t")
            want[part[2]] = part[1]
            wanted++
        }
    }
    FNR == 1 { name = FILENAME; sub(/\.txt$/, ".name", name); getline shown < name; close(name) }
    { c = code_of($0); if (c in want) { printf "FAIL: %s has a solution line of %s: %s\n", shown, want[c], c; found++ } }
    END {
        printf "student-test: %d solution lines looked for in the student edition, %d found\n", wanted, found
        exit found > 0 || wanted == 0
    }' "$work"/text/*.txt
