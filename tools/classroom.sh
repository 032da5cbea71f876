#!/bin/sh
# classroom.sh: Classroom 50's autograding tests of one lesson.
#
#   sh tools/classroom.sh [--dest FILE] LESSON   (make classroom LESSON=NN)
#
# Writes classroom50/tests.json (or FILE): the bare JSON array of declarative
# tests that Classroom 50 reads (gh teacher assignment add ... --tests FILE, or
# the assignment form), in its "run" type, which passes when the command
# exits 0:
#   - first "setup", 0 points: the packages (make deps) and the lesson's
#     build, going on past errors (what does not build scores 0 later);
#   - then one test per line of tests/<lesson>/points.txt with points, whose
#     command is tools/grade.sh --test NAME: it grades that one test and exits
#     0 exactly when it passed.
# Classroom 50 grades in the student's own repository, with the student's
# copy of the tests: docs/teaching.md says what that can and cannot prove.
set -eu
dest=classroom50/tests.json
lesson=""
while [ $# -gt 0 ]; do
    case $1 in
        --dest) dest=$2; shift ;;
        *) lesson=$1 ;;
    esac
    shift
done
[ -n "$lesson" ] || { echo "usage: make classroom LESSON=NN [DEST=file]" >&2; exit 2; }
# One lesson, never a path or the last of several (tools/lesson-name.sh).
prog=classroom
. "$(dirname "$0")/lesson-name.sh"
lesson_name LESSON "$lesson"
name=$lesson_name
number=$(echo "$name" | cut -c1-2)
points="tests/$name/points.txt"
[ -f "$points" ] || { echo "classroom: error: $points is missing" >&2; exit 1; }
mkdir -p "$(dirname "$dest")"
awk -v n="$number" -v lesson="$name" '
    BEGIN {
        print "["
        printf "  {\"name\": \"setup\", \"type\": \"run\", \"run\": \"make deps && make -k grade-build LESSON=%s GRADE_WARNINGS_SHOWN=1; exit 0\", \"timeout\": 600, \"points\": 0}", n
    }
    /^[ \t]*(#|$)/ { next }
    $2 + 0 > 0 {
        printf ",\n  {\"name\": \"%s\", \"type\": \"run\", \"run\": \"sh tools/grade.sh --build build --test %s %s\", \"timeout\": 120, \"points\": %s}",
            $1, $1, lesson, $2 + 0
    }
    END { print "\n]" }' "$points" >"$dest.tmp"
mv "$dest.tmp" "$dest"
echo "classroom: wrote $dest: $(($(grep -c '"run"' "$dest") - 1)) tests of $name, after its setup"
echo "classroom: gh teacher assignment add ... --tests $dest   (or paste it into the assignment form)"
