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

printf '%-22s %-15s %9s %10s %7s %11s %11s\n' lesson scene covered "same face" differ \
    "depth" "depth snap"
for lesson in 03_perspective_z 04_scanline_inverse_z 05_clipping; do
    for scene in $scenes; do
        "$bin/$lesson" --scene "$scene" --out "$work/p.png" --id-out "$work/id.png" \
            --depth-out "$work/d.pfm" >"$work/lesson.txt"
        dropped=$(sed -n 's/.* \([0-9][0-9]*\) dropped at the near plane.*/\1/p' "$work/lesson.txt")
        if [ "$lesson" != 05_clipping ] && [ "${dropped:-0}" -gt 0 ]; then
            printf '%-22s %-15s (drops %s triangles at the near plane: not compared)\n' \
                "$lesson" "$scene" "$dropped"
            continue
        fi
        for snap in "" --snap; do
            # shellcheck disable=SC2086 # $snap is one flag or none
            "$gpu" --scene "$scene" --depth-format float32 --depth-mapping reversed --far inf \
                $snap --agree-id "$work/id.png" --agree-depth "$work/d.pfm" >"$work/gpu$snap.txt"
        done
        set -- $(numbers "$work/gpu.txt") $(numbers "$work/gpu--snap.txt")
        printf '%-22s %-15s %9s %9s%% %7s %11s %11s\n' "$lesson" "$scene" "$1" "$2" "$3" "$4" "$8"
    done
done
