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
# Prints one line a lesson and exits 1 if a lesson's neutered handout scores
# more than its untouched one, or its records cannot be made.
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
exit "$status"
