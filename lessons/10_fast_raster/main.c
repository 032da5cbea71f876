/* main.c: lesson 10, a fast rasterizer (docs/10_fast_raster.md): the outline.
 * What it teaches is in fast_raster.c (lesson 09's pictures in tiles and
 * blocks, each asking lesson 09's tile buffer first; threads) and simd.c.
 * What it shows but does not teach (flags, plain C and SSE2, memory): extras/. */
#include "extras/extras.h" /* and lesson 09's hierarchical_z.h */
#include "fast_raster.h"
#include "harness/lesson.h"
#include "state.h"

static const Lesson LESSON = {
    .program = "10_fast_raster",
    .purpose = "Lesson 10: a fast rasterizer: lesson 09's pictures drawn in tiles and blocks, "
               "with SIMD and threads.",
    .scene = "crowd",
    .rasterizer = &FAST_ZBUFFER,
    .depth_rule = {"depth buffer", "z_w", "face", SMALLER_IS_NEARER}, /* reversed: extras */
    .extras = &EXTRAS,
    .report = print_engine, /* tiles, blocks, SIMD, threads, the tile buffer */
};

int main(int argc, char **argv)
{
    Run run;
    int status = run_load(&run, &LESSON, argc, argv); /* load: the command line, the scene */
    if (status != RUN_GO)
        return status;
    LessonState state = fast_chosen(&run);             /* --simd, --threads, the depth flags */
    HierarchicalZ h = {0};
    if (!hiz_begin(&h, &run.target, BLOCK_SIZE, &run.err)) { /* the tiles: one per block */
        hiz_free(&h);
        return run_end(&run);
    }
    state.hiz = &h;
    run.rasterizer.state = &state;                     /* the format, the engine, the tiles */
    run.rz->clear(&run.target, run.rz->state);         /* clear: each tile, when drawn */
    if (run_draw(&run) &&                              /* draw: each face set up, binned */
        fast_finish(&run.target, &state, &run.err) &&  /* ... then drawn, tile by tile */
        run_write(&run))                               /* write: the pictures asked for */
        run_report(&run);                              /* report: the summary, the engine */
    status = run_end(&run);
    hiz_free(&h);
    fast_raster_free(&state.fast);
    return status;
}
