#!/bin/sh
# build.sh: the book, an HTML site of the series' pages (make site).
#
#   sh tools/site/build.sh [SITE_DIR [WASM_BIN_DIR [EDITION]]]   (from the top of
#       the tree; defaults build/site, build/wasm/bin, full; or EDITION student)
#
# Every page is written once, as Markdown: README.md becomes index.html,
# docs/X.md docs/X.html, lessons/NN/README.md lessons/NN/index.html. The site
# keeps the tree's layout, so the pages' relative links hold; the pictures,
# diffs, examples and the lessons' files they link to are copied beside
# them. pandoc (tools/site/links.lua) turns links to pages into links to
# their HTML, highlights code as it builds, and writes each page's sections
# for the search index (search-index.js), and gives each lesson command a
# Run button that runs the lesson's browser build (make wasm) in the page
# (site.js, worker.js, wasm/run.js). The sidebar lists the book in
# reading order: the lessons, then the reference pages; each page links the
# one before and after it.
set -eu
site=${1:-build/site}
wasm=${2:-build/wasm/bin}
edition=${3:-full}
top=$(pwd)
here=$top/tools/site
case $site in /*) ;; *) site=$(pwd)/$site ;; esac
case $wasm in /*) ;; *) wasm=$(pwd)/$wasm ;; esac
rm -rf "$site"
mkdir -p "$site/docs" "$site/search"

# The student edition (EDITION=student): the book of a tree in which every
# solution region is taken out, as make handout takes it out
# (tools/solution-regions.awk: its hint in its place), of the pages and the
# lessons' files alike; the diffs between lessons, which show the same code,
# are each replaced by a line that says so. It is built from that copy.
if [ "$edition" = student ]; then
    copy=$(mktemp -d)
    trap 'rm -rf "$copy"' EXIT
    cp -Rp README.md docs lessons "$copy/"
    for f in $(cd "$copy" && grep -rlE 'SOLUTION (BEGIN|STUB|END)' README.md docs lessons); do
        awk -v mode=strip -f tools/solution-regions.awk "$copy/$f" >"$copy/$f.student"
        mv "$copy/$f.student" "$copy/$f"
    done
    for d in "$copy"/docs/diffs/*.diff; do
        echo "This diff is not in the student edition of the book: it shows the code that the lessons' exercises ask you to write." >"$d"
    done
    cd "$copy"
fi

# The book in reading order: source, then its title in the sidebar.
book="README.md|Introduction"
for f in docs/[0-9][0-9]_*.md; do
    n=$(basename "$f" .md)
    book="$book
$f|$(sed -n '1s/^# Lesson \([0-9]*\): /\1 /p' "$f")"
done
for f in conventions tools robustness performance teaching; do
    book="$book
docs/$f.md|$(sed -n '1s/^# //p' "docs/$f.md")"
done

html_of() { # a page's source -> its path in the site
    case $1 in
        README.md) echo index.html ;;
        */README.md) echo "${1%README.md}index.html" ;;
        *) echo "${1%.md}.html" ;;
    esac
}

root_of() { # a path in the site -> the way up to the site's top
    printf '%s\n' "$1" | awk -F/ '{ s = ""; for (i = 1; i < NF; i++) s = s "../"; print s }'
}

