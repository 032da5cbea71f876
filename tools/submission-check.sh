#!/bin/sh
# submission-check.sh: what a submission's code may hold, so that a test
# program linked with it still records what its checks saw (docs/teaching.md,
# "Who decides that a test passed"). tools/grade.sh calls it.
#
#   sh tools/submission-check.sh record BUILD LESSON DIR
#       from the teacher's solution, built in BUILD: DIR/taught (the lesson's
#       files with a solution region), DIR/defines (each taught object's
#       global names), DIR/calls (the names a submission may call), DIR/taken
#       (the names the tests call or define), DIR/<file>.directives
#       (each taught header's preprocessor lines)
#   sh tools/submission-check.sh check BUILD LESSON DIR
#       the student's build against them: one line per thing refused on
#       stdout, and status 1 if there is one; 0 and nothing if all is well;
#       3 and one line when the records in DIR cannot be used (missing, or
#       older than this grader): the grader's failure, not the submission's
#
# A taught file of the submission may not
#   - define a global name that the test program or a library it loads
#     calls from a shared library (vsnprintf, malloc, write, ...) or that the
#     tests define (observed_int_equal), nor one that begins with an
#     underscore: the test program would take it in place of theirs;
#   - call what the teacher's solution does not, but for the functions of
#     the lesson's own files and of common/, the C library's mathematics,
#     memory, strings and printing (FUNCTIONS below): no open, write, fork,
#     exit, no harness or test function;
#   - run code before main or after it (constructors, destructors, the
#     resolver of an indirect function), nor hold a system call or inline
#     assembly;
#   - (a header the tests include) hold a preprocessor line or an attribute
#     that the teacher's does not, but an include of a standard header: it
#     is compiled into the test itself.
# A correct solution needs none of these: a helper of its own, static or
# not, and a debug printf are fine.
set -u
prog=submission-check

# The C library's functions a solution may call besides the teacher's: none
# opens, writes to a descriptor, starts or ends a process. Printing goes to
# stdout and stderr (the test's output, never its record). The _chk forms
# are what _FORTIFY_SOURCE makes of them.
FUNCTIONS='memcpy memmove memset memcmp memchr strlen strnlen strcmp strncmp strchr strrchr
strstr strcpy strncpy strcat strncat strtol strtoll strtoul strtoull strtod strtof strtold
atoi atol atof abs labs llabs div ldiv malloc calloc realloc free aligned_alloc
posix_memalign qsort bsearch printf puts putchar fputs fputc putc fprintf vprintf vfprintf
fflush fwrite sprintf snprintf vsprintf vsnprintf sscanf stdout stderr abort __assert_fail
__errno_location __stack_chk_fail __stack_chk_guard _GLOBAL_OFFSET_TABLE_ __printf_chk
__fprintf_chk __sprintf_chk __snprintf_chk __vprintf_chk __vfprintf_chk __vsprintf_chk
__vsnprintf_chk __memcpy_chk __memmove_chk __memset_chk __strcpy_chk __strncpy_chk
__strcat_chk __strncat_chk __isnan __isnanf __isinf __isinff __finite __finitef
__fpclassify __fpclassifyf __signbit __signbitf'

usage() {
    echo "usage: sh tools/submission-check.sh record|check BUILD LESSON DIR" >&2
    exit 2
}
[ $# -eq 4 ] || usage
what=$1 build=$2 lesson=$3 dir=$4
case $what in record|check) ;; *) usage ;; esac

