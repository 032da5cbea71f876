#!/bin/sh
# grade.sh: the score of the lessons' tests, as a table and as results.json.
#
#   sh tools/grade.sh --build DIR [--time-limit SECONDS] LESSON_DIR_NAME...
#   (make grade [LESSON=NN] builds the tests, then calls it)
#
# Points come from tests/<lesson>/points.txt, one test a line:
#     <test name>  <points>  [visible|hidden|after_due_date|after_published]  <what it checks>
# (# starts a comment; the visibility is Gradescope's, visible by default). A
# test that the file does not list still runs and is shown, but counts 0
# points; a listed test that never ran (its binary did not build, or no
# binary has it) scores 0.
#
# Every test runs alone, in a process of its own (TEST_FILTER), under the
# time limit: a crash, an exit or a hang costs the points of that test only.
# The limit is CPU time (TIME_LIMIT seconds, 10 by default, or five times
# what the teacher's solution took when judged against a reference), so that
# a busy machine costs no points; three times as much wall-clock time stops a
# test that waits for ever.
# Whether it passed is never read from what it printed: the process runs the
# student's code, which can print anything. It is the exit status and a line
# with a number drawn at random for that run, which only the test framework
# writes, into a file of its own, after cmocka has run the test to its end
# (tests/support/test_hooks.c; docs/teaching.md says what this guards
# against and what it does not). UPDATE_EXPECTED is taken out of the
# environment, and the tests never update an expected image while graded.
# TOTAL_TIME_LIMIT=seconds bounds the whole grading.
#
# Writes DIR/grade/results.json in the format of the Gradescope autograder
# (tests[] with name, score, max_score, status, output; the overall score),
# and the output of each test under DIR/grade/<lesson>/.
# Exit status: 0 when grading worked (whatever the score), 1 when it could
# not (a malformed points file, a missing tool), 2 usage error.
#
# --test NAME (make grade TEST=name) grades that one test, run alone in each
# test program; the exit status is then 0 if it passed and 1 if not, so that
# a CI step per test can give it its points (Classroom 50, docs/teaching.md).
#
# Who decides that a test passed. Without --reference, the test program
# itself, as above: the student's own feedback, on a machine the student
# controls. With --reference DIR, a judge that holds no student code
# (tools/judge.c): each test program runs observed (tests/support/observe.h),
# and the judge compares what its checks saw with DIR/<lesson>/<program>.<test>.obs,
# the record of the same test run on the teacher's solution; what the program
# prints, exits with or claims is not a verdict. --record DIR makes those
# records, from a tree that holds the teacher's solution: every test must pass
# there, judged against its own record, or nothing is recorded for the lesson.
# (The autograder records at setup and judges each submission: tools/autograder/.)
#
# Where the student's code runs, when the grader gives it no power (the
# autograder does; docs/teaching.md):
#   GRADE_DIR          where the grader keeps its files (default DIR/grade)
#   GRADE_TOOLS        where time_limit and judge are (default DIR/tools)
#   GRADE_SANDBOX      a script (tools/autograder/sandbox.sh) that runs each
#                      test program as an unprivileged user, one per slot of
#                      GRADE_JOBS, gives it its output directory first, ends
#                      every process of that user after, and names the user
#                      whose pictures the judge accepts
set -u

prog=grade
build=build
limit=${TIME_LIMIT:-10}
only_test=""
mode=self
records=""
check_only=0
while [ $# -gt 0 ]; do
    case $1 in
        --check) check_only=1; shift ;;
        --build) build=$2; shift 2 ;;
        --time-limit) limit=$2; shift 2 ;;
        --test) only_test=$2; shift 2 ;;
        --record) mode=record; records=$2; shift 2 ;;
        --reference) mode=reference; records=$2; shift 2 ;;
        -*) echo "$prog: error: unknown option $1" >&2; exit 2 ;;
        *) break ;;
    esac
done
if [ $# -eq 0 ]; then
    echo "$prog: error: no lesson to grade" >&2
    echo "usage: make grade [LESSON=NN] [TEST=name] [TIME_LIMIT=seconds per test]" >&2
    exit 2
fi
if [ "$mode" = record ] && [ -n "$only_test" ]; then
    echo "$prog: error: --record records every test of a lesson, not --test $only_test" >&2
    exit 2
fi
case $limit in
    ''|*[!0-9]*|0) echo "$prog: error: TIME_LIMIT=$limit: want a whole number of seconds, at least 1" >&2; exit 2 ;;
