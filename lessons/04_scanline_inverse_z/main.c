/* main.c: lesson 04, the z-buffer as a scanline renderer (docs/04_scanline_inverse_z.md).
 * The outline of the program. What this lesson teaches is in scanline.c and
 * depth_buffer.c: clear the buffer of 1/d to 0, then fill every face scanline
 * by scanline, keeping per pixel the largest 1/d. The report ends with "front
 * object detection"; the rest is common/harness/, reached through lesson.h. */
#include <math.h>
#include <stdio.h>

#include "harness/lesson.h"
#include "scanline.h"

/* What a player's step forward would run into: the buffer at the centre pixel. */
static void print_front_object(const Target *t, const LessonState *s)
{
    int x = t->width / 2, y = t->height / 2;
    double d = stored_to_depth(s, t->depth[y * t->width + x]); /* the nearest surface there */
    if (isinf(d))
        printf("  front object: nothing at the screen centre (%d,%d)\n", x, y);
    else
        printf("  front object: face %d at d = %.3f at the screen centre (%d,%d)\n",
               t->face[y * t->width + x], d, x, y);
}

static const Lesson LESSON = {
    .program = "04_scanline_inverse_z",
    .purpose = "Lesson 04: the z-buffer of 1990s software renderers: 1/d stored, cleared "
               "to 0, convex polygons filled scanline by scanline.",
    .scene = "walls",
    .rasterizer = &SCANLINE_ZBUFFER,
    .depth_rule = {"depth buffer", "1/d", "face", LARGER_IS_NEARER}, /* 1/d > stored wins */
    .report = print_front_object,
};

int main(int argc, char **argv)
{
    Run run;
    int status = run_load(&run, &LESSON, argc, argv); /* load: the command line, the scene */
    if (status != RUN_GO)
        return status;
    run.rz->clear(&run.target, run.rz->state);         /* clear: clear_depth */
    if (run_draw(&run) &&                              /* draw: draw_face, face by face */
        run_write(&run))                               /* write: the pictures asked for */
        run_report(&run);                              /* report: the summary and the tools */
    return run_end(&run);
}
