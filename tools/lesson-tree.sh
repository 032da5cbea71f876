#!/bin/sh
# lesson-tree.sh: the files of a lesson, its own and those it inherits.
#
# A file lives in the lesson that introduces it or changes it. A later lesson
# that uses it unchanged names it in the table "Inherited files" of its
# README.md, one row per file, as a link to where it lives:
#
#   | [scanline.h](../04_scanline_inverse_z/scanline.h) | ... |
#
# The link's text is the file's path in the lesson (extras/shader.c), and its
# target is the same path in the earlier lesson that owns it. Nothing else of
# the README is read.
#
#   lesson-tree.sh list LESSON        one line per file of the lesson, sorted:
#                                     "<path in the lesson> <where it lives>"
#   lesson-tree.sh assemble DIR       DIR/<lesson>/ for every lesson: a relative
#                                     symbolic link per file to where it lives,
#                                     and the list of them in DIR/<lesson>/.files
#   lesson-tree.sh copy LESSON DEST   the lesson's files, as plain copies, in DEST
#   lesson-tree.sh check              every lesson's table is sound (below);
#                                     prints each fault, exit 1 if any
#
# LESSON is a directory name (07_depth_bias) or its number (07). Run from the
# top of the series. Exit status: 0 done, 1 a fault, 2 a usage error.
set -eu
prog=lesson-tree

usage() { echo "$prog: error: $1" >&2; exit 2; }

# 07 or 07_depth_bias -> lessons/07_depth_bias, or one line and status 2
# (a path such as ../.. or a pattern is no lesson: tools/lesson-name.sh).
. "$(dirname "$0")/lesson-name.sh"

# The rows of a lesson's README table: "<link text> <owner lesson> <path there>".
inherited() {
    [ -f "$1/README.md" ] || return 0
    awk '
        /^\| *\[[^]]+\]\(\.\.\/[0-9][0-9]_[A-Za-z0-9_]+\/[^)]+\) *\|/ {
            s = $0; sub(/^\| *\[/, "", s)
            text = s; sub(/\].*/, "", text)
            target = s; sub(/^[^]]*\]\(\.\.\//, "", target); sub(/\).*/, "", target)
            owner = target; sub(/\/.*/, "", owner)
            path = target; sub(/^[^\/]*\//, "", path)
            print text, owner, path
        }' "$1/README.md"
}

# list lessons/NN: own files (sources, found on disk), then inherited ones.
list() {
    dir=$1
    (cd "$dir" && find . -type f \( -name '*.c' -o -name '*.h' \) | sed 's|^\./||') |
        while read -r f; do echo "$f $dir/$f"; done
    # A file the lesson holds itself wins over a row that names it (check
    # reports the row); a row naming what is not there is an error.
    inherited "$dir" | while read -r text owner path; do
        [ -f "$dir/$text" ] && continue
        if [ ! -f "lessons/$owner/$path" ]; then
            echo "$prog: error: $dir/README.md inherits $text from lessons/$owner/$path, which is not there" >&2
            exit 1
        fi
        echo "$text lessons/$owner/$path"
    done
}