esac
# --check (make grade, before it removes and rebuilds the tests): the
# command line and the records only, so that a bad TIME_LIMIT=, TEST= or
# REFERENCE= is said at once, not after minutes of building.
if [ "$check_only" -eq 1 ]; then
    if [ "$mode" = reference ] && [ ! -d "$records" ]; then
        echo "$prog: error: no records of the teacher's solution in $records (make them with --record)" >&2
        exit 1
    fi
    # (as below: every lesson graded must list the test)
    for lesson in "$@"; do
        [ -n "$only_test" ] && [ -f "tests/$lesson/points.txt" ] || continue
        if ! awk -v t="$only_test" '!/^[ \t]*(#|$)/ && $1 == t { found = 1 } END { exit !found }' \
            "tests/$lesson/points.txt"; then
            echo "$prog: error: no test $only_test in tests/$lesson/points.txt" >&2
            exit 2
        fi
    done
    exit 0
fi
jobs=${GRADE_JOBS:-$(nproc 2>/dev/null || getconf _NPROCESSORS_ONLN 2>/dev/null || echo 1)}
case $jobs in
    ''|*[!0-9]*|0) jobs=1 ;;
esac

tools=${GRADE_TOOLS:-$build/tools}
time_limit="$tools/time_limit"
[ -x "$time_limit" ] || { echo "$prog: error: $time_limit is missing (make tools builds it)" >&2; exit 1; }
GRADE_JUDGE="$tools/judge"
if [ "$mode" != self ]; then
    [ -x "$GRADE_JUDGE" ] || { echo "$prog: error: $GRADE_JUDGE is missing (make tools builds it)" >&2; exit 1; }
    case $records in
        /*) ;;
        *) records="$(pwd)/$records" ;;
    esac
    if [ "$mode" = reference ] && [ ! -d "$records" ]; then
        echo "$prog: error: no records of the teacher's solution in $records (make them with --record)" >&2
        exit 1
    fi
    # --record replaces DIR/<lesson> whole: only records are replaced (what
    # --record writes: check/, *.obs, *.cpu). REFERENCE=tests replaced
    # tests/<lesson>, the lesson's tests, by its records.
    if [ "$mode" = record ]; then
        for lesson in "$@"; do
            [ -e "$records/$lesson" ] || [ -L "$records/$lesson" ] || continue
            other=$(cd "$records/$lesson" 2>/dev/null && for f in * .[!.]*; do
                        case $f in '*'|'.[!.]*'|check|*.obs|*.cpu) ;; *) echo "$f"; break ;; esac
                    done) || other="?"
            if [ -L "$records/$lesson" ] || [ ! -d "$records/$lesson" ] || [ -n "$other" ]; then
                echo "$prog: error: $records/$lesson exists and is not records of the teacher's solution (it holds ${other:-something else}): pick another REFERENCE" >&2
                exit 2
            fi
        done
    fi
fi
gdir=${GRADE_DIR:-$build/grade}
mkdir -p "$gdir" || exit 1
start=$(date +%s)
# TOTAL_TIME_LIMIT=seconds: the whole grading ends by then, whatever the code
# does (a test started later gets what is left; none starts after it).
total_limit=${TOTAL_TIME_LIMIT:-}
case $total_limit in
    '') GRADE_DEADLINE="" ;;
    *[!0-9]*) echo "$prog: error: TOTAL_TIME_LIMIT=$total_limit: want whole seconds" >&2; exit 2 ;;
    *) GRADE_DEADLINE=$((start + total_limit)) ;;
esac
# GRADE_DEADLINE_AT=seconds since the epoch: the same, set by the caller
# (the autograder, which counts the build too).
case ${GRADE_DEADLINE_AT:-} in
    ''|*[!0-9]*) ;;
    *) if [ -z "$GRADE_DEADLINE" ] || [ "$GRADE_DEADLINE_AT" -lt "$GRADE_DEADLINE" ]; then
           GRADE_DEADLINE=$GRADE_DEADLINE_AT
       fi ;;
esac
# Where each run's nonce and result files go: a directory of random name.
GRADE_PRIVATE=$(mktemp -d "${TMPDIR:-/tmp}/grade.XXXXXXXXXX") || { echo "$prog: error: no temporary directory" >&2; exit 1; }
trap 'rm -rf "$GRADE_PRIVATE"' EXIT
# Each test's TEST_OUTPUT is GRADE_OUTPUT/<program>.<test>: under the build
# by default; GRADE_TEST_OUTPUT=dir puts them elsewhere (the autograder: in a
# directory of root's, out of the student's build).
export GRADE_DEADLINE GRADE_PRIVATE GRADE_LIMIT="$limit" GRADE_BUILD="$build"
export GRADE_OUTPUT="${GRADE_TEST_OUTPUT:-$build/test-output/grade}"
export GRADE_MODE="$mode" GRADE_RECORDS="$records" GRADE_JUDGE
GRADE_LOG_MAX=${GRADE_LOG_MAX:-1048576}
case $GRADE_LOG_MAX in
    ''|*[!0-9]*|0) echo "$prog: error: GRADE_LOG_MAX=$GRADE_LOG_MAX: want a number of bytes" >&2; exit 2 ;;
esac
export GRADE_LOG_MAX
export GRADE_SANDBOX="${GRADE_SANDBOX:-}"
rm -rf "$GRADE_OUTPUT"
export BIN_DIR="$build/bin" TOOL_DIR="$build/tools" TEST_OUTPUT="$build/test-output"

# What a status of time_limit says about a run that did not finish a test.
why_unfinished() { # why_unfinished STATUS
    case $1 in
        124) echo "did not finish in time: an endless wait?" ;;
        152) echo "used more than its CPU time: an endless loop? (TIME_LIMIT=$limit)" ;;
        127|125) echo "could not be run (status $1)" ;;
        *) if [ "$1" -gt 128 ]; then
               sig=$(($1 - 128))
               if signame=$(kill -l "$sig" 2>/dev/null); then signame=SIG$signame; else signame="signal $sig"; fi
               case $signame in
                   SIGSEGV|SIGBUS) what=", a bad memory access" ;;
                   SIGABRT) what=", abort() or a failed assert()" ;;
                   SIGFPE) what=", an arithmetic error" ;;
                   *) what="" ;;
               esac
               echo "crashed: killed by $signame$what"
           else
               echo "the test program exited (status $1) in the middle of this test"
           fi ;;
    esac
}

# JSON string escaping, for results.json. A table from each character that
# JSON wants escaped to its escape, applied one character at a time: gsub's
# handling of "\\" in replacements differs between awks.
json_awk='
    BEGIN {
        for (i = 1; i < 32; i++) esc[sprintf("%c", i)] = sprintf("\\u%04x", i)
        esc["\\"] = "\\\\"; esc["\""] = "\\\""
        esc["\n"] = "\\n"; esc["\t"] = "\\t"; esc["\r"] = "\\r"
    }
    function json(s,    out, i, c, n) {
        out = ""; n = length(s)
        for (i = 1; i <= n; i++) { c = substr(s, i, 1); out = out ((c in esc) ? esc[c] : c) }
        return "\"" out "\""
    }'

# What the compiler said (errors and warnings, with their source lines), for
# the student: make grade writes the build's output to build.log.
compiler="$gdir/compiler.txt"
: >"$compiler"
if [ -f "$gdir/build.log" ]; then
    LC_ALL=C grep -E ': (fatal error|error|warning|note):|^ +[0-9]* \| |^ +\| ' "$gdir/build.log" |
        head -n 200 | LC_ALL=C tr -d '\000' | LC_ALL=C tr '\200-\377' '?' >"$compiler"
fi
tests_json="$gdir/tests.json.part"
summary="$gdir/summary.txt"
: >"$tests_json"
: >"$summary"
status=0
total=0
total_max=0
first_test=1

for lesson in "$@"; do
    points="tests/$lesson/points.txt"
    ldir="$gdir/$lesson"
    rm -rf "$ldir"
    mkdir -p "$ldir"
    if [ ! -f "$points" ]; then
        echo "$prog: error: $points is missing: it gives each test of $lesson its points (see docs/teaching.md)" >&2
        status=1
        continue
    fi
    # The points file, checked: "name<tab>points<tab>what" in $ldir/points.
    if ! awk -v file="$points" '
        /^[ \t]*(#|$)/ { next }
        {
            name = $1; pts = $2; vis = "visible"
            what = $0; sub(/^[ \t]*[^ \t]+[ \t]+[^ \t]+[ \t]*/, "", what)
            if ($3 ~ /^(visible|hidden|after_due_date|after_published)$/) {
                vis = $3; sub(/^[^ \t]+[ \t]*/, "", what)
            }
            if (name !~ /^[A-Za-z_][A-Za-z0-9_]*$/) { bad = "a test name, a C identifier" }
            else if (pts !~ /^[0-9]+(\.[0-9]+)?$/) { bad = "points: a number, 0 or more" }
            else if (what == "") { bad = "a few words on what the test checks" }
            else if (name in seen) { bad = "each test once (it was on line " seen[name] ")" }
            if (bad != "") {
                printf "%s:%d: want \"<test name> <points> <what it checks>\": %s\n", file, FNR, bad > "/dev/stderr"
                exit 1
            }
            seen[name] = FNR
            printf "%s\t%s\t%s\t%s\n", name, pts, what, vis
        }' "$points" >"$ldir/points"; then
        echo "$prog: error: $points is malformed; $lesson not graded" >&2
        status=1
        continue
    fi
    if [ -n "$only_test" ]; then
        # TEST=name: that test alone (run by itself in each test program).
        awk -F '\t' -v t="$only_test" '$1 == t' "$ldir/points" >"$ldir/points.one"
        if [ ! -s "$ldir/points.one" ]; then
            echo "$prog: error: no test $only_test in $points" >&2
            status=2
            continue
        fi
        mv "$ldir/points.one" "$ldir/points"
    fi

    missing=""
    export GRADE_LDIR="$ldir" GRADE_LESSON="$lesson"
    # Which program has which test: each built program lists its tests
    # (GRADE_LIST=1, test_hooks.c), running none. A list only says where to
    # look: a test's result never comes from what a program prints. Judged
    # against records, the records say it: the student's programs are not asked.
    : >"$ldir/where"       # test <tab> binary
    : >"$ldir/bins"
    if [ "$mode" = record ]; then
        rm -rf "$records/$lesson.new"
        mkdir -p "$records/$lesson.new" || { echo "$prog: error: cannot write $records" >&2; exit 1; }
    fi
    if [ "$mode" = reference ]; then
        if [ ! -d "$records/$lesson" ]; then
            echo "$prog: error: no records of the teacher's solution of $lesson in $records" >&2
            status=1
            continue
        fi
        for f in "$records/$lesson"/*.obs; do
            [ -f "$f" ] || continue
            b=${f##*/}
            b=${b%.obs}
            printf '%s\t%s\n' "${b#*.}" "${b%%.*}"
        done >"$ldir/where"
        cut -f 2 "$ldir/where" | sort -u >"$ldir/bins"
        # A test of the points file with no record cannot be judged: the
        # records are not the teacher's whole run (not the student's zero).
        lacking=$(awk -F '\t' 'FILENAME == ARGV[1] { have[$1] = 1; next } !($1 in have) { printf " %s", $1 }' \
                      "$ldir/where" "$ldir/points")
        if [ -n "$lacking" ]; then
            echo "$prog: error: the records in $records/$lesson have no record of:$lacking; $lesson not graded (make grade-reference)" >&2
            status=1
            continue
        fi
        while read -r bin; do
            [ -x "$build/tests/$lesson/$bin" ] || missing="$missing $bin"
        done <"$ldir/bins"
    fi
    for src in tests/"$lesson"/test_*.c; do
        [ "$mode" != reference ] || break
        [ -f "$src" ] || continue
        bin=$(basename "$src" .c)
        exe="$build/tests/$lesson/$bin"
        if [ ! -x "$exe" ]; then
            missing="$missing $bin"
            continue
        fi
        echo "$bin" >>"$ldir/bins"
        GRADE_LIST=1 TEST_FILTER="" "$time_limit" "$limit" "$exe" 2>/dev/null |
            LC_ALL=C sed -n 's/^GRADE_LIST \([A-Za-z_][A-Za-z0-9_]*\)$/\1/p' |
            while read -r t; do printf '%s\t%s\n' "$t" "$bin"; done >>"$ldir/where"
    done
    # The runs: each listed test (and each test a program lists) alone, in
    # each program that lists it.
    # (and in each program that listed nothing: it could not say). One awk
    # for all the names: "<binary> <test>" per run, names in the order of the
    # points file then of the lists, binaries in the order of the lists.
    awk -F '\t' -v only="$only_test" '
        FILENAME == ARGV[1] { if (!($1 in seen)) { seen[$1] = 1; names[++n] = $1 }; next }
        FILENAME == ARGV[2] { if (!($1 in seen)) { seen[$1] = 1; names[++n] = $1 }
                              where[$1] = where[$1] " " $2; listed[$2] = 1; next }
        !($1 in listed) { silent = silent " " $1 }
        END {
            for (i = 1; i <= n; i++) {
                if (only != "" && names[i] != only) continue
                k = split(where[names[i]] silent, bins, " ")
                for (j = 1; j <= k; j++) printf "%s %s\n", bins[j], names[i]
            }
        }' "$ldir/points" "$ldir/where" "$ldir/bins" >"$ldir/jobs"
    mkdir -p "$ldir/run"
    # Judged: the submission's taught files may hold nothing that would turn
    # its test programs against their record (tools/submission-check.sh); if
    # one does, no test of the lesson runs, and each says why.
    refused=""
    checked=0
    if [ "$mode" = reference ]; then
        sh tools/submission-check.sh check "$build" "$lesson" "$records/$lesson/check" >"$ldir/refused" 2>&1
        checked=$?
    fi
    # (1: the submission is refused; anything else: the records are unusable,
    # which is the grader's failure, not the student's.)
    if [ "$checked" -ne 0 ] && [ "$checked" -ne 1 ]; then
        echo "$prog: error: $lesson not graded: $(head -n 1 "$ldir/refused")" >&2
        status=1
        continue
    fi
    if [ "$checked" -eq 1 ]; then
        refused=1
        echo "$prog: $lesson is not judged:" >&2
        sed 's/^/  /' "$ldir/refused" >&2
        while read -r bin name; do
            { echo "not judged: the submission holds what a solution has no need of:"; cat "$ldir/refused"; } \
                >"$ldir/run/$bin.$name.log"
            echo "fail 0 $limit $((3 * limit))" >"$ldir/run/$bin.$name.verdict"
        done <"$ldir/jobs"
    fi
    # A run starts about ten processes, each worth a millisecond or so: a
    # shell built-in stands in for a program wherever one can.
    # shellcheck disable=SC2016 # expanded by the inner sh
    [ -s "$ldir/jobs" ] && [ -z "$refused" ] && xargs -n 2 -P "$jobs" sh -c '
        unset UPDATE_EXPECTED
        bin=$1 name=$2
        out="$GRADE_LDIR/run/$bin.$name"
        # CPU seconds: TIME_LIMIT, or five times what the teacher'"'"'s
        # solution used, if that is more. Wall-clock seconds: three times
        # that, only to stop a test that waits for ever. Neither past the
        # deadline of the whole grading.
        lim=$GRADE_LIMIT
        if [ "$GRADE_MODE" = reference ]; then
            ref=$(cat "$GRADE_RECORDS/$GRADE_LESSON/$bin.$name.cpu" 2>/dev/null)
            lim=$(awk -v l="$lim" -v r="${ref:-0}" '"'"'BEGIN { r = int(5 * r + 0.999); print (r > l ? r : l) }'"'"')
        fi
        wall=$((3 * lim))
        if [ -n "$GRADE_DEADLINE" ]; then
            left=$((GRADE_DEADLINE - $(date +%s)))
            [ "$left" -lt "$lim" ] && lim=$left
            [ "$left" -lt "$wall" ] && wall=$left
        fi
        if [ "$lim" -le 0 ]; then
            : >"$out.log"; echo "budget 0" >"$out.verdict"; exit 0
        fi
        # Its own TEST_OUTPUT: tests of one program run side by side here,
        # and their scratch files must not meet. Its nonce and result files
        # in a directory of its own under GRADE_PRIVATE (removed with it).
        tout="$GRADE_OUTPUT/$bin.$name"
        d="$GRADE_PRIVATE/$GRADE_LESSON.$bin.$name"
        if [ -e "$tout" ] || [ -L "$tout" ]; then rm -rf "$tout"; fi
        mkdir -p "$d" "$tout" || exit 0
        set -- $(od -An -N16 -tx1 /dev/urandom) # 16 bytes as words "3f" "a0" ...
        nonce=""
        for byte in "$@"; do nonce=$nonce$byte; done
        echo "$nonce" >"$d/n"
        exe="$GRADE_BUILD/tests/$GRADE_LESSON/$bin"
        if [ ! -x "$exe" ]; then
            echo "its test program, $bin, did not build (the compiler'"'"'s messages are with the score)" >"$out.log"
            echo "unfinished 127 $lim $wall" >"$out.verdict"
            exit 0
        fi
        # In a sandbox: a slot of its own (at most GRADE_JOBS run at once, so
        # one is free), whose user runs the test and owns its directory.
        sandbox=""
        owner=""
        if [ -n "$GRADE_SANDBOX" ]; then
            slot=0
            while ! mkdir "$GRADE_PRIVATE/slot.$slot" 2>/dev/null; do slot=$((slot + 1)); done
            sh "$GRADE_SANDBOX" prepare "$slot" "$tout"
            sandbox="sh $GRADE_SANDBOX run $slot --"
            owner="--owner $(sh "$GRADE_SANDBOX" uid "$slot")"
        fi
        # Its output, at most GRADE_LOG_MAX bytes of it: time_limit reads the
        # rest and throws it away (a debug print per fragment writes gigabytes).
        if [ "$GRADE_MODE" = self ]; then
            TEST_OUTPUT="$tout" \
                TEST_FILTER="$name" GRADE_NONCE_FILE="$d/n" GRADE_RESULT_FILE="$d/r" \
                "$0" --cpu "$lim" --output "$out.log" --output-max "$GRADE_LOG_MAX" "$wall" \
                $sandbox "$exe" </dev/null
            st=$?
        else
            # Observed: what its checks saw goes to descriptor 3 (observe.h).
            # The grader'"'"'s own variables kept from it: where the records are.
            TEST_OUTPUT="$tout" TEST_FILTER="$name" GRADE_OBSERVE_FD=3 \
                env -u GRADE_RECORDS -u GRADE_JUDGE -u GRADE_PRIVATE -u GRADE_LDIR -u GRADE_DIR \
                "$0" --cpu "$lim" --cpu-out "$out.cpu" --output "$out.log" \
                --output-max "$GRADE_LOG_MAX" "$wall" $sandbox "$exe" </dev/null 3>"$out.obs"
            st=$?
        fi
        if [ -n "$GRADE_SANDBOX" ]; then
            sh "$GRADE_SANDBOX" cleanup "$slot"
            rmdir "$GRADE_PRIVATE/slot.$slot"
        fi
        # What the test framework wrote: one line, or it is no verdict.
        r=""
        if [ -f "$d/r" ]; then
            { IFS= read -r r; IFS= read -r more && r=""; } <"$d/r"
        fi
        case $GRADE_MODE in
        self)
            if [ "$r" = "$nonce passed $name" ] && [ "$st" -eq 0 ]; then v=pass
            elif [ "$r" = "$nonce failed $name" ]; then v=fail
            elif [ "$r" = "$nonce passed $name" ]; then v=fail
            else v=unfinished; fi ;;
        record)
            # The teacher'"'"'s run: judged against itself (its pictures against
            # tests/expected/), it must pass to become the record.
            if [ "$st" -eq 0 ] && "$GRADE_JUDGE" "$out.obs" "$out.obs" "$tout" >>"$out.log"; then
                v=pass
                cp "$out.obs" "$GRADE_RECORDS/$GRADE_LESSON.new/$bin.$name.obs" &&
                    cp "$out.cpu" "$GRADE_RECORDS/$GRADE_LESSON.new/$bin.$name.cpu" || v=fail
            elif [ "$st" -eq 0 ] || grep -q "^E " "$out.obs"; then v=fail
            else v=unfinished; fi ;;
        reference)
            # The verdict is the judge'"'"'s alone: the record against the teacher'"'"'s.
            "$GRADE_JUDGE" $owner "$GRADE_RECORDS/$GRADE_LESSON/$bin.$name.obs" \
                "$out.obs" "$tout" >>"$out.log"
            j=$?
            # 2: the judge could not judge: the teacher'"'"'s record is missing or
            # malformed. The grading fails; the test is not the student'"'"'s zero.
            if [ "$j" -eq 2 ]; then v=nojudge
            elif [ "$j" -eq 0 ] && [ "$st" -eq 0 ]; then v=pass
            elif [ "$st" -eq 0 ] || [ "$j" -ne 1 ] || grep -q "^E " "$out.obs" 2>/dev/null; then v=fail
            else v=unfinished; fi ;;
        esac
        echo "$v $st $lim $wall" >"$out.verdict"' "$time_limit" <"$ldir/jobs"

    # The verdicts: a test passes if a program that has it passed it.
    : >"$ldir/results"     # test <tab> pass|fail|crash <tab> binary
    while read -r bin; do mkdir -p "$ldir/out/$bin"; done <"$ldir/bins"
    seen=" " passed=" " # the tests with a line in results so far; those that passed
    unjudged=""
    while read -r bin name; do
        read -r v st lim wall <"$ldir/run/$bin.$name.verdict" 2>/dev/null ||
            { v=unfinished; st=127; lim=$limit; wall=$((3 * limit)); }
        if [ "$v" = nojudge ]; then unjudged="$unjudged $name"; v=fail; fi
        log="$ldir/run/$bin.$name.log"
        case $passed in *" $name "*) continue ;; esac
        # NUL and the bytes that are not plain text (and are not valid UTF-8
        # in JSON) as "?". At most its first and last 3000 bytes, whatever the
        # size of the log (a debug print per fragment writes gigabytes): head
        # and tail read no more than that.
        size=$(wc -c <"$log" 2>/dev/null || echo 0)
        shown="$ldir/out/$bin/$name.out"
        if [ "$size" -gt 6000 ]; then
            { head -c 3000 "$log"; printf '\n[... %s bytes of output left out ...]\n' $((size - 6000))
              tail -c 3000 "$log"; } | LC_ALL=C tr '\000\200-\377' '?' >"$shown"
        elif [ -f "$log" ]; then
            LC_ALL=C tr '\000\200-\377' '?' <"$log" >"$shown"
        else
            : >"$shown"
        fi
        case $v in
            pass|fail) how=$v ;;
            budget) how=crash
                echo "not run: the time for the whole grading ran out" >>"$ldir/out/$bin/$name.out" ;;
            *) how=crash
               if [ "$st" -eq 0 ]; then
                   echo "the test program ended before this test finished (exit() or _exit() in the code?)" >>"$ldir/out/$bin/$name.out"
               elif [ "$st" -eq 124 ]; then
                   echo "did not finish within $wall s, waiting rather than computing: a read or a wait that never ends?" >>"$ldir/out/$bin/$name.out"
               elif [ "$st" -eq 152 ]; then
                   echo "used more than $lim s of CPU time: an endless loop? (TIME_LIMIT=$limit)" >>"$ldir/out/$bin/$name.out"
               else
                   why_unfinished "$st" >>"$ldir/out/$bin/$name.out"
               fi ;;
        esac
        case $seen in
            *" $name "*)
                [ "$how" = pass ] || continue
                grep -v "^$name	" "$ldir/results" >"$ldir/results.tmp"; mv "$ldir/results.tmp" "$ldir/results" ;;
        esac
        printf '%s\t%s\t%s\n' "$name" "$how" "$bin" >>"$ldir/results"
        seen="$seen$name "
        [ "$how" != pass ] || passed="$passed$name "
    done <"$ldir/jobs"
    if [ -n "$unjudged" ]; then
        echo "$prog: error: the records in $records/$lesson could not judge:$unjudged (missing or malformed: make grade-reference); the grading of $lesson failed" >&2
        status=1
    fi
    if [ "$mode" = record ]; then
        # (A test of the points file that no program has did not pass either:
        # judged without its record, it could not be graded.)
        if [ -n "$missing" ] || awk -F '\t' 'FILENAME == ARGV[1] { if ($2 == "pass") ok[$1] = 1; else bad = 1; next }
                                             !($1 in ok) { bad = 1 } END { exit !bad }' "$ldir/results" "$ldir/points"; then
            echo "$prog: error: the teacher's solution of $lesson does not pass every test (below): nothing is recorded for it" >&2
            rm -rf "$records/$lesson.new"
            status=1
        elif ! sh tools/submission-check.sh record "$build" "$lesson" "$records/$lesson.new/check"; then
            echo "$prog: error: could not record what $lesson's solution defines and calls: nothing is recorded for it" >&2
            rm -rf "$records/$lesson.new"
            status=1
        else
            rm -rf "$records/$lesson"
            mv "$records/$lesson.new" "$records/$lesson" || status=1
        fi
    fi

    # The table, and this lesson's entries of results.json.
    echo "$prog: $lesson (points from $points)"
    [ -z "$missing" ] ||
        echo "  these test programs did not build, their tests score 0:$missing (see $gdir/build.log)"
    awk -F '\t' -v lesson="$lesson" -v ldir="$ldir" -v missing="$missing" \
        -v first="$first_test" -v tests_json="$tests_json" -v summary="$summary" \
        -v points_file="$points" -v compiler="$compiler" "$json_awk"'
        function compiler_errors(    l, s, n) {
            s = ""
            while ((getline l < compiler) > 0) if (l ~ /error:/ && n++ < 20) s = s "\n" l
            close(compiler)
            return s == "" ? "" : "\nthe compiler said:" s
        }
        function output_of(name, bin,    f, l, s) {
            f = ldir "/out/" bin "/" name ".out"
            s = ""
            while ((getline l < f) > 0) { s = s l "\n"; last_line = l }
            close(f)
            return s
        }
        function entry(name, score, max, status, out, vis) {
            printf "%s    {\"name\": %s, \"score\": %s, \"max_score\": %s, \"status\": \"%s\", \"visibility\": \"%s\", \"output_format\": \"text\", \"output\": %s}",
                first ? "" : ",\n", json(lesson ": " name), score, max, status, vis, json(out) >> tests_json
            first = 0
        }
        FILENAME == ldir "/results" {
            if (!($1 in how)) order[++norder] = $1
            if (!($1 in how) || how[$1] == "pass") how[$1] = $2
            bin[$1] = $3
            next
        }
        {
            name = $1; max = $2 + 0; what = $3; listed[name] = 1
            ok = (name in how) && (how[name] == "pass")
            score = ok ? max : 0
            got += score; all += max
            if (name in how) out = output_of(name, bin[name])
            else out = "this test did not run: " (missing != "" ? "some test programs did not build (" missing " )" compiler_errors() : "no test program of " lesson " has it (renamed? see " points_file ")") "\n"
            if (!ok) out = out "This test checks: " what "\n"
            entry(name, score, max, ok ? "passed" : "failed", out, $4 == "" ? "visible" : $4)
            printf "  %-4s %6s  %s\n", ok ? "PASS" : "FAIL", sprintf("%g/%g", score, max), name
            if (!ok) printf "              checks: %s\n", what
            if (how[name] == "crash") printf "              %s\n", last_line
        }
        END {
            for (k = 1; k <= norder; k++) if (!((name = order[k]) in listed)) {
                entry(name, 0, 0, how[name] == "pass" ? "passed" : "failed", output_of(name, bin[name]) "(not in " points_file ": counts 0 points)\n", "visible")
                printf "  %-4s %6s  %s  (not in %s: 0 points)\n", how[name] == "pass" ? "pass" : "fail", "-", name, points_file
            }
            printf "  %s: %g/%g\n", lesson, got, all
            printf "%s: %g/%g\n", lesson, got, all >> summary
            printf "%g %g %d\n", got, all, first
        }' "$ldir/results" "$ldir/points" >"$ldir/score"
    sed '$d' "$ldir/score"

    read -r got max first_test <<EOF
