#!/bin/sh
# grade-check.sh: the grader, tried against the series itself.
#
#   sh tools/grade-check.sh [--build DIR] [LESSON_DIR_NAME...]   (make grade-check)
#
# For each lesson (by default every lesson with a points file), in a copy of
# this tree under DIR/grade-check:
#   1. the teacher's records, made from this tree (make grade-reference):
#      the solution must pass every test;
#   2. the untouched handout (the lesson's own solution regions replaced by
#      their stubs), judged against them;
#   3. the same handout with the test framework's checks neutered
#      (tests/grading/neutered_checks.c: every check records what it saw but
#      none fails), judged against them: it must score no more than 2.
# Then, once:
#   4. lesson 02's solution with a debug print in its depth test, one line
#      a fragment: it must score full marks, its output cut short; lessons 01,
#      04 and 05, whose tests read what their program writes to stderr, with
#      a debug print there: full marks too; and lesson
#      02 with all but depth_test() written: it must score the points of
#      every test whose line in points.txt does not name depth_test();
#   5. every lesson's solution judged while another process keeps every core
#      busy, as many tests at a time as there are cores: full marks;
#   6. the default handout of the last lesson (every earlier lesson solved,
#      the last stubbed) builds;
#   7. the handout of the last lesson with EARLIER=stubbed (every lesson
#      stubbed), graded as a student grades it: every lesson scores 0.
# Prints a table and exits 1 if any of these does not hold, or the records
# cannot be made.
set -u
prog=grade-check
build=build
while [ $# -gt 0 ]; do
    case $1 in
        --build) build=$2; shift 2 ;;
        -*) echo "$prog: error: unknown option $1" >&2; exit 2 ;;
        *) break ;;
    esac
