#!/bin/sh
# make-doc-images.sh [BUILD]: renders the pictures the lesson pages show into
# docs/images/, with the lessons themselves. BUILD is the build directory
# (default: build). One section per lesson; a lesson's pages name these files.
set -eu
cd "$(dirname "$0")/.."
build=${1:-build}
images=docs/images
mkdir -p "$images"

# ---- 01_ybuffer: render, y-buffer strip, the world from above, the steps, another order
make -s BUILD="$build" "$build/bin/01_ybuffer"
l01="$build/bin/01_ybuffer"
rm -rf "$images/01_steps"
"$l01" --out "$images/01_render.png" --ybuffer-out "$images/01_ybuffer.png" \
       --scene-out "$images/01_scene.png" --steps "$images/01_steps" >/dev/null
"$l01" --order 312 --out "$images/01_order_312.png" >/dev/null
echo "make-doc-images: 01_ybuffer done"

# ---- 02_zbuffer: triangles3 right and painted, the two bugs, a shared edge up close
make -s BUILD="$build" "$build/bin/02_zbuffer" "$build/tools/magnify"
l02="$build/bin/02_zbuffer"
size="--width 400 --height 300"
"$l02" $size --out "$images/02_triangles3.png" >/dev/null
"$l02" $size --painter --out "$images/02_triangles3_painter.png" >/dev/null
"$l02" $size --shade depth --out "$images/02_triangles3_depth.png" >/dev/null
"$l02" $size --scene interpenetrate --out "$images/02_interpenetrate.png" >/dev/null
"$l02" $size --scene interpenetrate --bug separate-buffers \
       --out "$images/02_bug_separate_buffers.png" >/dev/null
"$l02" $size --bug clear-zero --out "$images/02_bug_clear_zero.png" >/dev/null
"$l02" --scene cubes --out "$images/02_cubes.png" >/dev/null
# Two triangles sharing the edge from pixel centre (1.5, 0.5) to (10.5, 6.5) of
# a 12 x 8 screen: seen from (0, 0, 1) with fovy 90, the plane z = 0 maps to
# the screen by x_s = 4 x + 6, y_s = 4 - 4 y.
tmp=$(mktemp -d)
cat >"$tmp/shared_edge.obj" <<'OBJ'
v -1.125 0.875 0
v 1.125 -0.625 0
v 1.45 0.925 0
v -1.425 -0.925 0
f 1 3 2
f 1 2 4
OBJ
"$l02" --obj "$tmp/shared_edge.obj" --width 12 --height 8 --eye 0,0,1 --target 0,0,0 \
       --fovy 90 --near 0.5 --far 2 --out "$tmp/shared_edge.png" >/dev/null
"$build/tools/magnify" "$tmp/shared_edge.png" "$images/02_shared_edge.png" 40 \
    1.5,0.5,10.5,6.5 1.5,0.5,11.8,0.3 11.8,0.3,10.5,6.5 1.5,0.5,0.3,7.7 0.3,7.7,10.5,6.5
rm -rf "$tmp"
echo "make-doc-images: 02_zbuffer done"
