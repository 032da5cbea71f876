#!/bin/sh
# setup.sh: what Gradescope runs once, as root, to build the autograder's
# image for lesson @LESSON@ (make autograder; docs/teaching.md, "Gradescope").
#
#   1. the packages the series needs (AUTOGRADER_SKIP_APT=1: already there);
#   2. the users the student's code runs as, one per test run at a time
#      (AUTOGRADER_USERS, "grader-student0 grader-student1"), with no home,
#      no shell and no group of anyone else's;
#   3. the teacher's records: every test of the lesson run on the solution
#      (make grade-reference), kept with the judge and time_limit in
#      ROOT/judge, which only root reads;
#   4. the tree each submission is graded in, ROOT/template: the lesson's
#      taught files replaced by their stubs, everything built; the expected
#      pictures, the points and the list of taught files readable by root only,
#      as are the sources of earlier lessons that this lesson does not build on
#      (their programs are built: the tests run them);
#   5. the zip as uploaded (ROOT/source, which holds the solution): root only.
# ROOT is AUTOGRADER_ROOT, /autograder by default, so that a test can build
# the image in a temporary directory (tests/tools/test_grade.c).
set -eu
lesson=@LESSON@
root=${AUTOGRADER_ROOT:-/autograder}
src=${AUTOGRADER_SOURCE:-$root/source}
users=${AUTOGRADER_USERS:-grader-student0 grader-student1}
jobs=$(set -- $users; echo $#)

if [ "${AUTOGRADER_SKIP_APT:-0}" != 1 ]; then
    apt-get update
    apt-get install -y build-essential libstb-dev zlib1g-dev libcmocka-dev pkg-config util-linux
fi

for u in $users; do
    id -u "$u" >/dev/null 2>&1 ||
        useradd --system --user-group --no-create-home --home-dir /nonexistent \
            --shell /usr/sbin/nologin "$u"
done

judge="$root/judge"
rm -rf "$judge"
mkdir -p "$judge"
chmod 700 "$judge"
cp -R "$src" "$judge/solved"
(cd "$judge/solved" && make --no-print-directory -j"$jobs" grade-reference LESSON="$lesson" \
    REFERENCE="$judge/reference")
cp "$judge/solved/build/tools/judge" "$judge/solved/build/tools/time_limit" \
    "$judge/solved/tools/autograder/sandbox.sh" "$judge/"
rm -rf "$judge/solved"

template="$root/template"
rm -rf "$template"
cp -R "$src" "$template"
rm -f "$template/setup.sh" "$template/run_autograder"
while read -r f; do
    [ -n "$f" ] || continue
    awk -v mode=strip -f "$template/tools/solution-regions.awk" "$template/lessons/$lesson/$f" \
        >"$template/lessons/$lesson/$f.stub"
    mv "$template/lessons/$lesson/$f.stub" "$template/lessons/$lesson/$f"
done <"$template/autograder/taught.txt"
# The stubs build (a failing build here is the series' fault, not a student's).
(cd "$template" && make --no-print-directory -j"$jobs" grade-build LESSON="$lesson" GRADE_WARNINGS_SHOWN=1)

for f in "$template/tests/expected" "$template/autograder" "$template"/tests/*/points.txt; do
    [ -e "$f" ] && chmod -R go-rwx "$f"
done
# Earlier lessons' sources that this lesson's tree does not hold.
(cd "$template" && sh tools/lesson-tree.sh list "$lesson") | awk '{ print $2 }' >"$judge/tree.txt"
for d in "$template"/lessons/*/; do
    d=${d%/}
    l=${d##*/}
    [ "$l" = "$lesson" ] && continue
    (cd "$template" && find "lessons/$l" -type f -name '*.c') | while read -r f; do
        grep -qxF "$f" "$judge/tree.txt" || chmod go-rwx "$template/$f"
    done
done
chmod -R go-rwx "$src"
echo "setup: lesson $lesson recorded ($(ls "$judge/reference/$lesson" | grep -c '\.obs$') test runs) and ready"