done
if [ $# -eq 0 ]; then
    for d in tests/[0-9][0-9]_*/points.txt; do
        [ -f "$d" ] || continue
        d=${d%/points.txt}
        set -- "$@" "${d#tests/}"
    done
fi
here=$(pwd)
case $build in
    /*) abs_build=$build ;;
    *) abs_build="$here/$build" ;;
esac
work="$abs_build/grade-check"
records="$work/reference"
copy="$work/tree"
mkdir -p "$work" || exit 1

score_of() { # score_of LOG LESSON: "got/max" from grade.sh's table
    sed -n "s/^  $2: \([0-9.]*\/[0-9.]*\)\$/\1/p" "$1" | tail -n 1
}

# judged_in_copy TAG LESSON: the copy's lesson as it is now, built and judged
# against the records into $work/TAG.LESSON.log; then the lesson put back.
judged_in_copy() {
    (
        cd "$copy" || exit 1
        make --no-print-directory -k grade-build LESSON="${2%%_*}" GRADE_WARNINGS_SHOWN=1 \
            >"$work/$1.$2.build.log" 2>&1
        GRADE_TOOLS="$abs_build/tools" sh tools/grade.sh --build build --reference "$records" "$2" \
            >"$work/$1.$2.log" 2>&1
    )
    rm -rf "$copy/lessons/$2"
    cp -R "lessons/$2" "$copy/lessons/$2"
}

# 1. The teacher's records, every lesson at once.
rm -rf "$records"
for l in "$@"; do
    if ! make --no-print-directory grade-reference LESSON="${l%%_*}" REFERENCE="$records" \
            BUILD="$build" >"$work/reference.$l.log" 2>&1; then
        cat "$work/reference.$l.log"
        echo "$prog: error: the teacher's solution of $l could not be recorded (above)" >&2
        exit 1
    fi
done

# 2. and 3. in a copy of the tree, one lesson stubbed at a time.
rm -rf "$copy"
mkdir -p "$copy"
tar --exclude=./build --exclude=./out --exclude=./.git -cf - . | (cd "$copy" && tar -xf -) || exit 1
status=0
printf '%-24s %10s %10s %10s\n' lesson teacher handout neutered
for l in "$@"; do
    rm -rf "$copy/lessons/$l"
    cp -R "lessons/$l" "$copy/lessons/$l"
    for f in $(cd "$copy" && grep -rlE 'SOLUTION BEGIN' "lessons/$l" | sort); do
        awk -v mode=strip -f tools/solution-regions.awk "$copy/$f" >"$copy/$f.stub" &&
            mv "$copy/$f.stub" "$copy/$f" || exit 1
    done
    teacher=$(score_of "$work/reference.$l.log" "$l")
    (
        cd "$copy" || exit 1
        make --no-print-directory -k grade-build LESSON="${l%%_*}" GRADE_WARNINGS_SHOWN=1 \
            >"$work/handout.$l.build.log" 2>&1
        GRADE_TOOLS="$abs_build/tools" sh tools/grade.sh --build build --reference "$records" "$l" \
            >"$work/handout.$l.log" 2>&1
        make --no-print-directory -k grade-build LESSON="${l%%_*}" GRADE_WARNINGS_SHOWN=1 \
            BUILD=build-neutered OBSERVE_OBJ=build-neutered/obj/tests/grading/neutered_checks.o \
            >"$work/neutered.$l.build.log" 2>&1
        GRADE_TOOLS="$abs_build/tools" sh tools/grade.sh --build build-neutered --reference "$records" "$l" \
            >"$work/neutered.$l.log" 2>&1
    )
    handout=$(score_of "$work/handout.$l.log" "$l")
    neutered=$(score_of "$work/neutered.$l.log" "$l")
    printf '%-24s %10s %10s %10s\n' "$l" "${teacher:-?}" "${handout:-?}" "${neutered:-?}"
    if [ -z "$handout" ] || [ -z "$neutered" ] ||
        awk -v a="${neutered%/*}" -v b="${handout%/*}" 'BEGIN { exit !(a > b) }'; then
        echo "$prog: $l: the neutered handout scores more than the untouched one; the tests it passes:" >&2
        grep '^  PASS' "$work/neutered.$l.log" | grep -v ' 0/0 ' >&2
        status=1
    fi
    rm -rf "$copy/lessons/$l"
    cp -R "lessons/$l" "$copy/lessons/$l"
done
[ "$status" -eq 0 ] && echo "$prog: no neutered handout scores more than the untouched one"

# 4. A correct solution that prints a line for every fragment (lesson 02's
# depth test, to stderr): full marks, its output cut short.
case " $* " in *" 02_zbuffer "*)
    l=02_zbuffer
    f="$copy/lessons/$l/raster.c"
    awk '{ print } /bool passed = d < stored;/ && !done {
             print "    fprintf(stderr, \"fragment %zu face %d d %g\\n\", i, face, (double)d);"; done = 1 }
         END { if (!done) exit 1 }' "lessons/$l/raster.c" >"$f.tmp" &&
        { echo '#include <stdio.h>'; cat "$f.tmp"; } >"$f" && rm -f "$f.tmp" ||
        { echo "$prog: error: no place for a debug print in lessons/$l/raster.c" >&2; exit 1; }
    judged_in_copy debug "$l"
    teacher=$(score_of "$work/reference.$l.log" "$l")
    debug=$(score_of "$work/debug.$l.log" "$l")
    cut=$(grep -l 'more bytes of output: cut at' "$copy"/build/grade/$l/run/*.log 2>/dev/null | wc -l)
    echo "$prog: $l with a debug print per fragment: ${debug:-?} (the solution: $teacher), $cut logs cut short"
    if [ "$debug" != "$teacher" ] || [ "$cut" -eq 0 ]; then
        echo "$prog: error: a correct solution with a debug print lost points (or no log was cut):" >&2
        grep '^  FAIL' "$work/debug.$l.log" | grep -v ' 0/0 ' >&2
        status=1
    fi ;;
esac

# 4a. The same print to stderr where a lesson's tests run its program and
# read what it wrote there (lessons 01, 04, 05): a line that is not the
# program's own message costs nothing.
for spec in "01_ybuffer ybuffer.c yb->y[x] = YBUFFER_CLEARED; fprintf(stderr, \"cleared %d\\n\", x);" \
    "04_scanline_inverse_z depth_buffer.c bool passed = inv_d > stored; fprintf(stderr, \"fragment %zu 1/d %g\\n\", i, (double)inv_d);" \
    "05_clipping clip.c double s = d_in / (d_in - d_out); fprintf(stderr, \"crossing at %g\\n\", s);"; do
    l=${spec%% *}
    case " $* " in *" $l "*) ;; *) continue ;; esac
    rest=${spec#* }
    file=${rest%% *}
    rest=${rest#* }
    anchor=${rest%%;*}
    line=${rest#*; }
    f="$copy/lessons/$l/$file"
    # (through the environment: awk -v would read the \n of the line as a newline)
    DEBUG_ANCHOR="$anchor;" DEBUG_LINE="$line" awk '
        { print } index($0, ENVIRON["DEBUG_ANCHOR"]) && !done { print "    " ENVIRON["DEBUG_LINE"]; done = 1 }
        END { if (!done) exit 1 }' "lessons/$l/$file" >"$f.tmp" &&
        { echo '#include <stdio.h>'; cat "$f.tmp"; } >"$f" && rm -f "$f.tmp" ||
        { echo "$prog: error: no place for a debug print in lessons/$l/$file" >&2; exit 1; }
    judged_in_copy stderr "$l"
    teacher=$(score_of "$work/reference.$l.log" "$l")
    debug=$(score_of "$work/stderr.$l.log" "$l")
    echo "$prog: $l with a debug print to stderr: ${debug:-?} (the solution: $teacher)"
    if [ "$debug" != "$teacher" ]; then
        echo "$prog: error: a correct solution with a debug print to stderr lost points:" >&2
        grep '^  FAIL' "$work/stderr.$l.log" | grep -v ' 0/0 ' >&2
        status=1
    fi
done

# 4b. Partial credit: lesson 02 with every function written but depth_test()
# (its two regions stubbed) scores the points of every test whose points.txt
# line does not name depth_test(): the coverage tests count on their own.
case " $* " in *" 02_zbuffer "*)
    l=02_zbuffer
    f="$copy/lessons/$l/raster.c"
    awk '/^inline bool depth_test/ { rest = 1 } !rest { print }' "lessons/$l/raster.c" >"$f"
    awk '/^inline bool depth_test/ { rest = 1 } rest { print }' "lessons/$l/raster.c" >"$f.tail"
    awk -v mode=strip -f tools/solution-regions.awk "$f.tail" >>"$f" && rm -f "$f.tail" ||
        { echo "$prog: error: cannot stub depth_test() alone" >&2; exit 1; }
    judged_in_copy partial "$l"
    partial=$(score_of "$work/partial.$l.log" "$l")
    want=$(awk '!/^[ \t]*(#|$)/ && $0 !~ /depth_test\(\)/ { s += $2 } END { print s }' "tests/$l/points.txt")
    echo "$prog: $l with all but depth_test() written: ${partial:-?} (the tests that do not need it: $want)"
    if [ "${partial%/*}" != "$want" ]; then
        echo "$prog: error: partial credit does not match the points file's lines" >&2
        grep '^  \(PASS\|FAIL\)' "$work/partial.$l.log" | grep -v ' 0/0 ' >&2
        status=1
    fi ;;
esac

# 5. The teacher's solution of every lesson, judged while every core is busy
# with another process, as many tests at a time as there are cores: full marks.
cores=$(nproc 2>/dev/null || echo 2)
hogs=""
i=0
while [ "$i" -lt "$cores" ]; do
    sh -c 'while :; do :; done' &
    hogs="$hogs $!"
    i=$((i + 1))
done
trap 'kill $hogs 2>/dev/null' EXIT
GRADE_JOBS=$cores sh tools/grade.sh --build "$build" --reference "$records" "$@" >"$work/busy.log" 2>&1
kill $hogs 2>/dev/null
trap - EXIT
for l in "$@"; do
    teacher=$(score_of "$work/reference.$l.log" "$l")
    busy=$(score_of "$work/busy.log" "$l")
    if [ "$busy" != "$teacher" ]; then
        echo "$prog: error: $l scored ${busy:-?} on a busy machine, the solution scores $teacher" >&2
        status=1
    fi
done
[ "$status" -eq 0 ] && echo "$prog: on a machine kept busy on all $cores cores, every lesson's solution scores full marks"

# 6. The default handout of the last lesson builds: every earlier lesson as it
# is and the last one stubbed (test_handout builds each lesson's stubs alone).
last=""
for l in "$@"; do last=$l; done
h="$work/handout"
rm -rf "$h"
if sh tools/handout.sh --dest "$h" "$last" >"$work/handout.log" 2>&1 &&
    (cd "$h" && make --no-print-directory -j"$cores" >>"$work/handout.log" 2>&1); then
    echo "$prog: the default handout of $last builds"
else
    tail -n 20 "$work/handout.log" >&2
    echo "$prog: error: the default handout of $last does not build (above)" >&2
    status=1
fi

# 7. The handout of the last lesson with the earlier ones stubbed too
# (EARLIER=stubbed): every lesson's work taken out at once, built as make
# grade builds it and graded by the test programs themselves, as a student's
# make grade grades. Every lesson scores 0: a test that compares a lesson
# with an earlier one passes no more when both draw nothing.
h="$work/handout-stubbed"
rm -rf "$h"
if sh tools/handout.sh --earlier stubbed --dest "$h" "$last" >"$work/stubbed.log" 2>&1 &&
    (cd "$h" && make --no-print-directory -j"$cores" -k grade-build GRADE_WARNINGS_SHOWN=1 &&
        sh tools/grade.sh --build build "$@") >>"$work/stubbed.log" 2>&1; then
    scored=$(sed -n 's/^  \([0-9][0-9]_[a-z_]*\): \([0-9.]*\)\/[0-9.]*$/\1 \2/p' "$work/stubbed.log" |
        awk '$2 != 0 { printf " %s", $1 }')
    graded=$(grep -c '^  [0-9][0-9]_[a-z_]*: [0-9.]*/[0-9.]*$' "$work/stubbed.log")
    if [ -n "$scored" ] || [ "$graded" -ne "$#" ]; then
        grep '^  PASS' "$work/stubbed.log" | grep -v ' 0/0 ' >&2
        echo "$prog: error: with every lesson stubbed, $graded of $# lessons graded, and these scored points:${scored:- none} (above)" >&2
        status=1
    else
        echo "$prog: with every lesson stubbed (the handout of $last, EARLIER=stubbed), all $graded lessons score 0"
    fi
else
    tail -n 20 "$work/stubbed.log" >&2
    echo "$prog: error: the handout of $last with EARLIER=stubbed could not be graded (above)" >&2
    status=1
fi
exit "$status"