# The object of taught file f (a .c of the lesson, as the build compiles it).
object() { echo "$build/obj/lessons/$lesson/${1%.c}.o"; }
# The global names an object defines, one a line.
defined() { nm -g --defined-only --format=posix "$1" 2>/dev/null | awk '{ print $1 }' | sort -u; }
# The names an object needs from elsewhere.
needed() { nm -u --format=posix "$1" 2>/dev/null | awk '{ print $1 }' | sort -u; }
# A header's preprocessor lines, comments out and spaces made one; a
# #define as "#define NAME", whatever its value, unless the value holds
# ; { or } (code, not a value).
directives() {
    sed -n 's/^[[:space:]]*#[[:space:]]*/#/p' "$1" | sed 's|//.*||; s|/\*.*\*/||g' |
        tr -s ' \t' '  ' | sed 's/[[:space:]]*$//' |
        awk '$1 == "#define" && $0 !~ /[;{}]/ { sub(/\(.*/, "", $2); print $1, $2; next } { print }' | sort -u
}
# An object's sections that run code before main or after it.
sections() {
    objdump -h "$1" 2>/dev/null | awk '{ print $2 }' |
        grep -E '^\.(init_array|fini_array|preinit_array|ctors|dtors|init|fini)(\.|$)' | sort -u
}
# Whether an object holds a GNU indirect function (__attribute__((ifunc))):
# the dynamic loader runs its resolver before main, before any constructor.
ifuncs() {
    nm --format=posix "$1" 2>/dev/null | awk '$2 == "i" { found = 1 } END { exit !found }'
}
# Whether an object holds a system call of its own.
# shellcheck disable=SC2016 # a dollar of the assembly, not of the shell
syscalls() {
    objdump -d --no-show-raw-insn "$1" 2>/dev/null |
        grep -qE '[[:space:]](syscall|sysenter|svc)([[:space:]]|$)|int[[:space:]]+\$0x80'
}
# How many times each word that reaches past C occurs in a source's code: inline
# assembly; in a header (compiled into the tests), attributes and pragmas too.
words() {
    case $1 in *.h) w='asm|__asm|__asm__|__attribute__|_Pragma' ;; *) w='asm|__asm|__asm__' ;; esac
    # comments out (the preprocessor's own reading, no macro expanded)
    ${CC:-cc} -fpreprocessed -dD -E -P -x c "$1" 2>/dev/null | grep -oE "\\b($w)\\b" |
        sort | uniq -c | awk '{ print $2, $1 }'
}

if [ "$what" = record ]; then
    mkdir -p "$dir" || exit 1
    (cd "lessons/$lesson" && grep -rlE 'SOLUTION BEGIN' . | sed 's|^\./||' | sort) >"$dir/taught"
    : >"$dir/defines"
    : >"$dir/calls.new"
    while read -r f; do
        case $f in
            *.c) o=$(object "$f")
                 [ -f "$o" ] || { echo "$prog: error: no $o: build the lesson first" >&2; exit 1; }
                 defined "$o" | sed "s|^|$f |" >>"$dir/defines"
                 needed "$o" >>"$dir/calls.new" ;;
            *) directives "lessons/$lesson/$f" >"$dir/$(echo "$f" | tr / _).directives" ;;
        esac
        words "lessons/$lesson/$f" >"$dir/$(echo "$f" | tr / _).words"
    done <"$dir/taught"
    # The tests' own objects, compiled with the taught headers.
    : >"$dir/tests.defines"
    : >"$dir/tests.sections"
    : >"$dir/tests.calls.new"
    for o in "$build/obj/tests/$lesson"/*.o; do
        [ -f "$o" ] || continue
        defined "$o" | sed "s|^|${o##*/} |" >>"$dir/tests.defines"
        needed "$o" >>"$dir/tests.calls.new"
        sections "$o" | sed "s|^|${o##*/} |" >>"$dir/tests.sections"
    done
    # What the lesson's own files (not its extras/, which write files) and
    # common/ (not its harness/) define; the C library's mathematics.
    for o in "$build/obj/lessons/$lesson"/*.o "$build/obj/common"/*.o; do
        [ -f "$o" ] && defined "$o"
    done >>"$dir/calls.new"
    libm=$(find /lib /usr/lib -name 'libm.so.6' 2>/dev/null | head -n 1)
    [ -n "$libm" ] && nm -D --defined-only --format=posix "$libm" | awk '{ sub(/@.*/, "", $1); print $1 }' >>"$dir/calls.new"
    libgcc=$(${CC:-cc} -print-libgcc-file-name 2>/dev/null)
    [ -f "$libgcc" ] && defined "$libgcc" >>"$dir/calls.new"
    # shellcheck disable=SC2086 # one name a word
    printf '%s\n' $FUNCTIONS >>"$dir/calls.new"
    sort -u "$dir/calls.new" >"$dir/calls" && rm -f "$dir/calls.new"
    sort -u "$dir/calls" "$dir/tests.calls.new" >"$dir/tests.calls" && rm -f "$dir/tests.calls.new"
    # The names taken: what the lesson's test programs and the libraries
    # they load (but the C library's own) call from a shared library, which
    # a name of the program's would replace; and every name the tests'
    # objects define.
    {
        for t in "$build/tests/$lesson"/test_*; do
            [ -x "$t" ] || continue
            echo "$t"
            ldd "$t" 2>/dev/null | awk '$3 ~ /^\// { print $3 } $1 ~ /^\// { print $1 }' |
                grep -vE '/(libc|ld-linux[^/]*)\.so'
        done | sort -u | while read -r f; do
            nm -D --undefined-only --format=posix "$f" 2>/dev/null | awk '{ sub(/@.*/, "", $1); print $1 }'
        done
        find "$build/obj/tests" -name '*.o' 2>/dev/null | while read -r o; do defined "$o"; done
    } | sort -u >"$dir/taken"
    [ -s "$dir/taken" ] || { echo "$prog: error: no test program of $lesson to read the libraries of" >&2; exit 1; }
    exit 0