# assemble DIR: a lesson's links are made afresh when the list of its files
# differs from the one they were made from (DIR/<lesson>/.files), or when its
# links lead elsewhere (the tree was copied to another depth). The build
# compiles a lesson's files again when its .files changes (a link that now
# points elsewhere). A make that changes nothing costs one find (below).
assemble() {
    out=$1
    case $out in /*|*..*) usage "assemble wants a directory below the top, not $out" ;; esac
    # Every make runs this: when no directory under lessons/ and no README.md
    # changed since the last assembly into $out (DIR/.assembled is newer and
    # names $out: not a copy at another depth), and every lesson has its
    # list, the links are as they were: one find, no list.
    stamp=$out/.assembled was=""
    if [ -f "$stamp" ]; then read -r was <"$stamp" || was=""; fi
    if [ "$was" = "$out" ] &&
        [ -z "$(find lessons \( -type d -o -name README.md \) -newer "$stamp" | head -n 1)" ]; then
        whole=1
        for dir in lessons/[0-9][0-9]_*; do
            [ -d "$dir" ] && [ ! -f "$out/${dir#lessons/}/.files" ] && whole=0
        done
        [ $whole -eq 1 ] && return 0
    fi
    mkdir -p "$out" && echo "$out" >"$out/.assembling" # its time: before any file is listed
    for dir in lessons/[0-9][0-9]_*; do
        [ -d "$dir" ] || continue
        name=${dir#lessons/}
        want=$(list "$dir") || exit 1
        want=$(echo "$want" | sort)
        same=0
        [ -f "$out/$name/.files" ] && [ "$(cat "$out/$name/.files")" = "$want" ] && same=1
        # A tree copied to another depth has links that lead elsewhere: the
        # first link is read back to tell.
        if [ $same -eq 1 ]; then
            first=$(echo "$want" | awk -v lesson="$out/$name" 'NR == 1 {
                n = split(lesson "/" $1, part, "/"); up = ""
                for (i = 1; i < n; i++) if (part[i] != "" && part[i] != ".") up = up "../"
                print $1 " " up $2 }')
            [ "$(readlink "$out/$name/${first%% *}")" = "${first#* }" ] && continue
        fi
        [ $same -eq 0 ] || cp -p "$out/$name/.files" "$out/.files.$name"
        rm -rf "${out:?}/$name"
        mkdir -p "$out/$name"
        # "<path> <target>" -> ln -s with a path up to the top: one mkdir and
        # one ln a directory (ln -s TARGET... DIR names each link after its
        # target), one ln of its own for a link named otherwise.
        echo "$want" | awk -v lesson="$out/$name" '
            function base(p) { sub(/.*\//, "", p); return p }
            NF == 2 {
                link = lesson "/" $1
                n = split(link, part, "/"); up = ""
                for (i = 1; i < n; i++) if (part[i] != "" && part[i] != ".") up = up "../"
                dir = link; sub(/\/[^\/]*$/, "", dir)
                if (!(dir in targets)) { dirs[++ndirs] = dir; targets[dir] = "" }
                if (base($1) == base($2)) targets[dir] = targets[dir] " \"" up $2 "\""
                else others[dir] = others[dir] " && ln -s \"" up $2 "\" \"" link "\""
            }
            END {
                for (k = 1; k <= ndirs; k++) {
                    dir = dirs[k]
                    printf "mkdir -p \"%s\"", dir
                    if (targets[dir] != "") printf " && ln -s%s \"%s/\"", targets[dir], dir
                    printf "%s || exit 1\n", others[dir]
                }
            }' | sh || { echo "$prog: error: cannot make the links under $out/$name" >&2; exit 1; }
        # The same list keeps its time: only a new one rebuilds the lesson.
        if [ $same -eq 1 ]; then mv "$out/.files.$name" "$out/$name/.files"
        else echo "$want" >"$out/$name/.files"; fi
    done
    mv "$out/.assembling" "$stamp"
}

copy() {
    dir=$1 dest=$2
    files=$(list "$dir") || exit 1
    echo "$files" | while read -r rel target; do
        mkdir -p "$dest/$(dirname "$rel")" && cp "$target" "$dest/$rel" ||
            { echo "$prog: error: cannot copy $target to $dest/$rel" >&2; exit 1; }
    done
}

# check: each row names a file that exists in an earlier lesson, that the
# lesson does not also hold, and that is the latest version before it (no
# lesson in between owns one of its own) unless the row says why not, in
# parentheses after its "taught in" link; the link's text is its path there.
check() {
    faults=0
    for dir in lessons/[0-9][0-9]_*; do
        [ -d "$dir" ] || continue
        name=${dir#lessons/}
        rows=$(inherited "$dir")
        [ -n "$rows" ] || continue
        out=$(echo "$rows" | while read -r text owner path; do
            where="$dir/README.md: [$text](../$owner/$path)"
            if [ "$text" != "$path" ]; then echo "$where: the link's text is not its path there"; continue; fi
            if [ ! -f "lessons/$owner/$path" ]; then echo "$where: no such file"; continue; fi
            if [ ! "$owner" \< "$name" ]; then echo "$where: $owner is not an earlier lesson"; continue; fi
            if [ -f "$dir/$path" ]; then echo "$where: the lesson holds its own $path too"; continue; fi
            # "| [f](../06_x/f) | [06 x](../../docs/06_x.md) (not 08's: ...) |"
            why=$(awk -v f="[$text](../$owner/$path)" 'index($0, "| " f " |") == 1 &&
                $0 ~ /\]\([^)]*\.md\) *\([^)]+\) *\| *$/ { print "yes" }' "$dir/README.md")
            [ -n "$why" ] && continue
            for other in lessons/[0-9][0-9]_*; do
                o=${other#lessons/}
                if [ "$owner" \< "$o" ] && [ "$o" \< "$name" ] && [ -f "$other/$path" ]; then
                    echo "$where: $o has a later version of it"
                fi
            done
            n=$(echo "$rows" | awk -v f="$text" '$1 == f' | wc -l)
            [ "$n" -eq 1 ] || echo "$where: named $n times"
        done)
        if [ -n "$out" ]; then echo "$out"; faults=1; fi
    done
    return $faults
}

[ $# -ge 1 ] || usage "usage: lesson-tree.sh list LESSON | assemble DIR | copy LESSON DEST | check"
[ -d lessons ] || usage "run it from the top of the series (where lessons/ is)"
case $1 in
    list) [ $# -eq 2 ] || usage "usage: lesson-tree.sh list LESSON"
          lesson_name LESSON "$2"
          files=$(list "lessons/$lesson_name") || exit 1
          echo "$files" | sort ;;
    assemble) [ $# -eq 2 ] || usage "usage: lesson-tree.sh assemble DIR"
          assemble "${2%/}" ;;
    copy) [ $# -eq 3 ] || usage "usage: lesson-tree.sh copy LESSON DEST"
          lesson_name LESSON "$2"
          copy "lessons/$lesson_name" "$3" ;;
    check) [ $# -eq 1 ] || usage "usage: lesson-tree.sh check"
          check ;;
    *) usage "unknown command $1" ;;
esac
