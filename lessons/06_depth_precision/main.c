/* main.c: lesson 06, depth precision (docs/06_depth_precision.md).
 *
 * The outline of the program. What this lesson teaches is in depth_buffer.c:
 * the buffer stores window depth z_w as a GPU does, in a format (unorm16,
 * unorm24, float32) and a mapping (standard or reversed). Faces are clipped
 * as in lesson 05 (clip.c) and drawn by lesson 04's scanline (scanline.c),
 * both unchanged. What the lesson shows but does not teach (the flags' words,
 * --precision-plot, the ladder's score and labels) is in extras/. */
#include <stdio.h>

#include "depth_format.h"
#include "state.h"
#include "extras/extras.h"
#include "harness/lesson.h"

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
    .program = "06_depth_precision",
    .purpose = "Lesson 06: the depth buffer as a GPU keeps it: window depth in unorm16, "
               "unorm24 or float32, standard or reversed.",
    .scene = "ladder",
    .rasterizer = &DEPTH_PRECISION_ZBUFFER,
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
    LessonState state = {depth_chosen(&run)};         /* --depth-format, --depth-mapping */
    run.rasterizer.state = &state;                     /* the buffer's format and mapping */
    run.rz->clear(&run.target, run.rz->state);         /* clear: to the far plane, 1 or 0 */
    if (run_draw(&run) &&                              /* draw: clip, divide, draw_face */
        run_write(&run))                               /* write: the pictures asked for */
        run_report(&run);                              /* report: the summary, the steps */
    return run_end(&run);
}
