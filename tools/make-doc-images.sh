#!/bin/sh
# make-doc-images.sh [BUILD [IMAGES]]: renders the pictures the lesson pages
# show into IMAGES (default: docs/images/), with the lessons themselves. BUILD
# is the build directory (default: build). One section per lesson; a
# lesson's pages name these files. tests/tools/test_doc_images.c renders
# them into a directory of its own and compares them with docs/images/.
set -eu
cd "$(dirname "$0")/.."
build=${1:-build}
images=${2:-docs/images}
mkdir -p "$images"
# Where a render goes that only its --world-out picture is wanted from.
tmp_out="$build/doc-images-render.png"

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
# The camera, its frustum and triangles3 from the side and from above
"$l02" --out "$tmp_out" --world-out "$images/02_world.png" >/dev/null
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

# ---- 03_perspective_z: grazing with each rule and where the rules differ,
# also on cubes and interpenetrate, the negated-w bug on cubes, and a torus
# knot written as OBJ by tools/make_obj
make -s BUILD="$build" "$build/bin/03_perspective_z" "$build/tools/make_obj"
l03="$build/bin/03_perspective_z"
size="--width 400 --height 300"
"$l03" $size --out "$images/03_grazing.png" \
       --compare-naive "$images/03_grazing_compare.png" >/dev/null
"$l03" $size --depth-interp naive --out "$images/03_grazing_naive.png" >/dev/null
# The two strips from the side and from above, stretched vertically to read
"$l03" --out "$tmp_out" --world-out "$images/03_grazing_world.png" >/dev/null
"$l03" $size --scene cubes --out "$images/03_cubes.png" \
       --compare-naive "$images/03_cubes_compare.png" >/dev/null
"$l03" $size --scene interpenetrate --out "$images/03_interpenetrate.png" \
       --compare-naive "$images/03_interpenetrate_compare.png" >/dev/null
"$l03" $size --scene cubes --bug negated-w --out "$images/03_cubes_negated_w.png" >/dev/null
tmp=$(mktemp -d)
"$build/tools/make_obj" knot "$tmp/knot.obj" >/dev/null
"$l03" --obj "$tmp/knot.obj" --out "$images/03_knot.png" >/dev/null
rm -rf "$tmp"
echo "make-doc-images: 03_perspective_z done"

# ---- 04_scanline_inverse_z: the walls, their depth shading, and De Goes'
# two z-buffers on an 8 x 3 screen, magnified with the triangle's true edges.
# Camera at the origin looking down -Z, fovy 90: screen (x_s, y_s) at depth d
# is world x = (x_s / 4 - 1) * d * 8/3, y = (1 - y_s / 1.5) * d.
make -s BUILD="$build" "$build/bin/04_scanline_inverse_z" "$build/tools/magnify"
l04="$build/bin/04_scanline_inverse_z"
"$l04" --out "$images/04_walls.png" >/dev/null
"$l04" --shade depth --out "$images/04_walls_depth.png" >/dev/null
tmp=$(mktemp -d)
cat >"$tmp/two_buffers.obj" <<'OBJ'
v 0 5 -5
v 13.333333333333334 -5 -5
v -13.333333333333334 -5 -5
v -16 6 -6
v 16 6 -6
v 16 -6 -6
v -16 -6 -6
f 1 2 3
f 4 5 6 7
OBJ
"$l04" --obj "$tmp/two_buffers.obj" --eye 0,0,0 --target 0,0,-1 --up 0,1,0 --fovy 90 --near 1 \
       --far 10 --width 8 --height 3 --out "$tmp/two_buffers.png" >/dev/null
"$build/tools/magnify" "$tmp/two_buffers.png" "$images/04_spans.png" 48 4,0,8,3 8,3,0,3 0,3,4,0
rm -rf "$tmp"
echo "make-doc-images: 04_scanline_inverse_z done"

# ---- 05_clipping: the inside scene clipped, as lesson 04 draws it (faces
# through the near plane dropped), the pixels lesson 04 gets wrong, the
# no-clip bug, and the depth shading.
make -s BUILD="$build" "$build/bin/05_clipping" "$build/bin/04_scanline_inverse_z"
l05="$build/bin/05_clipping"
"$l05" --out "$images/05_inside.png" --compare-drop "$images/05_inside_compare_drop.png" >/dev/null
"$build/bin/04_scanline_inverse_z" --scene inside --out "$images/05_inside_as_04.png" >/dev/null
"$l05" --bug no-clip --out "$images/05_inside_no_clip.png" >/dev/null
"$l05" --shade depth --out "$images/05_inside_depth.png" >/dev/null
echo "make-doc-images: 05_clipping done"

