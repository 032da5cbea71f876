# lesson-name.sh: which lesson a value such as LESSON=07 names. Sourced
# (. "$(dirname "$0")/lesson-name.sh") by the scripts that take a lesson from the command
# line: handout, snapshot, classroom, autograder, lesson-diff, lesson-tree.
#
#   lesson_name VARIABLE VALUE
#
# sets $lesson_name to the one directory under lessons/ that
# VALUE names, its number (07) or its name (07_depth_bias, or the start of
# it), or says why not in one line, "$prog: error: ...", and exits with
# status 2. VARIABLE is what the user typed the value as (LESSON, FROM, TO),
# for the message. A value is two digits and then letters, digits and "_"
# only: never a path (../.., /etc) or a pattern (*, 0?), which would reach
# outside lessons/, and never one digit (LESSON=1 is not lesson 10).
lesson_name() {
    lesson_name=""
    case $2 in
        '') echo "${prog:-lesson}: error: which lesson? e.g. $1=07" >&2
            exit 2 ;;
        [0-9][0-9]|[0-9][0-9]_*) ;;
        *) echo "${prog:-lesson}: error: $1=$2 is not a lesson: give its two digits (07) or its name (07_depth_bias)" >&2
           exit 2 ;;
    esac
    case $2 in
        *[!A-Za-z0-9_]*)
            echo "${prog:-lesson}: error: $1=$2 is not a lesson: give its two digits (07) or its name (07_depth_bias)" >&2
            exit 2 ;;
    esac
    for lesson_dir_ in lessons/"$2"*; do
        [ -d "$lesson_dir_" ] || continue
        if [ -n "$lesson_name" ]; then
            echo "${prog:-lesson}: error: $1=$2 matches more than one lesson ($lesson_name, ${lesson_dir_#lessons/})" >&2
            exit 2
        fi
        lesson_name=${lesson_dir_#lessons/}
    done
    if [ -z "$lesson_name" ]; then
        lesson_dir_=$(cd lessons 2>/dev/null && for d in [0-9][0-9]_*; do [ -d "$d" ] && printf '%s ' "$d"; done)
        echo "${prog:-lesson}: error: no lesson $1=$2 in lessons/ (they are: ${lesson_dir_% })" >&2
        exit 2
    fi
}
