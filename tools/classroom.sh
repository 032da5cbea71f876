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
        --dest) [ $# -ge 2 ] || { echo "classroom: error: --dest wants a file" >&2; exit 2; }
                dest=$2; shift ;;
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
# DEST is a file, written whole to a temporary name beside it and renamed
# into place: never a directory (the rename would put the file inside it) nor
# a device or a pipe (the rename would put a file in its place: DEST=/dev/full
# replaced the device); a link is followed to the file it names.
case $dest in
    '') echo "$prog: error: DEST is empty: name the file to write" >&2; exit 2 ;;
    */) echo "$prog: error: DEST=$dest ends in '/': name the file to write" >&2; exit 2 ;;
esac
if [ -L "$dest" ]; then
    dest=$(readlink -f "$dest") ||
        { echo "$prog: error: DEST is a link that leads nowhere a file can be" >&2; exit 2; }
fi
if [ -d "$dest" ]; then
    echo "$prog: error: DEST=$dest is a directory: name the file to write (e.g. $dest/tests.json)" >&2
    exit 2
elif [ -e "$dest" ] && [ ! -f "$dest" ]; then
    echo "$prog: error: DEST=$dest exists and is not a regular file" >&2
    exit 2
fi
if [ -e "$dest" ] && [ "$dest" -ef "$points" ]; then
    echo "$prog: error: DEST=$dest is $points, which the tests are read from" >&2
    exit 2
fi
dir=$(dirname "$dest")
if [ -e "$dir" ] && [ ! -d "$dir" ]; then
    echo "$prog: error: DEST=$dest: $dir is not a directory" >&2
    exit 2
fi
mkdir -p "$dir" 2>/dev/null || { echo "$prog: error: cannot create the directory $dir" >&2; exit 1; }
tmp="$dir/.${dest##*/}.tmp.$$"
( set -C; : >"$tmp" ) 2>/dev/null || { tmp=""; echo "$prog: error: cannot write in $dir" >&2; exit 1; }
trap '[ -z "$tmp" ] || rm -f "$tmp"' EXIT
trap 'exit 129' HUP
trap 'exit 130' INT
trap 'exit 143' TERM
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
    END { print "\n]" }' "$points" >"$tmp" ||
    { echo "$prog: error: cannot write $dest" >&2; exit 1; }
mv "$tmp" "$dest" || { echo "$prog: error: cannot write $dest" >&2; exit 1; }
tmp=""
echo "classroom: wrote $dest: $(($(grep -c '"run"' "$dest") - 1)) tests of $name, after its setup"
echo "classroom: gh teacher assignment add ... --tests $dest   (or paste it into the assignment form)"
