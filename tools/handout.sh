#!/bin/sh
# handout.sh: the student's copy of the series, with one lesson to write.
#
#   sh tools/handout.sh [--only] [--dest DIR] [--build DIR] LESSON
#   (make handout LESSON=03 [DEST=dir] [ONLY=1] calls it)
#
# Writes a tree that builds and tests on its own: common/, tools/,
# the Makefile, the README, the lesson pages and the tests, and the lesson
# with each solution region (tools/solution-regions.awk says what that is)
# replaced by a TODO(student): comment and its stub. The other lessons come
# as they are, or, with --only, are left out with their tests and pages.
# Left out always: the teacher's own checks of these tools (tests/tools/,
# tests/grading/, tools/grade-check.sh), the
# teacher's guide and key (tools/teacher/), the GPU reference (tests/gpu/); the
# benchmark's limit (tests/bench/limit.c times a copy of the depth test, so
# make bench does not work in a handout: it times the finished lessons); the
# diffs that show this lesson's code (docs/diffs/*NN*); and the CI script (it
# would fail: the handout's tests fail until the work is done).
#
# Before the tree is put in place, it is searched for every line that only
# the solution has; one found there fails the handout, and nothing is written.
# Every page's link to a file the handout does not hold keeps its words alone
# (tools/md-links.awk).
#
# DEST defaults to BUILD/handout/<lesson>. An existing DEST is replaced only
# if it is empty or an earlier handout (it holds the file .handout).
# Exit status: 0 done, 1 failed (no regions, malformed marker, a solution line
# in the handout, a copy failed), 2 usage error.
set -eu

prog=handout
usage() {
    echo "$prog: error: $1" >&2
    echo "usage: make handout LESSON=NN [DEST=dir] [ONLY=1]" >&2
    exit 2
}
# The handout is built in $tmp, beside DEST; the lists of the checks in $work,
# a directory of this run's own (so that no list is left beside DEST, and no
# name in DEST, spaces and all, is ever split into words or read by awk or sed).
tmp="" work=""
clean_up() { [ -z "$tmp" ] || rm -rf "$tmp"; [ -z "$work" ] || rm -rf "$work"; }
die() {
    echo "$prog: error: $1" >&2
    clean_up
    exit 1
}

only=0
earlier=""
later=absent
dest=""
build=build
lesson=""
while [ $# -gt 0 ]; do
    case $1 in
        --only) only=1 ;;
        --earlier) [ $# -ge 2 ] || usage "--earlier wants solved, stubbed or absent"; earlier=$2; shift ;;
        --later) [ $# -ge 2 ] || usage "--later wants absent or solved"; later=$2; shift ;;
        --dest) [ $# -ge 2 ] || usage "--dest wants a directory"; dest=$2; shift ;;
        --build) [ $# -ge 2 ] || usage "--build wants a directory"; build=$2; shift ;;
        -*) usage "unknown option $1" ;;
        *) [ -z "$lesson" ] || usage "one lesson at a time (got $lesson and $1)"; lesson=$1 ;;
    esac
    shift
done
[ -n "$lesson" ] || usage "which lesson? e.g. LESSON=03"
# The other lessons: as they are (solved), with their own regions taken out
# too (stubbed), or left out (absent; --only says the same).
case $earlier in
    '') [ "$only" -eq 1 ] && earlier=absent || earlier=solved ;;
    absent) only=1 ;;
    solved|stubbed) [ "$only" -eq 0 ] || usage "--only leaves the other lessons out: not with EARLIER=$earlier" ;;
    *) usage "EARLIER=$earlier: want solved, stubbed or absent" ;;
esac
case $later in
    absent|solved) ;;
    *) usage "LATER=$later: want absent or solved" ;;
esac
[ -f Makefile ] && [ -d lessons ] && [ -d common ] ||
    usage "run it from the top of the series (where the Makefile is)"

# LESSON=03 or LESSON=03_perspective_z: exactly one lesson directory, never
# a path (tools/lesson-name.sh).
. "$(dirname "$0")/lesson-name.sh"
lesson_name LESSON "$lesson"
name=$lesson_name
number=$(echo "$name" | cut -c1-2)
awk_regions=tools/solution-regions.awk

# The files of the lesson that hold regions, and its page if it has any.
marked=""
# (extras/ included: a lesson's files are every file below its directory)
lesson_files=$(find lessons/"$name" -type f | sort | tr '\n' ' ')
for f in $lesson_files docs/"$name".md; do
    [ -f "$f" ] || continue
    if grep -Eq 'SOLUTION (BEGIN|STUB|END)' "$f"; then marked="$marked $f"; fi
