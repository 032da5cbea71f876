/* fuzz_10_fast_raster.c: lesson 10's fast rasterizer (fast_raster.c and
 * extras/) against faces in clip space with any coordinates, on screens of
 * any size (make fuzz FUZZ=10), in every format and mapping, with lesson
 * 07's bias and faces in `cutout`. Drawn twice: counting, one fragment at a
 * time, with the checks of fuzz_clip.h; then as fast as it goes (blocks,
 * the --simd the bytes pick, 1 to 3 threads, counting or not): the depth
 * and face buffers are the same to the bit. */
#include "engine.h" /* the lesson's extras/: simd_best */
#include "state.h"

#include "fuzz_depth.h"

static void finish(Target *t, LessonState *state)
{
    fuzz_check(fast_finish(t, state, NULL), "fast_finish has the memory");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    FuzzBytes b = {data, size};
    FuzzScene s;
    fuzz_scene(&s, &b);
    DepthSetup depth = fuzz_depth_setup(&s, &b, false);
    DepthBias bias = fuzz_bias(&s, &b);
    uint8_t pick = fuzz_u8(&b);
    Simd simd = (Simd)(pick % 5);
    if (simd > simd_best())
        simd = simd_best();
    Target counted, fast;
    fuzz_target(&counted, &s);
    fuzz_target(&fast, &s);
    fast.counting = pick >> 7; /* off: the benchmark's frames, hidden blocks skipped first */
    HierarchicalZ h1 = {0}, h2 = {0};
    Error err;
    fuzz_check(hiz_begin(&h1, &counted, BLOCK_SIZE, &err) && hiz_begin(&h2, &fast, BLOCK_SIZE, &err),
               "hiz_begin");

    LessonState one = fast_raster(depth, SIMD_NONE, 1, true);
    one.bias = bias, one.hiz = &h1;
    Rasterizer rz = FAST_ZBUFFER;
    rz.state = &one;
    fuzz_draw(&s, &rz, &counted, finish);

    LessonState all = fast_raster(depth, simd, 1 + (pick >> 2) % 3, false);
    all.bias = bias, all.hiz = &h2;
    rz.state = &all;
    rz.clear(&fast, &all);
    for (int f = 0; f < s.nfaces; f++)
        if (render_face_clippable(&s.face[f]))
            rz.draw_face(&fast, &all, &s.face[f], &s.ctx);
    finish(&fast, &all);
    fuzz_check(fuzz_same_buffers(&counted, &fast),
               "blocks, SIMD and threads draw what one fragment at a time draws");

    fast_raster_free(&one.fast);
    fast_raster_free(&all.fast);
    hiz_free(&h1);
    hiz_free(&h2);
    target_free(&counted);
    target_free(&fast);
    return 0;
}