$(tail -n 1 "$ldir/score")
EOF
    total=$(awk -v a="$total" -v b="$got" 'BEGIN { printf "%g", a + b }')
    total_max=$(awk -v a="$total_max" -v b="$max" 'BEGIN { printf "%g", a + b }')
done

# TEST=name: the exit status says whether it passed, for a CI step per test.
if [ -n "$only_test" ] && [ "$status" -eq 0 ]; then
    passed=no
    for lesson in "$@"; do
        if grep -q "^$only_test	pass	" "$gdir/$lesson/results" 2>/dev/null; then passed=yes; fi
    done
    [ "$passed" = yes ] || status=1
fi

# The whole run's seconds: GRADE_STARTED_AT (seconds since the epoch) when the
# caller started earlier (the autograder, whose build comes first).
case ${GRADE_STARTED_AT:-} in
    ''|*[!0-9]*) began=$start ;;
    *) began=$GRADE_STARTED_AT ;;
esac
elapsed=$(($(date +%s) - began))
results="$gdir/results.json"
# GRADE_PREAMBLE=file: lines put first in the output (which files were graded).
awk -v score="$total" -v elapsed="$elapsed" -v summary="$summary" -v parts="$tests_json" \
    -v compiler="$compiler" -v preamble="${GRADE_PREAMBLE:-}" "$json_awk"'
    BEGIN {
        out = ""
        if (preamble != "") while ((getline l < preamble) > 0) out = out l "\n"
        while ((getline l < summary) > 0) out = out l "\n"
        c = ""
        while ((getline l < compiler) > 0) c = c l "\n"
        if (c != "") out = out "\nThe compiler said (warnings do not cost points here, but read them):\n" c
        printf "{\n  \"score\": %s,\n  \"execution_time\": %d,\n  \"visibility\": \"visible\",\n", score, elapsed
        # Plain text, so that a compiler message that names <stdio.h> shows as it is.
        printf "  \"output_format\": \"text\",\n  \"test_output_format\": \"text\",\n"
        printf "  \"output\": %s,\n  \"tests\": [\n", json(out)
        while ((getline l < parts) > 0) print l
        printf "\n  ]\n}\n"
    }' >"$results.tmp" && mv "$results.tmp" "$results" || { echo "$prog: error: cannot write $results" >&2; exit 1; }
rm -f "$tests_json" "$summary"
echo "$prog: total $total/$total_max  ->  $results"
exit "$status"
