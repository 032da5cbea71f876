/* main.c: lesson 02, the z-buffer (docs/02_zbuffer.md). The outline of the
 * program. What this lesson teaches is in coverage.c and raster.c: clear the
 * depth buffer, then draw every face, keeping per pixel the nearest fragment.
 * Around it (the command line, the scenes, the pictures, the tools) is
 * common/harness/, reached through lesson.h; what the lesson shows but does
 * not teach (--painter, --bug) is in extras/. */
#include "extras/extras.h"
#include "harness/lesson.h"
#include "raster.h"

static const Lesson LESSON = {
    .program = "02_zbuffer",
    .purpose = "Lesson 02: the z-buffer, with depth interpolated linearly on the screen.",
    .scene = "triangles3",
    .rasterizer = &ZBUFFER,
    .depth_rule = {"depth buffer", "d", "face", SMALLER_IS_NEARER}, /* the smaller d wins */
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
