#!/bin/sh
# autograder.sh: the Gradescope autograder of one lesson, as a zip.
#
#   sh tools/autograder.sh [--build DIR] LESSON   (make autograder LESSON=NN)
#
# Writes DIR/autograder/<lesson>.zip: setup.sh and run_autograder at its top
# (tools/autograder/, with the lesson filled in), and the series beside
# them, which Gradescope unpacks into /autograder/source. autograder/taught.txt
# lists the lesson's files that hold solution regions: those, and only those,
# run_autograder takes from the submission. In: the lesson and the earlier
# ones, their tests, expected images and points, the build machinery. Out:
# later lessons and their tests (they hold what this lesson teaches), the
# pages, the teacher's material and the checks of the tools. setup.sh records
# the solution's results and then makes the unpacked zip root's alone.
set -eu
prog=autograder
build=build
lesson=""
while [ $# -gt 0 ]; do
    case $1 in
        --build) build=$2; shift ;;
        -*) echo "$prog: error: unknown option $1" >&2; exit 2 ;;
        *) lesson=$1 ;;
    esac
    shift
done
[ -n "$lesson" ] || { echo "usage: make autograder LESSON=NN" >&2; exit 2; }
# One lesson, never a path (tools/lesson-name.sh).
. "$(dirname "$0")/lesson-name.sh"
lesson_name LESSON "$lesson"
name=$lesson_name
command -v zip >/dev/null || { echo "$prog: error: make autograder needs zip (apt-get install zip)" >&2; exit 1; }

out="$build/autograder"
stage="$out/$name.stage"
rm -rf "$stage"
mkdir -p "$stage/autograder"
for f in Makefile README.md common tools tests lessons; do
    [ -e "$f" ] && cp -R "$f" "$stage/"
done
rm -rf "$stage/tests/tools" "$stage/tests/gpu" "$stage/tests/grading" "$stage/tools/grade-check.sh" \
    "$stage/docs" "$stage/tools/teacher"
# Later lessons, and their tests.
n=${name%%_*}
for d in lessons/[0-9][0-9]_*; do
    l=${d#lessons/}
    m=${l%%_*}
    if [ "${m#0}" -gt "${n#0}" ]; then
        rm -rf "$stage/lessons/$l" "$stage/tests/$l"
    fi
done
(cd "lessons/$name" && grep -rlE 'SOLUTION BEGIN' . | sed 's|^\./||' | sort) >"$stage/autograder/taught.txt"
[ -s "$stage/autograder/taught.txt" ] || { echo "$prog: error: lessons/$name has no solution region" >&2; exit 1; }
sed "s/@LESSON@/$name/g" tools/autograder/run_autograder >"$stage/run_autograder"
sed "s/@LESSON@/$name/g" tools/autograder/setup.sh >"$stage/setup.sh"
chmod +x "$stage/run_autograder" "$stage/setup.sh"
rm -f "$out/$name.zip"
(cd "$stage" && zip -qr "../$name.zip" .)
taught=$(tr '\n' ' ' <"$stage/autograder/taught.txt")
rm -rf "$stage"
echo "$prog: wrote $out/$name.zip: upload it to Gradescope as the autograder."
echo "$prog: students submit $taught(at the top, or under lessons/$name/)"
