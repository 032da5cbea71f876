#!/bin/sh
# seed_build.sh FROM TO: before TO's first make, the objects that FROM has
# already compiled from the same files, so that make compiles only the rest.
# test_handout runs it for each handout it builds (FROM: the series, or the
# first handout).
#
# FROM and TO are the tops of two trees, each built in its build/. An object
# of FROM's build/obj is copied, with its .d, when it is up to date there
# (no file it reads is newer) and every file its .d names (its source and
# each header it includes), and the Makefile, are in TO byte for byte as in
# FROM: the compiler would make the same object. One that reads a file TO
# has otherwise (a lesson's file with its solution taken out, and every
# object that includes it) is left to make. The copies are given the time
# of the copy, later than TO's files: make finds them up to date; a file of
# TO changed afterwards (the solution put back) is later than they are, and
# make compiles again what reads it, as the .d says.
# Also copied: build/tools (the built tools) and build/.deps-ok.
set -eu
from=$1 to=$2
if [ ! -d "$from/build/obj" ] || [ ! -d "$to" ]; then
    echo "seed_build: usage: seed_build.sh FROM TO (FROM built)" >&2
    exit 2
fi
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT

# TO's lessons linked as make links them (build/lessons/NN/ -> lessons/...),
# the paths the .d files name.
(cd "$to" && sh tools/lesson-tree.sh assemble build/lessons)

# "<object> <file it reads>", one line per file, from the first rule of
# every .d of FROM ("obj: file file \" and the lines it goes on to).
# shellcheck disable=SC2016 # an awk program
(cd "$from" && find build/obj -name '*.d' -print0 | xargs -0 awk '
    FNR == 1 { done = 0 }
    done { next }
    {
        line = $0; more = sub(/\\$/, "", line)
        n = split(line, word, " ")
        for (i = 1; i <= n; i++)
            if (FNR == 1 && i == 1) { obj = word[1]; sub(/:$/, "", obj); print obj, "Makefile" }
            else print obj, word[i]
        if (!more) done = 1
    }') >"$work/reads"

# Each file named, once: the same in both trees, or not.
cut -d' ' -f2 "$work/reads" | sort -u >"$work/files"
(cd "$from" && xargs md5sum <"$work/files") >"$work/from.sum" 2>/dev/null || true
(cd "$to" && xargs md5sum <"$work/files") >"$work/to.sum" 2>/dev/null || true

# The objects FROM's make would compile again (a file they read is newer;
# the Makefile aside, as make does): not copied. (-nt: dash's, bash's and
# busybox's test have it.)
# shellcheck disable=SC3013
while read -r obj file; do
    [ "$file" != Makefile ] && [ "$from/$file" -nt "$from/$obj" ] && echo "$obj"
done <"$work/reads" >"$work/stale" || true

# The objects all of whose files are the same, and their .d.
awk 'FILENAME == ARGV[1] { sum[$2] = $1; next }
     FILENAME == ARGV[2] { same[$2] = (sum[$2] == $1); next }
     FILENAME == ARGV[3] { stale[$1] = 1; next }
     { obj = $1; if (!(obj in ok)) ok[obj] = !(obj in stale); if (!same[$2]) ok[obj] = 0 }
     END { for (o in ok) if (ok[o]) { print o; d = o; sub(/\.o$/, ".d", d); print d } }' \
    "$work/from.sum" "$work/to.sum" "$work/stale" "$work/reads" >"$work/copy"

# Copied with the time of the copy (tar -m), not FROM's.
(cd "$from" && tar -cf - -T "$work/copy" build/tools build/.deps-ok) | (cd "$to" && tar -xmf -)
echo "seed_build: $(($(wc -l <"$work/copy") / 2)) objects of $(cd "$from" && find build/obj -name '*.o' | wc -l) copied"
