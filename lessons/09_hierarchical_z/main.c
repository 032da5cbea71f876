/* main.c: lesson 09, hierarchical Z (docs/09_hierarchical_z.md).
 *
 * The outline of the program. What this lesson teaches is in
 * hierarchical_z.c, the tile buffer (each tile's farthest stored value),
 * and tiles.c, the rasterizer that asks it before it touches a tile's
 * pixels. What it shows but does not teach is in extras/. */
#include <stdio.h>

#include "extras/extras.h"
#include "hierarchical_z.h"
#include "harness/lesson.h"
#include "state.h"

/* How much shading the picture cost, and what the tiles saved. */
static void print_shading(const Target *t, const LessonState *s)
{
    const EarlyZ *z = &s->early_z;
    const HierarchicalZ *h = s->hiz;
    (void)t;
    printf("  z-mode %s, sort %s: fragments tested %llu, shaded %llu, pixels covered %llu\n"
           "  shaded / covered: %.3f\n", z_mode_name(z->mode), sort_name(z->sort), z->tested,
           z->shaded, z->covered, z->covered ? (double)z->shaded / (double)z->covered : 0.0);
    printf("  hierarchical Z, %dx%d tiles: tiles tested %llu, skipped %llu; fragments never "
           "tested %llu; faces skipped whole %llu\n", h->tile, h->tile, h->tiles_tested,
           h->tiles_skipped, h->fragments_skipped, h->faces_skipped);
}

static const Lesson LESSON = {
    .program = "09_hierarchical_z",
    .purpose = "Lesson 09: hierarchical Z: a tile whose farthest stored depth is nearer than "
               "a triangle is skipped before any of its pixels is tested.",
    .scene = "city",
    .rasterizer = &HIERARCHICAL_ZBUFFER,
    .depth_rule = {"depth buffer", "z_w", "face", SMALLER_IS_NEARER}, /* unorm24, standard */
    .extras = &EXTRAS,
    .report = print_shading,
};

int main(int argc, char **argv)
{
    Run run;
    int status = run_load(&run, &LESSON, argc, argv); /* load: the command line, the scene */
    if (status != RUN_GO)
        return status;
    LessonState state = early_z_chosen(&run);          /* --z-mode, --sort, --bug */
    HierarchicalZ h = {.exact = exact_chosen(&run), .count_skipped = true}; /* --hiz-update */
    state.hiz = &h;
    if (!early_z_begin(&state, &run, &run.err) ||      /* the buffers; draw through them */
        !hiz_begin(&h, &run.target, tile_chosen(&run), &run.err)) { /* the tiles, --tile */
        hiz_free(&h), early_z_free(&state.early_z);
        return run_end(&run);
    }
    run.rz->clear(&run.target, run.rz->state);         /* clear: the far plane, every tile */
    if (run_draw(&run) &&                              /* draw: tile by tile, hidden skipped */
        run_write(&run))                               /* write: the pictures asked for */
        run_report(&run);                              /* report: the summary, the counts */
    status = run_end(&run);
    hiz_free(&h);
    early_z_free(&state.early_z);
    return status;
}
