#!/bin/sh
# grade.sh: the score of the lessons' tests, as a table and as results.json.
#
#   sh scripts/grade.sh --build DIR [--time-limit SECONDS] LESSON_DIR_NAME...
#   (make grade [LESSON=NN] builds the tests, then calls it)
#
# Points come from tests/<lesson>/points.txt, one test a line:
#     <test name>  <points>  <what it checks>
# (# starts a comment). A test that the file does not list still runs and is
# shown, but counts 0 points; a listed test that never ran (its binary did not
# build, or no binary has it) scores 0.
#
# Each test binary first runs whole, under a time limit. Any listed test it
# did not finish (the binary crashed or hung in it or before it) then runs
# alone (TEST_FILTER, see tests/support/test_hooks.c), under the per-test
# limit: a crash or a hang costs the points of the test it happens in, not
# the whole grade.
#
# Writes DIR/grade/results.json in the format of the Gradescope autograder
# (tests[] with name, score, max_score, status, output; the overall score),
# and the output of each test under DIR/grade/<lesson>/.
# Exit status: 0 when grading worked (whatever the score), 1 when it could
# not (a malformed points file, a missing tool), 2 usage error.
#
# --test NAME (make grade TEST=name) grades that one test, run alone in each
# test program; the exit status is then 0 if it passed and 1 if not, so that
# a CI step per test can give it its points (GitHub Classroom, docs/teaching.md).
set -u

prog=grade
build=build
limit=${TIME_LIMIT:-10}
only_test=""
while [ $# -gt 0 ]; do
    case $1 in
        --build) build=$2; shift 2 ;;
        --time-limit) limit=$2; shift 2 ;;
        --test) only_test=$2; shift 2 ;;
        -*) echo "$prog: error: unknown option $1" >&2; exit 2 ;;
        *) break ;;
    esac
done
if [ $# -eq 0 ]; then
    echo "$prog: error: no lesson to grade" >&2
    echo "usage: make grade [LESSON=NN] [TEST=name] [TIME_LIMIT=seconds per test]" >&2
    exit 2
fi
case $limit in
    ''|*[!0-9]*|0) echo "$prog: error: TIME_LIMIT=$limit: want a whole number of seconds, at least 1" >&2; exit 2 ;;
esac
jobs=${GRADE_JOBS:-$(nproc 2>/dev/null || getconf _NPROCESSORS_ONLN 2>/dev/null || echo 1)}
case $jobs in
    ''|*[!0-9]*|0) jobs=1 ;;
esac
# A whole binary may take as long as a few of its tests: it only decides how
# soon the tests it did not finish are run one by one.
binary_limit=$((limit * 3))

time_limit="$build/tools/time_limit"
[ -x "$time_limit" ] || { echo "$prog: error: $time_limit is missing (make tools builds it)" >&2; exit 1; }
gdir="$build/grade"
mkdir -p "$gdir" || exit 1
start=$(date +%s)
export BIN_DIR="$build/bin" TOOL_DIR="$build/tools" TEST_OUTPUT="$build/test-output"

# Reads a test binary's log (cmocka's standard output, stdout and stderr in
# one file); writes each test's lines to OUT/<test>.out and prints
#   R <tab> test <tab> pass|fail|skip   for each test that finished,
#   S <tab> test                        for one that started and never finished,
#   D                                   when the run ended with cmocka's summary.
parse_log() { # parse_log LOG OUTDIR
    mkdir -p "$2"
    awk -v out="$2" '
        function finish(how) {
            printf "R\t%s\t%s\n", current, how
            close(out "/" current ".out")
            current = ""
        }
        /^\[ RUN      \] / {
            if (current != "") printf "S\t%s\n", current
            current = substr($0, 14)
            done = 0
            print $0 > (out "/" current ".out")
            next
        }
        current != "" {
            print $0 > (out "/" current ".out")
            if ($0 == "[       OK ] " current) finish("pass")
            else if ($0 == "[  FAILED  ] " current || $0 == "[  ERROR   ] " current) finish("fail")
            else if ($0 == "[  SKIPPED ] " current) finish("skip")
            next
        }
        /^\[==========\] [0-9]+ test\(s\) run\.$/ { done = 1 }
        END {
            if (current != "") printf "S\t%s\n", current
            if (done) print "D"
        }' "$1"
}

