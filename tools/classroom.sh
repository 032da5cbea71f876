#!/bin/sh
# classroom.sh: GitHub Classroom's autograding configuration of one lesson.
#
#   sh tools/classroom.sh [--dest FILE] LESSON   (make classroom LESSON=NN)
#
# Writes .github/classroom/autograding.json (or FILE): one test per line of
# tests/<lesson>/points.txt with points, each "make grade LESSON=NN TEST=name",
# which exits 0 exactly when that test passed (tools/grade.sh).
set -eu
dest=.github/classroom/autograding.json
lesson=""
while [ $# -gt 0 ]; do
    case $1 in
        --dest) dest=$2; shift ;;
        *) lesson=$1 ;;
    esac
    shift
done
[ -n "$lesson" ] || { echo "usage: make classroom LESSON=NN" >&2; exit 2; }
name=""
for d in lessons/"$lesson"*; do [ -d "$d" ] && name=${d#lessons/}; done
[ -n "$name" ] || { echo "classroom: error: no lesson LESSON=$lesson in lessons/" >&2; exit 2; }
number=$(echo "$name" | cut -c1-2)
points="tests/$name/points.txt"
[ -f "$points" ] || { echo "classroom: error: $points is missing" >&2; exit 1; }
mkdir -p "$(dirname "$dest")"
awk -v n="$number" '
    /^[ \t]*(#|$)/ { next }
    $2 + 0 > 0 {
        printf "%s    {\"name\": \"%s\", \"setup\": \"%s\", \"run\": \"make grade LESSON=%s TEST=%s\", \"input\": \"\", \"output\": \"\", \"comparison\": \"included\", \"timeout\": 10, \"points\": %s}",
            count++ ? ",\n" : "", $1, count == 1 ? "sudo apt-get update && sudo apt-get install -y libstb-dev zlib1g-dev libcmocka-dev pkg-config" : "", n, $1, $2 + 0
    }
    BEGIN { print "{\"tests\": [" }
    END { print "\n]}" }' "$points" >"$dest.tmp"
mv "$dest.tmp" "$dest"
echo "classroom: wrote $dest: $(grep -c '"run"' "$dest") tests of $name"
