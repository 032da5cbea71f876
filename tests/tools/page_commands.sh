#!/bin/sh
# page_commands.sh: every command that README.md and docs/*.md show runs as
# printed, in a fresh copy of the tree, and prints what the page says it
# prints. tests/tools/test_page_commands.c runs it; by hand:
#
#     sh tests/tools/page_commands.sh [BUILD_DIR [WORK_DIR]]   (from the top of the tree)
#
# What counts as a command (docs/conventions.md, "Commands on the pages"):
#   ```sh       every line is a command, except blank lines and comment lines;
#               a line ending in \ goes on on the next line. A comment
#               `# exit N` after a command says it ends with status N (else 0).
#               A block whose first line is #! is a script file shown, not run.
#   ```console  lines starting with "$ " are commands; the lines after one, up
#               to the next "$ " or the end of the block, are what it prints
#               (stdout and stderr together). In them a line "..." stands for
#               any number of lines, and <name> (a word in angle brackets, such
#               as <seconds>) for any text within a line. "$ echo $?" followed
#               by a number gives the status of the command before it.
#   other blocks (```, ```c, ...) are not run. A command line in a block with
#               no language ("$ ..." or "build/..." or "make ...") is an error:
#               mark the block sh or console.
#
# The copy: the files git knows (tracked and new, not ignored) and BUILD_DIR
# (default build) as its build/, times kept, so that nothing rebuilds (less
# what no command run here reads: other builds' directories, test outputs); then
# `make run` there, as a reader would have done, so out/ holds every lesson's
# picture. Each page's commands run in order, from the top of the copy.
#
# Commands that take minutes are not run but dry-run with make -n (the target
# exists and make knows how to build what it needs): make test, make grade and
# make update-expected without TEST=, make bench, sanitize, tsan, fuzz, valgrind,
# compile_commands.json and the book's targets (make site, site-serve, site-test, wasm),
# and the programs of build/bench/ (made by make bench).
#
# A command that only reads the build and writes nothing in the tree (the
# list in read_only_of below: make gpu-check, the slowest one) runs once even
# when two pages show it: the second showing is checked against the first
# run's status and output, in this same run of this script.
#
# Output: one line per failure, "page:line: command", what was expected and
# what came; then "page commands: N run, M failed". Exit status 1 on a failure.
set -u
build=${1:-build}
work=${2:-$build/test-output/page-commands}
top=$(pwd)
case $build in /*) ;; *) build=$top/$build ;; esac
case $work in /*) ;; *) work=$top/$work ;; esac

rm -rf "$work"
mkdir -p "$work/tree" "$work/cmds" || exit 1
tree=$work/tree

# ---- 1. the commands of the pages ----
# One record per command in $work/cmds: NNNN.where (page:line), .cmd, .status
# (expected), and .expect when the page shows its output.
pages="README.md $(ls docs/*.md)"
# shellcheck disable=SC2086 # one word per page
awk -v dir="$work/cmds" '
    function flush_expect() { if (have_expect) close(expect_file); have_expect = 0 }
    function new_cmd(where, cmd, status) {
        flush_expect()
        n++
        prefix = sprintf("%s/%04d", dir, n)
        printf "%s\n", where > (prefix ".where"); close(prefix ".where")
        printf "%s\n", cmd > (prefix ".cmd"); close(prefix ".cmd")
        printf "%s\n", status > (prefix ".status"); close(prefix ".status")
        last = prefix
    }
    function bad(msg) { printf "%s:%d: %s\n", FILENAME, FNR, msg > "/dev/stderr"; errors++ }
    FNR == 1 { inb = 0; pending = "" }
    /^```/ {
        if (!inb) {
            inb = 1; lang = substr($0, 4); first = 1; cur = ""
            sub(/[ \t].*/, "", lang)
            next
        }
        if (pending != "") bad("a command ends in \\ at the end of its block")
        inb = 0; pending = ""; flush_expect(); next
    }
    !inb { next }
    lang == "sh" {
        if (first && /^#!/) { lang = "script" }
        first = 0
        if (lang != "sh") next
        if (pending == "" && ($0 ~ /^[ \t]*$/ || $0 ~ /^[ \t]*#/)) next
        if (pending == "") { start = FNR; pending = $0 } else pending = pending "\n" $0
        if ($0 ~ /\\$/) next
        status = 0
        if (match(pending, /#[ \t]*exit[ \t]+[0-9]+/)) {
            s = substr(pending, RSTART, RLENGTH); sub(/^#[ \t]*exit[ \t]+/, "", s); status = s + 0
        }
        new_cmd(FILENAME ":" start, pending, status)
        pending = ""
        next
    }
    lang == "console" {
        if (first && $0 !~ /^\$ /) bad("a console block starts with a \"$ \" command")
        first = 0
        if ($0 ~ /^\$ /) {
            cmd = substr($0, 3)
            if (cmd == "echo $?") { want_status = 1; flush_expect(); next }
            new_cmd(FILENAME ":" FNR, cmd, 0)
            expect_file = last ".expect"; have_expect = 1; want_status = 0
            printf "" > expect_file
            next
        }
        if (want_status) {
            if ($0 !~ /^[0-9]+$/) bad("\"$ echo $?\" is followed by a number")
            else { printf "%d\n", $0 > (last ".status"); close(last ".status") }
            want_status = 0
            next
        }
        if (have_expect) printf "%s\n", $0 > expect_file
        next
    }
    lang == "" && /^(\$ |build\/|make( |$))/ {
        bad("a command in a block with no language: mark the block sh or console")
    }
    END { exit errors > 0 }
' $pages || { echo "page commands: the pages break the convention above"; exit 1; }

# ---- 2. the copy ----
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    git ls-files -z --cached --others --exclude-standard |
        xargs -0 sh -c 'for f; do [ -e "$f" ] && printf "%s\0" "$f"; done' sh |
        tar --null -T - -cf - | tar -xf - -C "$tree" || exit 1
else
    tar -cf - --exclude=./build --exclude=./out --exclude=./.git . | tar -xf - -C "$tree" || exit 1
fi
mkdir -p "$tree/build"
(cd "$build" && tar -cf - --exclude=./test-output --exclude=./handout --exclude=./grade \
    --exclude=./sanitize --exclude=./fuzz --exclude=./compile-commands --exclude=./bench \
    --exclude=./tsan --exclude=./grade-check --exclude=./wasm --exclude=./site \
    --exclude=./site-student --exclude=./site-node .) |
    tar -xf - -C "$tree/build" || exit 1
unset MAKEFLAGS MAKELEVEL MFLAGS BUILD OPT LESSON TEST TEST_FILTER FROM TO ONLY DEST \
    TIME_LIMIT SECONDS FUZZ UPDATE_EXPECTED
if ! (cd "$tree" && make --no-print-directory run >"$work/make-run.log" 2>&1); then
    echo "page commands: make run failed in the copy:"
    cat "$work/make-run.log"
    exit 1
fi

# ---- 3. run them ----
# A line of expected output against a line of actual output: <name> is any text.
matches() { # expected-file actual-file
    awk '
        function line_ok(e, a,    parts, np, i, pos, p) {
            np = split(e, parts, /<[a-z][a-z_ -]*>/)
            if (np == 1) return e == a
            if (substr(a, 1, length(parts[1])) != parts[1]) return 0
            pos = length(parts[1]) + 1
            for (i = 2; i < np; i++) {
                p = index(substr(a, pos), parts[i])
                if (parts[i] != "" && p == 0) return 0
                pos += (parts[i] == "" ? 0 : p - 1 + length(parts[i]))
            }
            return length(a) - pos + 1 >= length(parts[np]) &&
                   substr(a, length(a) - length(parts[np]) + 1) == parts[np]
        }
        function m(i, j) { # expected from line i, actual from line j
            if (i > ne) return j > na
            if (exp_[i] == "...") {
                for (; j <= na + 1; j++) if (m(i + 1, j)) return 1
                return 0
            }
            return j <= na && line_ok(exp_[i], act[j]) && m(i + 1, j + 1)
        }
        NR == FNR { sub(/[ \t]+$/, ""); exp_[++ne] = $0; next }
        { sub(/[ \t]+$/, ""); act[++na] = $0 }
        END {
            while (ne > 0 && exp_[ne] == "") ne--
            while (na > 0 && act[na] == "") na--
            exit !m(1, 1)
        }' "$1" "$2"
}

# make test, grade, update-expected without TEST=, and the long targets
# (bench, sanitize, tsan, fuzz, valgrind, and the book's, which install
# pandoc and chromium): make -n.
dry_run_of() { # command -> the make -n line to run instead, or nothing
    case $1 in
        make*bench*|make*sanitize*|make*tsan*|make*fuzz*|make*valgrind*|make*compile_commands.json*|make\ site*|make\ wasm*)
            echo "make -n ${1#make }" ;;
        make\ grade*)
            echo "make -n ${1#make }" ;;
        make*TEST=*) ;;
        make\ test*|make\ update-expected*|make\ -j*\ test*)
            echo "make -n ${1#make }" ;;
        build/bench/*)
            echo "make -n ${1%% *}" ;;
    esac
}

# Whether the command only reads the build and writes nothing in the tree:
# its status and output cannot depend on the commands run before it.
read_only_of() { # command -> 0 if so
    case $1 in
        'make gpu-check') return 0 ;;
    esac
    return 1
}

# stdout line by line, as on a terminal: the lines of stdout and stderr come
# in the order the page shows them.
linebuf=""
command -v stdbuf >/dev/null 2>&1 && linebuf="stdbuf -oL"
# stdbuf works by preloading a library; a program built with AddressSanitizer
# (make sanitize) wants its runtime first, and would refuse to start.
ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0"
export ASAN_OPTIONS

ran=0
failed=0
for rec in "$work"/cmds/*.cmd; do
    [ -e "$rec" ] || break
    base=${rec%.cmd}
    where=$(cat "$base.where")
    cmd=$(cat "$rec")
    want=$(cat "$base.status")
    run=$(dry_run_of "$cmd")
    [ -n "$run" ] || run=$cmd
    ran=$((ran + 1))
    # The first run of the same read-only command, if there was one.
    first=""
    if read_only_of "$cmd"; then
        for earlier in "$work"/cmds/*.cmd; do
            [ "$earlier" = "$rec" ] && break
            if [ "$(cat "$earlier")" = "$cmd" ] && [ -f "${earlier%.cmd}.got" ]; then
                first=${earlier%.cmd}
                break
            fi
        done
    fi
    if [ -n "$first" ]; then
        cp "$first.out" "$base.out"
        got=$(cat "$first.got")
    else
        (cd "$tree" && timeout 60 $linebuf sh -c "$run" </dev/null >"$base.out" 2>&1)
        got=$?
    fi
    echo "$got" >"$base.got"
    [ -n "$(dry_run_of "$cmd")" ] && want=0 # a dry run says only that make can do it
    problem=""
    if [ "$got" -ne "$want" ]; then
        problem="exit status $got, the page says $want"
    elif [ -f "$base.expect" ] && [ "$run" = "$cmd" ] && ! matches "$base.expect" "$base.out"; then
        problem="output differs from the page"
    fi
    if [ -n "$problem" ]; then
        failed=$((failed + 1))
        echo "$where: $cmd"
        echo "  $problem"
        if [ -f "$base.expect" ]; then
            echo "  expected (the page):"
            sed 's/^/    | /' "$base.expect"
        fi
        echo "  came (in $tree):"
        head -n 40 "$base.out" | sed 's/^/    | /'
    fi
done
echo "page commands: $ran run, $failed failed"
[ "$failed" -eq 0 ]
