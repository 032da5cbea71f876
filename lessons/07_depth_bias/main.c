/* main.c: lesson 07, z-fighting and depth bias (docs/07_depth_bias.md).
 *
 * The outline of the program. What this lesson teaches is in depth_bias.c:
 * a face in group `decal` gets o = m FACTOR + r UNITS added to its z_w, in
 * lesson 06's buffer (depth_buffer.c, unorm24 by default). Faces are clipped
 * as in lesson 05 (clip.c) and drawn by lesson 04's scanline (scanline.c),
 * both unchanged. What the lesson shows but does not teach (the flags' words,
 * each decal's share of its pixels) is in extras/. */
#include <stdio.h>

#include "depth_bias.h"
#include "extras/extras.h"
#include "harness/lesson.h"
#include "state.h"

/* How far apart two surfaces must be to be told apart, at a few distances. */
static void print_depth_steps(const Target *t, const LessonState *state)
{
    static const double AT[] = {1, 10, 100, 300};
    const DepthSetup *s = &state->depth;
    (void)t;
    printf("  depth step (%s, %s, near %g, far %g):", format_name(s->format),
           mapping_name(s->mapping), s->near, s->far);
    for (size_t k = 0; k < sizeof AT / sizeof AT[0]; k++)
        if (AT[k] > s->near && AT[k] <= s->far)
            printf("%s d = %g: %.3g", k ? "," : "", AT[k], depth_step(s, AT[k]));
    printf("\n");
}

static const Lesson LESSON = {
    .program = "07_depth_bias",
    .purpose = "Lesson 07: z-fighting between coplanar faces, and the depth bias (polygon "
               "offset) on the faces in `decal` that ends it.",
    .scene = "decals",
    .rasterizer = &DEPTH_BIAS_ZBUFFER,
    .depth_rule = {"depth buffer", "z_w", "face", SMALLER_IS_NEARER}, /* reversed: extras */
    .extras = &EXTRAS,
    .report = print_depth_steps,
};

int main(int argc, char **argv)
{
    Run run;
    int status = run_load(&run, &LESSON, argc, argv); /* load: the command line, the scene */
    if (status != RUN_GO)
        return status;
    LessonState state = depth_chosen(&run);           /* the depth flags, the bias's */
    run.rasterizer.state = &state;                     /* the buffer's format and mapping */
    run.rz->clear(&run.target, run.rz->state);         /* clear: to the far plane, 1 or 0 */
    if (run_draw(&run) &&                              /* draw: clip, divide, draw_face */
        run_write(&run))                               /* write: the pictures asked for */
        run_report(&run);                              /* report: the summary, the steps */
    return run_end(&run);
}