fi

# check
tmp=$(mktemp "${TMPDIR:-/tmp}/submission-check.XXXXXX") || exit 3
trap 'rm -f "$tmp"' EXIT
if [ ! -s "$dir/taught" ] || [ ! -f "$dir/calls" ] || [ ! -f "$dir/tests.calls" ] || [ ! -f "$dir/taken" ]; then
    echo "the teacher's records of $lesson in $dir are missing or older than this grader: make them again (make grade-reference)"
    exit 3
fi
found=0
refuse() { case $1 in "its headers") echo "the submission's headers $2" ;; *) echo "lessons/$lesson/$1: $2" ;; esac; found=1; }
while read -r f; do
    src="lessons/$lesson/$f"
    [ -f "$src" ] || continue
    key=$(echo "$f" | tr / _)
    # Words past C: no more of each than the teacher's file has.
    words "$src" | while read -r w n; do
        had=$(awk -v w="$w" '$1 == w { print $2 }' "$dir/$key.words" 2>/dev/null)
        [ "$n" -le "${had:-0}" ] || echo "$w"
    done >"$tmp"
    while read -r w; do
        refuse "$f" "uses $w, which the lesson's file does not: not graded (remove it)"
    done <"$tmp"
    case $f in
    *.c)
        o=$(object "$f")
        [ -f "$o" ] || continue # it did not compile: its tests score 0 anyway
        for name in $(defined "$o"); do
            grep -qx "$f $name" "$dir/defines" && continue
            case $name in
                _*) refuse "$f" "defines $name, a name that begins with an underscore: rename it or make it static" ;;
                *) if grep -qxF "$name" "$dir/taken"; then
                       refuse "$f" "defines $name, a name the tests or the C library use: rename it or make it static"
                   fi ;;
            esac
        done
        for name in $(needed "$o"); do
            grep -qxF "$name" "$dir/calls" ||
                refuse "$f" "calls $name, which a solution of this lesson has no need of: not graded (remove the call)"
        done
        if [ -n "$(sections "$o")" ]; then
            refuse "$f" "runs code before main or after it (a constructor or destructor): not graded"
        fi
        if ifuncs "$o"; then
            refuse "$f" "runs code before main (an indirect function, whose resolver the loader runs): not graded"
        fi
        if syscalls "$o"; then
            refuse "$f" "makes a system call of its own: not graded"
        fi ;;
    *.h)
        # (an include of a standard header is a solution's own business)
        directives "$src" | grep -vxE '#include <(assert|float|limits|math|stdbool|stddef|stdint|stdio|stdlib|string)\.h>' |
            while read -r line; do
                grep -qxF "$line" "$dir/$key.directives" || echo "$line"
            done >"$tmp"
        while read -r line; do
            refuse "$f" "has the line '$line', which the lesson's header does not: the tests include it (remove it)"
        done <"$tmp" ;;
    esac
done <"$dir/taught"
# The tests' objects, compiled with the submission's headers: what the
# teacher's define, call and run, and no more.
for o in "$build/obj/tests/$lesson"/*.o; do
    [ -f "$o" ] || continue
    t=${o##*/}
    for name in $(defined "$o"); do
        grep -qxF "$t $name" "$dir/tests.defines" ||
            refuse "its headers" "make the test $t define $name, which the tests do not: not graded"
    done
    for name in $(needed "$o"); do
        grep -qxF "$name" "$dir/tests.calls" ||
            refuse "its headers" "make the test $t call $name, which the tests do not: not graded"
    done
    for sec in $(sections "$o"); do
        grep -qxF "$t $sec" "$dir/tests.sections" 2>/dev/null ||
            refuse "its headers" "make the test $t run code before main or after it: not graded"
    done
    if ifuncs "$o"; then
        refuse "its headers" "make the test $t run code before main (an indirect function): not graded"
    fi
    if syscalls "$o"; then
        refuse "its headers" "put a system call in the test $t: not graded"
    fi
done
exit $found