# What a status of time_limit says about a run that did not finish a test.
why_unfinished() { # why_unfinished STATUS
    case $1 in
        124) echo "did not finish within $limit s: an endless loop? (TIME_LIMIT=$limit)" ;;
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
    mkdir -p "$ldir/alone"
    if [ ! -f "$points" ]; then
        echo "$prog: error: $points is missing: it gives each test of $lesson its points (see docs/teaching.md)" >&2
        status=1
        continue
    fi
    # The points file, checked: "name<tab>points<tab>what" in $ldir/points.
    if ! awk -v file="$points" '
        /^[ \t]*(#|$)/ { next }
        {
            name = $1; pts = $2
            what = $0; sub(/^[ \t]*[^ \t]+[ \t]+[^ \t]+[ \t]*/, "", what)
            if (name !~ /^[A-Za-z_][A-Za-z0-9_]*$/) { bad = "a test name, a C identifier" }
            else if (pts !~ /^[0-9]+(\.[0-9]+)?$/) { bad = "points: a number, 0 or more" }
            else if (what == "") { bad = "a few words on what the test checks" }
            else if (name in seen) { bad = "each test once (it was on line " seen[name] ")" }
            if (bad != "") {
                printf "%s:%d: want \"<test name> <points> <what it checks>\": %s\n", file, FNR, bad > "/dev/stderr"
                exit 1
            }
            seen[name] = FNR
            printf "%s\t%s\t%s\n", name, pts, what
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

    # Phase 1: every binary whole, GRADE_JOBS at a time (the number of cores
    # by default, as make test), each under its own time limit; then their
    # logs are read one by one, in the same order as ever.
    : >"$ldir/results"     # test <tab> pass|fail|skip <tab> binary
    : >"$ldir/unfinished"  # test <tab> binary <tab> status
    : >"$ldir/incomplete"  # binary <tab> status: binaries that did not finish
    : >"$ldir/whole"       # the binaries phase 1 runs
    missing=""
    for src in tests/"$lesson"/test_*.c; do
        [ -f "$src" ] || continue
        bin=$(basename "$src" .c)
        exe="$build/tests/$lesson/$bin"
        if [ ! -x "$exe" ]; then
            missing="$missing $bin"
            continue
        fi
        if [ -n "$only_test" ]; then
            printf '%s\t-\n' "$bin" >>"$ldir/incomplete" # phase 2 runs the one test
            continue
        fi
        echo "$bin" >>"$ldir/whole"
    done
    # shellcheck disable=SC2016 # expanded by the inner sh
    [ -s "$ldir/whole" ] && xargs -n 1 -P "$jobs" sh -c '
        TEST_FILTER="" "$0" "$1" "$2/$4" >"$3/$4.log" 2>&1
        echo $? >"$3/$4.status"' "$time_limit" "$binary_limit" "$build/tests/$lesson" "$ldir" \
        <"$ldir/whole"
    while read -r bin; do
        st=$(cat "$ldir/$bin.status" 2>/dev/null || echo 127)
        parse_log "$ldir/$bin.log" "$ldir/out/$bin" >"$ldir/$bin.parsed"
        awk -F '\t' -v bin="$bin" -v st="$st" '
            $1 == "R" { printf "%s\t%s\t%s\n", $2, $3, bin >> results }
            $1 == "S" { printf "%s\t%s\t%s\n", $2, bin, st >> unfinished }
            $1 == "D" { done = 1 }
            END { if (!done || st >= 124) printf "%s\t%s\n", bin, st >> incomplete }' \
            results="$ldir/results" unfinished="$ldir/unfinished" incomplete="$ldir/incomplete" \
            "$ldir/$bin.parsed"
    done <"$ldir/whole"

    # Phase 2: each listed test without a result, alone, in each binary that
    # did not finish, until one has it.
    cut -f1 "$ldir/points" | while read -r name; do
        grep -q "^$name	" "$ldir/results" && continue
        [ -s "$ldir/incomplete" ] || continue
        cut -f1 "$ldir/incomplete" | while read -r bin; do
            exe="$build/tests/$lesson/$bin"
            TEST_FILTER="$name" "$time_limit" "$limit" "$exe" >"$ldir/alone/$bin.$name.log" 2>&1
            st=$?
            parse_log "$ldir/alone/$bin.$name.log" "$ldir/alone/$bin" >"$ldir/alone/$bin.$name.parsed"
            if grep -q "^R	$name	" "$ldir/alone/$bin.$name.parsed"; then
                how=$(grep "^R	$name	" "$ldir/alone/$bin.$name.parsed" | head -n 1 | cut -f3)
                mkdir -p "$ldir/out/$bin"
                cp "$ldir/alone/$bin/$name.out" "$ldir/out/$bin/$name.out"
                printf '%s\t%s\t%s\n' "$name" "$how" "$bin" >>"$ldir/results"
                break
            fi
            if grep -q "^S	$name\$" "$ldir/alone/$bin.$name.parsed"; then
                mkdir -p "$ldir/out/$bin"
                cp "$ldir/alone/$bin/$name.out" "$ldir/out/$bin/$name.out"
                why_unfinished "$st" >>"$ldir/out/$bin/$name.out"
                printf '%s\t%s\t%s\n' "$name" crash "$bin" >>"$ldir/results"
                break
            fi
        done
    done

    # The table, and this lesson's entries of results.json.
    echo "$prog: $lesson (points from $points)"
    [ -z "$missing" ] ||
        echo "  these test programs did not build, their tests score 0:$missing (see $gdir/build.log)"
    awk -F '\t' -v lesson="$lesson" -v ldir="$ldir" -v missing="$missing" \
        -v first="$first_test" -v tests_json="$tests_json" -v summary="$summary" \
        -v points_file="$points" "$json_awk"'
        function output_of(name, bin,    f, l, s) {
            f = ldir "/out/" bin "/" name ".out"
            s = ""
            while ((getline l < f) > 0) { s = s l "\n"; last_line = l }
            close(f)
            if (length(s) > 6000) s = substr(s, 1, 3000) "\n[...]\n" substr(s, length(s) - 2999)
            return s
        }
        function entry(name, score, max, status, out) {
            printf "%s    {\"name\": %s, \"score\": %s, \"max_score\": %s, \"status\": \"%s\", \"output\": %s}",
                first ? "" : ",\n", json(lesson ": " name), score, max, status, json(out) >> tests_json
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
            else out = "this test did not run: " (missing != "" ? "some test programs did not build (" missing " )" : "no test program of " lesson " has it (renamed? see " points_file ")") "\n"
            if (!ok) out = out "This test checks: " what "\n"
            entry(name, score, max, ok ? "passed" : "failed", out)
            printf "  %-4s %6s  %s\n", ok ? "PASS" : "FAIL", sprintf("%g/%g", score, max), name
            if (!ok) printf "              checks: %s\n", what
            if (how[name] == "crash") printf "              %s\n", last_line
        }
        END {
            for (k = 1; k <= norder; k++) if (!((name = order[k]) in listed)) {
                entry(name, 0, 0, how[name] == "pass" ? "passed" : "failed", output_of(name, bin[name]) "(not in " points_file ": counts 0 points)\n")
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

elapsed=$(($(date +%s) - start))
results="$gdir/results.json"
awk -v score="$total" -v elapsed="$elapsed" -v summary="$summary" -v parts="$tests_json" "$json_awk"'
    BEGIN {
        out = ""
        while ((getline l < summary) > 0) out = out l "\n"
        printf "{\n  \"score\": %s,\n  \"execution_time\": %d,\n  \"visibility\": \"visible\",\n", score, elapsed
        printf "  \"output\": %s,\n  \"tests\": [\n", json(out)
        while ((getline l < parts) > 0) print l
        printf "\n  ]\n}\n"
    }' >"$results.tmp" && mv "$results.tmp" "$results" || { echo "$prog: error: cannot write $results" >&2; exit 1; }
rm -f "$tests_json" "$summary"
echo "$prog: total $total/$total_max  ->  $results"
exit "$status"
