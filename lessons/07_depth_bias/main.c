/* main.c: lesson 07, z-fighting and depth bias (docs/07_depth_bias.md).
 *
 * The outline of the program. What this lesson teaches is in depth_bias.c:
 * each face of group or object `decal` gets a depth offset o = m FACTOR +
 * r UNITS (--polygon-offset), its steepest depth slope and the format's
 * smallest step, and depth_test (depth_buffer.c) adds o to the fragment's
 * z_w before the test. The buffer is lesson 06's, unorm24 and standard by
 * default, like an OpenGL window's; faces are clipped (clip.c) and drawn
 * (scanline.c) as before. What the lesson shows but does not teach (the
 * flags' words, each decal's share of its pixels) is in extras/. */
#include <stdio.h>

#include "depth_format.h"
#include "extras/extras.h"
#include "lesson.h"

/* The bias in use, and what one unit is worth in this format at the far plane. */
static void print_bias(const Target *t)
{
    const DepthSetup *s = t->depth_setup;
    printf("  polygon offset on the faces in `decal`: factor %g, units %g", s->bias.factor,
           s->bias.units);
    if (s->bias.clamp != 0)
        printf(", clamp %g", s->bias.clamp);
    printf(" (%s, %s; one unit of r = %.3g at z_w = 1)\n", format_name(s->format),
           mapping_name(s->mapping), depth_quantum(s->format, 1.0));
}

static const Lesson LESSON = {
    .program = "07_depth_bias",
    .purpose = "Lesson 07: z-fighting between coplanar faces, and the depth bias "
               "(polygon offset) that ends it: o = m * factor + r * units on the decals.",
    .scene = "decals",
    .rasterizer = &DEPTH_BIAS_ZBUFFER,
    .depth_rule = {"depth buffer", "z_w", "face", SMALLER_IS_NEARER}, /* reversed: extras */
    .extras = &EXTRAS,
    .report = print_bias,
};

int main(int argc, char **argv)
{
    Run run;
    int status = run_load(&run, &LESSON, argc, argv); /* load: the command line, the scene */
    if (status != RUN_GO)
        return status;
    DepthSetup depth = depth_chosen(&run);             /* the format, mapping and bias */
    run.target.depth_setup = &depth;                   /* the buffer's format and mapping */
    run.rz->clear(&run.target);                        /* clear: to the far plane, 1 or 0 */
    if (run_draw(&run) &&                              /* draw: clip, offset, draw_face */
        run_write(&run))                               /* write: the pictures asked for */
        run_report(&run);                              /* report: the summary, the decals */
    return run_end(&run);
}
