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

# The numbers of one gpu_reference run: covered, same-face %, differing, depth.
numbers() {
    awk '/agreement:/ { covered = $2; pct = $10; differ = $11 }
         /^  depth:/ { rel = $5 }
         END { gsub(/[(),%]/, "", pct); print covered, pct, differ, rel }' "$1"
}

# One row of the table: lesson on scene, in a directory of its own.
row() { # lesson scene dir
    "$bin/$1" --scene "$2" --out "$3/p.png" --id-out "$3/id.png" \
        --depth-out "$3/d.pfm" >"$3/lesson.txt"
    dropped=$(sed -n 's/.* \([0-9][0-9]*\) dropped at the near plane.*/\1/p' "$3/lesson.txt")
    if [ "$1" != 05_clipping ] && [ "${dropped:-0}" -gt 0 ]; then
        printf '%-22s %-15s (drops %s triangles at the near plane: not compared)\n' \
            "$1" "$2" "$dropped"
        return 0
    fi
    for snap in "" --snap; do
        # shellcheck disable=SC2086 # $snap is one flag or none
        "$gpu" --scene "$2" --depth-format float32 --depth-mapping reversed --far inf \
            $snap --agree-id "$3/id.png" --agree-depth "$3/d.pfm" >"$3/gpu$snap.txt"
    done
    # shellcheck disable=SC2046 # one word per number
    set -- "$1" "$2" $(numbers "$3/gpu.txt") $(numbers "$3/gpu--snap.txt")
    printf '%-22s %-15s %9s %9s%% %7s %11s %11s\n' "$1" "$2" "$3" "$4" "$5" "$6" "${10}"
}

# The rows run side by side, as many at once as there are cores, each
# into a file of its own, with .ok beside it when it worked (set -e ends
# the job at its first failure); then they are printed in order.
cores=$(nproc 2>/dev/null || echo 1)
n=0
for lesson in 03_perspective_z 04_scanline_inverse_z 05_clipping; do
    for scene in $scenes; do
        n=$((n + 1))
        job=$work/$(printf %04d "$n")
        mkdir -p "$job"
        { row "$lesson" "$scene" "$job" >"$job.row"; : >"$job.ok"; } & # set -e ends it at a failure
        [ $((n % cores)) -ne 0 ] || wait
    done
done
wait
printf '%-22s %-15s %9s %10s %7s %11s %11s\n' lesson scene covered "same face" differ \
    "depth" "depth snap"
for k in $(seq 1 "$n"); do
    job=$work/$(printf %04d "$k")
    cat "$job.row"
    [ -f "$job.ok" ] || { echo "gpu-check: a run failed (above)" >&2; exit 1; }
done
