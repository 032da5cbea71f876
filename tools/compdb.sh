#!/bin/sh
# compdb.sh IN OUT COMPDB_BUILD BUILD: the compile_commands.json that editors
# read, from what bear recorded of a build in COMPDB_BUILD (make
# compile_commands.json).
#
# A lesson is compiled where make links its files together (tools/lesson-tree.sh):
# COMPDB_BUILD/lessons/NN_name/clip.c, a link to lessons/05_clipping/clip.c. The
# recorded build is removed afterwards, so its paths become BUILD's, whose
# links every make keeps; and the entry of each file a lesson owns names the
# file itself (lessons/05_clipping/clip.c), as an editor opens it, compiled as
# in its own lesson. Entries of inherited files keep their link's name: an
# editor has the owner's entry for the file itself.
set -eu
[ $# -eq 4 ] || { echo "usage: compdb.sh IN OUT COMPDB_BUILD BUILD" >&2; exit 2; }
in=$1 out=$2 from=$3 to=$4
top=$(pwd)
# Every "COMPDB_BUILD/lessons/" (relative, or under the top) becomes BUILD's.
sed -e "s|$from/lessons/|$to/lessons/|g" "$in" | awk -v top="$top" -v tree="$to/lessons/" '
    /"file": *"/ {
        path = $0; sub(/^[^"]*"file": *"/, "", path); sub(/".*/, "", path)
        rel = path; if (index(rel, top "/") == 1) rel = substr(rel, length(top) + 2)
        if (index(rel, tree) == 1) {
            lesson = substr(rel, length(tree) + 1); sub(/\/.*/, "", lesson)
            cmd = "readlink -f \"" top "/" rel "\""
            real = ""; cmd | getline real; close(cmd)
            if (index(real, top "/lessons/" lesson "/") == 1) sub(/"file": *"[^"]*"/, "\"file\": \"" real "\"")
        }
    }
    { print }' >"$out"
