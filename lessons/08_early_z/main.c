/* main.c: lesson 08, early-Z and the depth pre-pass (docs/08_early_z.md).
 *
 * The outline of the program. What this lesson teaches is in early_z.c: the
 * fragment shader runs after the depth test (early), before it (late), or
 * after a depth-only pass (prepass). Lesson 07's files draw, unchanged. What
 * the lesson shows but does not teach (the shader, the heat map) is in extras/. */
#include <stdio.h>

#include "early_z.h"
#include "extras/extras.h"
#include "harness/lesson.h"
#include "state.h"

/* How much shading the picture cost. */
static void print_shading(const Target *t, const LessonState *s)
{
    const EarlyZ *z = &s->early_z;
    (void)t;
    printf("  z-mode %s, sort %s: fragments tested %llu, shaded %llu, pixels covered %llu\n"
           "  shaded / covered: %.3f\n", z_mode_name(z->mode), sort_name(z->sort), z->tested,
           z->shaded, z->covered, z->covered ? (double)z->shaded / (double)z->covered : 0.0);
}

static const Lesson LESSON = {
    .program = "08_early_z",
    .purpose = "Lesson 08: early-Z and the depth pre-pass: the fragment shader runs once per "
               "covered pixel, not once per fragment.",
    .scene = "crowd",
    .rasterizer = &DEPTH_BIAS_ZBUFFER,
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
    if (!early_z_begin(&state, &run, &run.err))        /* the buffers; draw through them */
        return run_end(&run);
    run.rz->clear(&run.target, run.rz->state);         /* clear: to the far plane, 1 */
    if (run_draw(&run) &&                              /* draw: sorted, one or two passes */
        run_write(&run))                               /* write: the pictures asked for */
        run_report(&run);                              /* report: the summary, the counts */
    status = run_end(&run);
    early_z_free(&state.early_z);
    return status;
}