# ---- 06_depth_precision: the ladder in unorm16, unorm24 and reversed
# float32, labelled (each band's d, and a key), and the precision plot at
# near 0.1, far 1000.
make -s BUILD="$build" "$build/bin/06_depth_precision"
l06="$build/bin/06_depth_precision"
"$l06" --depth-format unorm16 --out "$tmp_out" --ladder-out "$images/06_ladder_unorm16.png" >/dev/null
"$l06" --depth-format unorm24 --out "$tmp_out" --ladder-out "$images/06_ladder_unorm24.png" \
       --precision-plot "$images/06_precision_plot.png" >/dev/null
"$l06" --depth-format float32 --depth-mapping reversed --out "$tmp_out" \
       --ladder-out "$images/06_ladder_float32_reversed.png" >/dev/null
echo "make-doc-images: 06_depth_precision done"

# ---- 07_depth_bias: the decals scene with no bias, units only, the
# recommended bias and far too much (the pictures of its tests, at 400 x 300).
make -s BUILD="$build" "$build/bin/07_depth_bias"
l07="$build/bin/07_depth_bias"
for pair in no_bias:0,0 units_only:0,-2 recommended:-1,-1 too_much:-1000,-1000; do
    "$l07" --width 400 --height 300 --polygon-offset "${pair#*:}" \
           --out "$images/07_${pair%%:*}.png" >/dev/null
done
echo "make-doc-images: 07_depth_bias done"

# ---- 08_early_z: crowd's heat maps of times shaded (late, early unsorted,
# early front to back, prepass), its shader's picture, and a fence close up
# with and without --bug early-z-with-discard.
make -s BUILD="$build" "$build/bin/08_early_z"
l08="$build/bin/08_early_z"
for pair in late:late:none early:early:none sorted:early:front-to-back prepass:prepass:none; do
    rest=${pair#*:}
    "$l08" --z-mode "${rest%%:*}" --sort "${rest#*:}" --out "$tmp_out" \
           --shade-count-out "$images/08_heat_${pair%%:*}.png" >/dev/null
done
"$l08" --out "$tmp_out" --colour-out "$images/08_crowd.png" >/dev/null
for bug in "" early-z-with-discard; do # close behind the first fence
    "$l08" --width 400 --height 300 --eye 0,0.8,-5 --target 0,0.6,-12 ${bug:+--bug "$bug"} \
           --out "$tmp_out" --colour-out "$images/08_fence${bug:+_bug}.png" >/dev/null
done
echo "make-doc-images: 08_early_z done"

# ---- 09_hierarchical_z: city's tile buffer and its skips, city seen from above (the city
# behind the wall), and the heat maps of times shaded with late-Z in
# lessons 08 and 09 (late shades every fragment tested: the skipped ones
# are neither tested nor shaded).
make -s BUILD="$build" "$build/bin/09_hierarchical_z"
l09="$build/bin/09_hierarchical_z"
"$l09" --out "$tmp_out" --hiz-out "$images/09_tiles.png" \
       --skip-out "$images/09_skips.png" --world-out "$images/09_world.png" >/dev/null
"$l08" --scene city --z-mode late --out "$tmp_out" \
       --shade-count-out "$images/09_heat_08.png" >/dev/null
"$l09" --z-mode late --out "$tmp_out" --shade-count-out "$images/09_heat_09.png" >/dev/null
echo "make-doc-images: 09_hierarchical_z done"

# ---- Diagrams drawn by code (tools/diagrams.c): lesson 02's edge functions
# and top-left rule, lesson 03's d and 1/d along a row, lesson 04's edge walk
make -s BUILD="$build" "$build/tools/diagrams"
"$build/tools/diagrams" "$images"
echo "make-doc-images: diagrams done"

# ---- 10_fast_raster: the crowd, and the chart of what each step gains, from
# the times measured with make bench (docs/data/10_steps.csv, the page's table)
make -s BUILD="$build" "$build/bin/10_fast_raster" "$build/tools/bar_chart"
"$build/bin/10_fast_raster" --scene crowd --out "$images/10_crowd.png" >/dev/null
"$build/tools/bar_chart" docs/data/10_steps.csv "$images/10_steps.png" \
    "ms per frame, 1 thread but where marked (less is faster)"
echo "make-doc-images: 10_fast_raster done"

# ---- docs/tools.md: the diff picture of --compare, and --steps of triangles3
make -s BUILD="$build" "$build/bin/02_zbuffer"
rm -rf "$images/tools_steps"
"$build/bin/02_zbuffer" --bug separate-buffers --out "$build/doc-images-bug.png" \
    --compare tests/expected/02_zbuffer/default.png >/dev/null || [ $? -eq 3 ] # they differ
mv "$build/doc-images-bug.diff.png" "$images/tools_compare_diff.png"
rm -f "$build/doc-images-bug.png"
"$build/bin/02_zbuffer" --width 320 --height 240 --out "$tmp_out" --steps "$images/tools_steps" >/dev/null
rm -f "$tmp_out"
echo "make-doc-images: tools done"
