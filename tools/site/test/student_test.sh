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
found=$(awk -v mode=find -v lines="$work/lines" -f tools/solution-regions.awk "$work"/text/*.txt)
wanted=$(wc -l <"$work/lines")
printf '%s\n' "$found" | while IFS="$(printf '\t')" read -r at where code; do
    [ -n "$at" ] || continue
    name=$(cat "$(printf '%s' "${at%:*}" | sed 's/\.txt$/.name/')")
    echo "FAIL: $name has a solution line of $where: $code"
done
count=$(printf '%s' "$found" | grep -c . || true)
echo "student-test: $wanted solution lines looked for in the student edition, $count found"
[ "$count" -eq 0 ] && [ "$wanted" -gt 0 ]
