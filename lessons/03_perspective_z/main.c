/* main.c: lesson 03, perspective-correct depth (docs/03_perspective_z.md). The
 * outline of the program. What this lesson teaches is in raster.c: clear the
 * depth buffer, then draw every face, keeping per pixel the nearest fragment.
 * Around it (the command line, the scenes, the pictures, the tools) is
 * common/harness/, reached through lesson.h; what the lesson shows but does
 * not teach (--depth-interp naive, --compare-naive, --bug) is in extras/. */
#include "extras/extras.h"
#include "harness/lesson.h"
#include "raster.h"

static const Lesson LESSON = {
    .program = "03_perspective_z",
    .purpose = "Lesson 03: the z-buffer with perspective-correct depth, 1/d interpolated "
               "on the screen.",
    .scene = "grazing",
    .rasterizer = &ZBUFFER,
    .depth_rule = {"depth buffer", "d", "face", SMALLER_IS_NEARER}, /* d < stored wins */
    .extras = &EXTRAS,
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
