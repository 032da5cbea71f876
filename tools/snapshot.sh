#!/bin/sh
# snapshot.sh: one lesson as a directory that builds on its own.
#
#   sh tools/snapshot.sh [--build DIR] [--dest DIR] LESSON
#   (make snapshot LESSON=07 [DEST=dir] calls it)
#
# Writes the lesson's own files and those it inherits from earlier lessons
# (tools/lesson-tree.sh), as plain files where the lesson's build finds
# them (main.c, clip.c, ..., extras/), common/, and a Makefile of a few lines:
# `make` there builds the lesson's program with the series' flags, and
# `make run` runs it into out/. It needs what the series needs: a C compiler,
# make, pkg-config, and Debian's libstb-dev and zlib1g-dev.
#
# DEST defaults to BUILD/snapshot/<lesson>. An existing DEST is replaced only
# if it is empty or an earlier snapshot (it holds the file .snapshot).
# Exit status: 0 done, 1 failed (a copy), 2 usage error.
set -eu
prog=snapshot
usage() {
    echo "$prog: error: $1" >&2
    echo "usage: make snapshot LESSON=NN [DEST=dir]" >&2
    exit 2
}
die() { echo "$prog: error: $1" >&2; [ -n "${tmp:-}" ] && rm -rf "$tmp"; exit 1; }

build=build dest="" lesson=""
while [ $# -gt 0 ]; do
    case $1 in
        --dest) [ $# -ge 2 ] || usage "--dest wants a directory"; dest=$2; shift ;;
        --build) [ $# -ge 2 ] || usage "--build wants a directory"; build=$2; shift ;;
        -*) usage "unknown option $1" ;;
        *) [ -z "$lesson" ] || usage "one lesson at a time (got $lesson and $1)"; lesson=$1 ;;
    esac
    shift
done
[ -n "$lesson" ] || usage "which lesson? e.g. LESSON=07"
[ -f Makefile ] && [ -d lessons ] && [ -d common ] ||
    usage "run it from the top of the series (where the Makefile is)"
# LESSON=07 or 07_depth_bias: one lesson, never a path (tools/lesson-name.sh).
. "$(dirname "$0")/lesson-name.sh"
lesson_name LESSON "$lesson"
name=$lesson_name
[ -f "lessons/$name/main.c" ] || usage "lessons/$name has no main.c: not a lesson to build"

[ -n "$dest" ] || dest="$build/snapshot/$name"
# Without its trailing slashes, but / stays / (refused below, as not empty).
while [ "${dest%/}" != "$dest" ] && [ -n "${dest%/}" ]; do dest=${dest%/}; done
if [ -e "$dest" ]; then
    [ -d "$dest" ] || usage "DEST=$dest exists and is not a directory"
    if [ ! -f "$dest/.snapshot" ] && [ -n "$(ls -A "$dest")" ]; then
        usage "DEST=$dest exists and is not an earlier snapshot: remove it or pick another DEST"
    fi
fi
mkdir -p "$(dirname "$dest")" || die "cannot create $(dirname "$dest")"
tmp="$dest.tmp.$$"
rm -rf "$tmp"
mkdir "$tmp" || die "cannot create $tmp"
# A signal ends the run, its copy removed (a trap that did not exit would go on).
trap 'rm -rf "$tmp"; exit 129' HUP
trap 'rm -rf "$tmp"; exit 130' INT
trap 'rm -rf "$tmp"; exit 143' TERM

sh tools/lesson-tree.sh copy "$name" "$tmp" || die "cannot copy the files of lessons/$name"
cp -R common "$tmp/common" || die "cannot copy common/"
sh tools/lesson-tree.sh list "$name" | awk '{ print $1 "\t" $2 }' >"$tmp/FILES" ||
    die "cannot list the files of lessons/$name"

cat >"$tmp/Makefile" <<EOF
# $name: lesson ${name%%_*} of the series, with the files it inherits (FILES
# says where each lives in the series) and common/.
#   make        builds ./$name
#   make run    runs it: the picture goes to out/$name.png
CC     ?= cc
CFLAGS ?= -O2 -g
WARN   := -std=c11 -Wall -Wextra -Werror -pedantic -Wshadow -Wconversion -Wmissing-prototypes
SRC    := \$(wildcard *.c extras/*.c common/*.c common/harness/*.c)

$name: \$(SRC) \$(wildcard *.h extras/*.h common/*.h common/harness/*.h)
	\$(CC) -D_POSIX_C_SOURCE=200809L -I. -Icommon \$(shell pkg-config --cflags stb zlib) \\
	    \$(CFLAGS) \$(WARN) -ffp-contract=off \$(SRC) -o \$@ \$(shell pkg-config --libs stb zlib) -lm -pthread

run: $name
	mkdir -p out && ./$name

clean:
	rm -f $name

.PHONY: run clean
EOF
echo "snapshot of lessons/$name, made by make snapshot" >"$tmp/.snapshot"
rm -rf "$dest"
mv "$tmp" "$dest" || die "cannot move the snapshot to $dest"
tmp=""
echo "$prog: wrote $dest: lessons/$name with $(grep -c "	lessons/$name/" "$dest/FILES") file(s) of its own, $(grep -vc "	lessons/$name/" "$dest/FILES") inherited, and common/; build it with: make -C $(case $dest in *[!A-Za-z0-9_./-]*) printf "'%s'" "$dest" ;; *) printf '%s' "$dest" ;; esac)"
