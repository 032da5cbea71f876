#!/bin/sh
# make gpu-check: how far lessons 03, 04 and 05 agree with the GPU reference
# (tests/gpu/gpu_reference.c, Mesa's llvmpipe) on every built-in scene, at the
# default size. One row per lesson and scene:
#   covered     pixels that the lesson or the GPU (or both) covers
#   same face   the share of them where both show the same face
#   depth       the largest relative difference of view depth d where both
#               show the same face, against the GPU as it is, then against
#               the GPU given the lessons' corners snapped to 1/256 pixel
#               (--snap): the difference the snapping makes, set apart
# The GPU's depth is float32, reversed, far at infinity: the most exact it has.
# It draws each scene twice, as it is and --snap, and each drawing is compared
# with all three lessons' pictures (--agree-id and --agree-depth take lists).
# Lessons 03 and 04 drop faces with a corner at or behind the near plane,
# which the GPU clips: their rows for such scenes say so instead.
#
#   BIN_DIR=build/bin GPU_REF=build/tools/gpu_reference sh tools/gpu-check.sh [SCENE...]
set -eu
bin=${BIN_DIR:-build/bin}
gpu=${GPU_REF:-build/tools/gpu_reference}
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT

scenes=$*
[ -n "$scenes" ] ||
    scenes=$("$bin/05_clipping" --help | sed -n '/^Scenes:/,/^$/p' | awk 'NR > 1 && NF { print $1 }')

# The numbers of the k-th lesson in one gpu_reference run: covered,
# same-face %, differing, depth.
numbers() { # file k
    awk -v k="$2" '/agreement:/ && ++a == k { covered = $2; pct = $10; differ = $11 }
         /^  depth:/ && ++d == k { rel = $5 }
         END { gsub(/[(),%]/, "", pct); print covered, pct, differ, rel }' "$1"
}

lessons="03_perspective_z 04_scanline_inverse_z 05_clipping"

# One scene, in a directory of its own: each lesson's pictures, then the GPU
# twice (as it is, and --snap), each run comparing every lesson that draws
# the scene whole; one row per lesson into dir/<lesson>.row.
scene_rows() { # scene dir
    scene=$1 dir=$2 ids="" depths="" compared=""
    for lesson in $lessons; do
        mkdir -p "$dir/$lesson"
        "$bin/$lesson" --scene "$scene" --out "$dir/$lesson/p.png" --id-out "$dir/$lesson/id.png" \
            --depth-out "$dir/$lesson/d.pfm" >"$dir/$lesson/lesson.txt"
        dropped=$(sed -n 's/.* \([0-9][0-9]*\) dropped at the near plane.*/\1/p' "$dir/$lesson/lesson.txt")
        if [ "$lesson" != 05_clipping ] && [ "${dropped:-0}" -gt 0 ]; then
            printf '%-22s %-15s (drops %s triangles at the near plane: not compared)\n' \
                "$lesson" "$scene" "$dropped" >"$dir/$lesson.row"
            continue
        fi
        compared="$compared $lesson"
        ids="$ids${ids:+,}$dir/$lesson/id.png"
        depths="$depths${depths:+,}$dir/$lesson/d.pfm"
    done
    for snap in "" --snap; do
        # shellcheck disable=SC2086 # $snap is one flag or none
        "$gpu" --scene "$scene" --depth-format float32 --depth-mapping reversed --far inf \
            $snap --agree-id "$ids" --agree-depth "$depths" >"$dir/gpu$snap.txt"
    done
    k=0
    for lesson in $compared; do
        k=$((k + 1))
        # shellcheck disable=SC2046 # one word per number
        set -- $(numbers "$dir/gpu.txt" "$k") $(numbers "$dir/gpu--snap.txt" "$k")
        printf '%-22s %-15s %9s %9s%% %7s %11s %11s\n' "$lesson" "$scene" "$1" "$2" "$3" "$4" "$8" \
            >"$dir/$lesson.row"
    done
}

# The scenes run side by side, as many at once as there are cores, each
# into a directory of its own, with .ok beside it when it worked (set -e
# ends the job at its first failure); then the rows are printed, lesson by
# lesson, each scene in order.
cores=$(nproc 2>/dev/null || echo 1)
n=0
for scene in $scenes; do
    n=$((n + 1))
    job=$work/$(printf %04d "$n")
    mkdir -p "$job"
    { scene_rows "$scene" "$job"; : >"$job.ok"; } & # set -e ends it at a failure
    [ $((n % cores)) -ne 0 ] || wait
done
wait
for k in $(seq 1 "$n"); do
    [ -f "$work/$(printf %04d "$k").ok" ] || { echo "gpu-check: a run failed" >&2; exit 1; }
done
printf '%-22s %-15s %9s %10s %7s %11s %11s\n' lesson scene covered "same face" differ \
    "depth" "depth snap"
for lesson in $lessons; do
    for k in $(seq 1 "$n"); do
        cat "$work/$(printf %04d "$k")/$lesson.row"
    done
done
