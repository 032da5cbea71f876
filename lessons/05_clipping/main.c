/* main.c: lesson 05, clipping at the near plane (docs/05_clipping.md).
 *
 * The outline of the program. What this lesson teaches is in clip.c: every
 * face is clipped in clip space against the near and far planes, divided,
 * and handed to lesson 04's scanline z-buffer (scanline.c, unchanged).
 * Everything around it is common/harness/, reached through lesson.h; what the lesson
 * shows but does not teach (--bug no-clip, --compare-drop) is in extras/. */
#include <math.h>
#include <stdio.h>

#include "clipping.h"
#include "extras/extras.h"
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
    .program = "05_clipping",
    .purpose = "Lesson 05: faces clipped at the near and far planes in clip space, before "
               "the divide, then lesson 04's scanline z-buffer.",
    .scene = "inside",
    .rasterizer = &CLIPPING_ZBUFFER,
    .depth_rule = {"depth buffer", "1/d", "face", LARGER_IS_NEARER}, /* 1/d > stored wins */
    .extras = &EXTRAS,
    .report = print_front_object,
};

int main(int argc, char **argv)
{
    Run run;
    int status = run_load(&run, &LESSON, argc, argv); /* load: the command line, the scene */
    if (status != RUN_GO)
        return status;
    run.rz->clear(&run.target, run.rz->state);         /* clear: clear_depth */
    if (run_draw(&run) &&                              /* draw: clip, divide, draw_face */
        run_write(&run))                               /* write: the pictures asked for */
        run_report(&run);                              /* report: the summary and the tools */
    return run_end(&run);
}