done
case $marked in
    *lessons/*) ;;
    *) die "lessons/$name has no SOLUTION BEGIN marker: nothing to take out (is this already a handout?)" ;;
esac
# shellcheck disable=SC2086 # the list is of plain relative paths
awk -v mode=regions -f "$awk_regions" $marked >/dev/null ||
    die "the solution markers above are malformed; nothing was written"

[ -n "$dest" ] || dest="$build/handout/$name"
# Without its trailing slashes, but / stays / (refused below, as not empty).
while [ "${dest%/}" != "$dest" ] && [ -n "${dest%/}" ]; do dest=${dest%/}; done
if [ -e "$dest" ]; then
    [ -d "$dest" ] || usage "DEST=$dest exists and is not a directory"
    if [ ! -f "$dest/.handout" ] && [ -n "$(ls -A "$dest")" ]; then
        usage "DEST=$dest exists and is not an earlier handout: remove it or pick another DEST"
    fi
fi

# Built beside DEST, moved into place only when it is complete and checked.
parent=$(dirname "$dest")
mkdir -p "$parent" || die "cannot create $parent"
tmp="$dest.tmp.$$"
rm -rf "$tmp"
mkdir "$tmp" || die "cannot create $tmp"
work=$(mktemp -d) || die "cannot create a temporary directory"
trap 'clean_up; exit 129' HUP
trap 'clean_up; exit 130' INT
trap 'clean_up; exit 143' TERM

# copy PATH: PATH (file or directory) into the same place in the handout.
copy() {
    mkdir -p "$tmp/$(dirname "$1")" && cp -R "$1" "$tmp/$1" || die "cannot copy $1"
}

for f in Makefile README.md .gitignore .editorconfig common tools tests docs lessons; do
    if [ -e "$f" ]; then copy "$f"; fi
done
rm -rf "$tmp/tests/tools" "$tmp/tests/gpu" "$tmp/tests/bench/limit.c"
# The grader's check against the series needs the solution (make grade-check).
rm -rf "$tmp/tests/grading" "$tmp/tools/grade-check.sh"
# The teacher's material: the guide (it names every answer), the answer key
# and anything else under tools/teacher/, never in a student's tree.
rm -rf "$tmp/tools/teacher" "$tmp/docs/teaching.md"
# The diffs between lessons (docs/diffs/02_to_03.diff) show this lesson's code.
if [ -d "$tmp/docs/diffs" ]; then
    find "$tmp/docs/diffs" -name "*${number}[_.]*" -exec rm -f {} + || die "cannot leave out docs/diffs"
fi
for f in $lesson_files; do
    case " $marked " in
        *" $f "*) awk -v mode=strip -f "$awk_regions" "$f" >"$tmp/$f" ||
                      die "cannot write the handout of $f" ;;
    esac
done
case " $marked " in
    *" docs/$name.md "*)
        awk -v mode=strip -f "$awk_regions" "docs/$name.md" >"$tmp/docs/$name.md" ||
            die "cannot write the handout of docs/$name.md" ;;
esac

# The lessons after this one (LATER=absent, the default): out, with their
# tests, pages, pictures and diffs. They build on this lesson's work: its
# answers are in their code.
# (In the shell alone, no process per lesson: number_of 03_perspective_z sets
# num=3, and ${other%"${other#??}"} is its first two characters, 03.)
number_of() { num=${1%%_*}; num=${num#0}; }
number_of "$name"
this=$num
# leave_out TEST...: the files and directories under the handout's tests/ and
# docs/ that find's TEST picks, removed; one find for both.
leave_out() {
    n=$#
    for top in "$tmp/docs" "$tmp/tests"; do
        if [ -d "$top" ]; then set -- "$top" "$@"; fi
    done
    [ $# -eq "$n" ] || find "$@" -prune -exec rm -rf {} +
}
if [ "$later" = absent ]; then
    for d in lessons/*; do
        [ -d "$d" ] || continue
        other=${d#lessons/}
        number_of "$other"
        [ "$num" -gt "$this" ] 2>/dev/null || continue
        rm -rf "${tmp:?}/$d"
        two=${other%"${other#??}"}
        leave_out \( -name "*$other*" -o -name "${two}_*" -o -name "*_$two.*" \) ||
            die "cannot leave out $other"
    done
fi

# EARLIER=stubbed: every other lesson with regions gets them taken out too
# (its page as well), so that a later lesson's handout does not solve an
# earlier one.
if [ "$earlier" = stubbed ]; then
    for d in lessons/*; do
        [ -d "$d" ] || continue
        other=${d#lessons/}
        [ "$other" = "$name" ] && continue
        [ -d "$tmp/$d" ] || continue # a later lesson, left out: nothing of it to write
        for f in $(find "$d" -type f | sort) docs/"$other".md; do
            [ -f "$f" ] && grep -Eq 'SOLUTION (BEGIN|STUB|END)' "$f" || continue
            awk -v mode=strip -f "$awk_regions" "$f" >"$tmp/$f" || die "cannot write the handout of $f"
        done
    done
fi

# --only: out go the other lessons, with everything named after them: their
# tests, expected images, pages, pictures (docs/images/02_*), fuzz targets.
# Of a lesson whose files this one inherits, those files stay, solved.
# A lesson whose program this lesson's tests run (lesson 03's compare their
# naive rule with lesson 02's pictures) stays, as it is, without its tests.
needed=""
kept=""
if [ "$only" -eq 1 ]; then
    for d in lessons/*; do
        [ -d "$d" ] && [ "${d#lessons/}" != "$name" ] || continue
        if grep -q "\"${d#lessons/}\"" tests/"$name"/* 2>/dev/null; then needed="$needed ${d#lessons/}"; fi
    done
fi
# The files that the lesson, and those it keeps whole, inherit (tools/lesson-tree.sh).
inherits=$(for l in "$name" $needed; do sh tools/lesson-tree.sh list "$l" || exit 1; done) ||
    die "cannot list the files of lessons/$name"
if [ "$only" -eq 1 ]; then
    for d in lessons/*; do
        [ -d "$d" ] || continue
        other=${d#lessons/}
        [ "$other" = "$name" ] && continue
        case " $needed " in
            *" $other "*) ;;
            *) if [ -n "$(echo "$inherits" | awk -v o="$d/" 'index($2, o) == 1')" ]; then
                   # Of a lesson files are inherited from, those files only.
                   find "$tmp/$d" -type f | while read -r f; do
                       echo "$inherits" | awk -v f="${f#"$tmp/"}" '$2 == f { found = 1 } END { exit !found }' ||
                           rm -f "$f"
                   done
                   find "$tmp/$d" -depth -type d -empty -exec rmdir {} \;
                   kept="$kept $other"
               else
                   rm -rf "${tmp:?}/$d"
               fi ;;
        esac
        two=${other%"${other#??}"}
        leave_out \( -name "*$other*" -o -name "${two}_*" \) || die "cannot leave out $other"
    done
fi

# The check: no line that only the solution has is anywhere in the handout
# but in other lessons (and their pages), which the teacher chose to include
# as they are. Lines are compared as solution-regions.awk prints them:
# trimmed, without their trailing comment and final ";".
lines="$work/lines"
# All of the lesson is read: a line it has outside the regions gives nothing away.
# (The sources are the arguments: "$@", one word each, whatever DEST is.)
# shellcheck disable=SC2086 # the lesson's files: plain relative paths
set -- $lesson_files
case " $marked " in
    *" docs/$name.md "*) set -- "$@" "docs/$name.md" ;;
esac
# So is all of what it inherits, which the handout holds solved: read as the
# teacher reads it (without markers), every line of it is outside the regions.
mkdir "$work/inherited" || die "cannot create $work/inherited"
echo "$inherits" | awk -v own="lessons/$name/" 'NF == 2 && index($2, own) != 1 { print $2 }' | sort -u |
    while read -r f; do
        awk -v mode=clean -f "$awk_regions" "$f" >"$work/inherited/$(echo "$f" | tr / _)" || exit 1
    done || die "cannot read the files lessons/$name inherits"
for f in "$work"/inherited/*; do
    if [ -f "$f" ]; then set -- "$@" "$f"; fi
done
awk -v mode=lines -f "$awk_regions" "$@" >"$lines" || die "cannot list the solution lines"
files="$work/files"
(cd "$tmp" && find . -type f ! -name '*.png' ! -name '*.pfm' ! -name '*.pgm') |
    sed 's|^\./||' | while read -r f; do
        case $f in
            lessons/"$name"/*|docs/"$name".md|tests/"$name"/*) echo "$f" ;;
            # Other lessons, as the teacher chose to include them: their
            # code, pages, tests and the diffs between them (with the later
            # lessons out, all earlier ones: the student's finished work).
            lessons/*|docs/[0-9][0-9]_*|tests/[0-9][0-9]_*|docs/diffs/*) ;;
            *) echo "$f" ;;
        esac
    done >"$files"
# (Read from inside the handout, by the names the list has.)
regions_abs="$PWD/$awk_regions"
leaks=$(cd "$tmp" && tr '\n' '\0' <"$files" |
    xargs -0 -r awk -v mode=find -v lines="$lines" -f "$regions_abs" |
    awk -F '\t' '{ printf "  %s has %s (%s)\n", $1, $2, $3 }')
[ -z "$leaks" ] || { die "a line of a solution region is in the handout:
$leaks
Widen the region, or change the line outside it; nothing was written."; }

# The same, inside prose and comments: each solution expression (a solution
# line, or what it computes: after its "return" or "="), with all white space
# taken out, searched for in every file with its white space taken out too
# (and the "*", "//", "#" and ">" that begin the lines of comments and
# quotes). A comment that states the formula gives it away as surely as code.
# Both sides are also read the way a paraphrase writes them: without
# parentheses, "*" or backquotes, and with "or" and "and" for || and &&, so
# that "x > 0 or (x == 0 and y)" reads as the expression it spells out.
exprs="$work/exprs"
awk -v mode=exprs -f "$awk_regions" "$@" >"$exprs" || die "cannot list the solution expressions"
leaks=$(cd "$tmp" && awk -v exprs="$exprs" -v files="$files" -v root=. '
    function paraphrase(s) {
        gsub(/[()*`]/, "", s)
        gsub(/[|][|]/, "or", s)
        gsub(/&&/, "and", s)
        return s
    }
    BEGIN {
        while ((getline l < exprs) > 0) {
            tab = index(l, "\t")
            n++; where[n] = substr(l, 1, tab - 1); expr[n] = paraphrase(substr(l, tab + 1))
        }
        while ((getline f < files) > 0) {
            text = ""; line_no = 0; delete starts
            while ((getline l < (root "/" f)) > 0) {
                line_no++
                sub(/^[ \t]*(\/\/|\*+|#+|>+)?/, "", l)
                gsub(/[ \t\r]+/, "", l)
                l = paraphrase(l)
                starts[line_no] = length(text) + 1
                text = text l
            }
            close(root "/" f)
            for (k = 1; k <= n; k++) {
                at = index(text, expr[k])
                if (at == 0) continue
                for (ln = line_no; ln > 1 && starts[ln] > at; ln--) ;
                printf "  %s:%d has %s (%s)\n", f, ln, where[k], expr[k]
            }
        }
    }')
rm -rf "$files" "$lines" "$exprs" "$work/inherited"
[ -z "$leaks" ] || die "a solution expression is in the handout (white space aside):
$leaks
Say what to compute and why in words, not the formula; nothing was written."

# Every page as the handout holds it (tools/md-links.awk): a link to a file
# or directory that is not there (a later lesson's page, a diff that shows
# this lesson's code, the teacher's guide) keeps its words alone, a picture
# that is not there goes, and so does a row of the README's table of lessons
# whose lesson is not there.
find "$tmp" -name '*.md' -type f | while read -r f; do
    rows=0
    [ "$f" = "$tmp/README.md" ] && rows=1
    awk -v dir="$(dirname "$f")" -v mode=fix -v rows="$rows" -f tools/md-links.awk "$f" >"$f.new" &&
        mv "$f.new" "$f" || exit 1
done || die "cannot write the links of the handout's pages"

# The README's section for teachers is the student's score instead: how
# to hand out and grade is no business of the handout (nor is teaching.md
# in it).
if [ -f "$tmp/README.md" ] && ! { awk -v n="$number" '
    /^## For teachers$/ {
        print "## Your score"; print ""; print "```sh"
        print "make grade LESSON=" n "   # each test alone, weighted by tests/<lesson>/points.txt: a score table"
        print "```"; print ""
        print "`make test` shows what failed and where; `make grade` weighs each test as"
        print "your teacher does."
        print ""; skip = 1; next
    }
    skip && /^## / { skip = 0 }
    !skip' "$tmp/README.md" >"$tmp/README.md.new" && mv "$tmp/README.md.new" "$tmp/README.md"; }; then
    die "cannot write the handout's README"
fi

echo "handout of lessons/$name, made by make handout" >"$tmp/.handout"
rm -rf "$dest"
mv "$tmp" "$dest" || die "cannot move the handout to $dest"
tmp=""
clean_up

todos=$(cd "$dest" && grep -rn 'TODO(student):' "lessons/$name" "docs/$name.md" 2>/dev/null || true)
count=$(echo "$todos" | grep -c . || true)
echo "$prog: wrote $dest: lessons/$name with $count solution region(s) taken out$(
    case $earlier in absent) echo ", no other lesson" ;; stubbed) echo ", the other lessons stubbed too" ;; esac)"
echo "$todos" | sed 's/^/  /'
if [ -n "$kept" ]; then
    echo "$prog: kept, solved, the files it inherits from:$kept"
fi
if [ -n "$needed" ]; then
    echo "$prog: kept, as they are, the lessons whose programs its tests run:$needed"
fi
echo "$prog: the student runs: make test LESSON=$number   (and make grade LESSON=$number for the score)"