# The sidebar, its links from the top of the site (ROOT stands for the way up).
nav=$(printf '%s\n' "$book" | awk -F'|' -v lessons=0 '
    function esc(s) { gsub(/&/, "\\&amp;", s); gsub(/</, "\\&lt;", s); return s }
    {
        url = $1; sub(/^README\.md$/, "index.html", url); sub(/\.md$/, ".html", url)
        if ($1 ~ /docs\/[0-9][0-9]_/ && !lessons) { print "<p class=\"nav-group\">Lessons</p>"; lessons = 1 }
        if ($1 ~ /docs\/conventions/) print "<p class=\"nav-group\">Reference</p>"
        printf "<a href=\"ROOT%s\" data-page=\"%s\">%s</a>\n", url, url, esc($2)
    }
    END {
        print "<p class=\"nav-group\">The whole book</p>"
        print "<a href=\"ROOTbook.pdf\">PDF</a>"
        print "<a href=\"ROOTbook.epub\">EPUB</a>"
    }')

page() { # source prev_source next_source [more_markdown]
    src=$1 prev_src=$2 next_src=$3 more=${4:-}
    out=$(html_of "$src")
    root=$(root_of "$out")
    title=$(sed -n '1s/^# //p' "$src")
    [ -n "$title" ] || title=$(basename "$src" .md)
    set -- --from gfm --to html5 --standalone --template "$here/template.html" \
        --toc --toc-depth 2 --highlight-style pygments --lua-filter "$here/links.lua" \
        --metadata "pagetitle=$title" --metadata "page_url=$out" \
        --metadata "site_dir=$site" \
        --metadata "search_out=$site/search/$(printf '%s' "$out" | tr / _).json" \
        --variable "root=$root" \
        --variable "nav=$(printf '%s\n' "$nav" | sed "s#ROOT#$root#g; s#data-page=\"$out\"#data-page=\"$out\" aria-current=\"page\"#")"
    if [ -n "$prev_src" ]; then
        set -- "$@" --variable "prev_url=$root$(html_of "$prev_src")" \
            --variable "prev_title=$(sed -n '1s/^# //p' "$prev_src")"
    fi
    if [ -n "$next_src" ]; then
        set -- "$@" --variable "next_url=$root$(html_of "$next_src")" \
            --variable "next_title=$(sed -n '1s/^# //p' "$next_src")"
    fi
    mkdir -p "$site/$(dirname "$out")"
    pandoc "$@" -o "$site/$out" "$src" ${more:+"$more"}
}

# The code the book holds, before its pages, which link a file they name in
# code when the book holds it (links.lua): each lesson's files beside its
# page, and common/. The student edition holds only the files the lessons'
# pages link to (the files each inherits): a lesson's extras may show an
# earlier lesson's solution (lesson 03's naive rule is lesson 02's), and no
# page needs them.
for readme in lessons/*/README.md; do
    if [ "$edition" = student ]; then
        grep -o '](\.\./[0-9][0-9]_[a-z_0-9]*/[^)]*\.[ch])' "$readme" | sed 's#^](\.\./##; s#)$##' |
            while read -r f; do
                mkdir -p "$site/lessons/$(dirname "$f")"
                cp -p "lessons/$f" "$site/lessons/$f"
            done
        continue
    fi
    mkdir -p "$site/$(dirname "$readme")"
    cp -p "$(dirname "$readme")"/*.[ch] "$site/$(dirname "$readme")/" 2>/dev/null || true
    if [ -d "$(dirname "$readme")/extras" ]; then
        mkdir -p "$site/$(dirname "$readme")/extras"
        cp -p "$(dirname "$readme")"/extras/*.[ch] "$site/$(dirname "$readme")/extras/" 2>/dev/null || true
    fi
done
if [ "$edition" != student ]; then
    mkdir -p "$site/common/harness"
    cp -p common/*.[ch] "$site/common/"
    cp -p common/harness/*.[ch] "$site/common/harness/"
fi

# The book's pages, each with the one before and after it.
sources=$(printf '%s\n' "$book" | cut -d'|' -f1)
prev=""
set -f
for src in $sources; do
    next=$(printf '%s\n' "$sources" | awk -v s="$src" 'found { print; exit } $0 == s { found = 1 }')
    page "$src" "$prev" "$next"
    prev=$src
done
set +f
# The lessons' own pages (what each inherits, and from where), outside the
# reading order. In the full edition a lesson's page ends with a link to
# each of its own files, which the book holds beside it: a browser lists no
# directory.
files_md=$(mktemp)
for readme in lessons/*/README.md; do
    if [ "$edition" = student ]; then
        page "$readme" "" ""
        continue
    fi
    {
        printf '\n## Files of this lesson\n\nEach opens as text.\n\n'
        (cd "$(dirname "$readme")" && ls *.[ch] 2>/dev/null; ls extras/*.[ch] 2>/dev/null) |
            sed 's#.*#- [&](&)#'
    } > "$files_md"
    page "$readme" "" "" "$files_md"
done
rm -f "$files_md"
for d in images diffs examples data; do
    [ -d "docs/$d" ] && cp -Rp "docs/$d" "$site/docs/"
done
cp -p "$here/site.css" "$here/site.js" "$here/worker.js" "$site/"
# Run it here: the lessons' browser build (make wasm), the runner the page's
# worker shares with node, and the list of example files it loads.
mkdir -p "$site/wasm"
for l in lessons/[0-9][0-9]_*/main.c; do
    l=$(basename "$(dirname "$l")")
    cp -p "$wasm/$l" "$site/wasm/$l.js"
    cp -p "$wasm/$l.wasm" "$site/wasm/"
done
cp -p "$here/wasm/run.js" "$wasm/pako_deflate.min.js" "$site/wasm/"
# The files of the tree a command of the pages may read, which the page's
# worker puts in the lesson's working directory (inputs.json): the examples,
# and each expected picture of tests/expected/ a page names (--compare).
for f in $(grep -ohE 'tests/expected/[A-Za-z0-9_./-]+\.png' $sources | sort -u); do
    [ -f "$top/$f" ] || continue
    mkdir -p "$site/$(dirname "$f")"
    cp -p "$top/$f" "$site/$f"
done
{
    printf '['
    sep=''
    for f in $(find docs/examples -type f | sort) $(cd "$site" && find tests -type f 2>/dev/null | sort); do
        printf '%s"%s"' "$sep" "$f"
        sep=','
    done
    printf ']\n'
} > "$site/inputs.json"
{
    printf 'window.SEARCH_INDEX = [\n'
    cat "$site"/search/*.json | sed 's/$/,/'
    printf '];\n'
} > "$site/search-index.js"
rm -rf "$site/search"

# The whole book as one document (tools/site/book.lua keeps each page's ids
# and links apart): book.epub, and book.pdf printed by chromium from it.
mkdir -p "$site/.book"
n=0
set -f
for src in $sources; do
    n=$((n + 1))
    pandoc --from gfm --to json --lua-filter "$here/book.lua" --metadata "page=$src" \
        -o "$site/.book/$(printf '%02d' $n).json" "$src"
done
set +f
title="Hidden-surface removal, one lesson at a time"
pandoc --from json --file-scope --to epub3 --toc --toc-depth 1 --resource-path=. \
    --metadata "title=$title" --metadata lang=en -o "$site/book.epub" "$site"/.book/*.json
cp -p "$here/print.css" "$site/"
pandoc --from json --file-scope --to html5 --standalone --toc --toc-depth 1 \
    --metadata "title=$title" --metadata lang=en --css print.css \
    --variable 'header-includes=<link rel="icon" href="data:,">' \
    -o "$site/book-print.html" "$site"/.book/*.json
rm -rf "$site/.book"
profile=$(mktemp -d)
chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
    --disable-background-networking --disable-component-update --disable-sync \
    --user-data-dir="$profile" --no-pdf-header-footer --print-to-pdf="$site/book.pdf" \
    "file://$(cd "$site" && pwd)/book-print.html" >/dev/null 2>&1
rm -rf "$profile"
[ -s "$site/book.pdf" ] || { echo "site: chromium printed no book.pdf" >&2; exit 1; }
echo "site: $(find "$site" -name '*.html' | wc -l) pages in $site, and book.epub and book.pdf"
