/* main.c: lesson 04, the z-buffer as a scanline renderer.
 *
 * Parse the command line, load the scene, clear the buffer to 0, draw every
 * face as a polygon walked edge by edge and span by span (scanline.c), write
 * the pictures, and report, with the distance of the nearest surface at the
 * centre of the screen ("front object detection").
 * Lesson 03's flags work here too: --depth-interp naive steps d instead of
 * 1/d; --compare-naive draws with both and marks where they disagree
 * (common/compare_naive.c); --trace, --ascii, --compare and --steps watch the depth
 * test decide (common/inspect.h), speaking of 1/d as the buffer holds it. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "compare_naive.h"
#include "inspect.h"
#include "render.h"
#include "scanline.h"

enum { FLAG_DEPTH_INTERP, FLAG_COMPARE_NAIVE, FLAG_COUNT };

static const LessonFlag FLAGS[FLAG_COUNT] = {
    [FLAG_DEPTH_INTERP] = {"--depth-interp", "RULE",
                           "perspective (1/d stepped, the default) or naive (d stepped)"},
    [FLAG_COMPARE_NAIVE] = {"--compare-naive", "FILE.png",
                            "also write where the naive rule shows another face (magenta)"},
};

static const LessonCli CLI = {
    .program = "04_scanline_inverse_z",
    .purpose = "Lesson 04: the z-buffer of 1990s software renderers: 1/d stored, cleared "
               "to 0, convex polygons filled scanline by scanline.",
    .groups = CLI_ALL_3D,
    .extra = FLAGS,
    .n_extra = FLAG_COUNT,
    .defaults = {.out = "out/04_scanline_inverse_z.png", .width = 800, .height = 600,
                 .scene = "walls", .shade = SHADE_FLAT},
};

/* What --trace and --ascii show: the buffer keeps 1/d, larger is nearer. */
static const DepthRule INVERSE_DEPTH = {"depth buffer", "1/d", "face", LARGER_IS_NEARER};

static bool choose_rasterizer(const Options *opt, const Rasterizer **rz, Error *err)
{
    const char *interp = opt->extra[FLAG_DEPTH_INTERP];
    *rz = &SCANLINE_ZBUFFER;
    if (interp && strcmp(interp, "naive") == 0)
        *rz = &SCANLINE_ZBUFFER_NAIVE;
    else if (interp && strcmp(interp, "perspective") != 0)
        return error_set(err, "--depth-interp: '%s' is not one of perspective, naive", interp);
    const char *compare = opt->extra[FLAG_COMPARE_NAIVE];
    return !compare || compare_naive_path_ok(opt, compare, err);
}

/* What a player's step forward would run into: the buffer at the centre pixel. */
static void print_front_object(const Target *t)
{
    int x = t->width / 2, y = t->height / 2;
    double d = nearest_distance_at(t, x, y);
    if (isinf(d))
        printf("  front object: nothing at the screen centre (%d,%d)\n", x, y);
    else
        printf("  front object: face %d at d = %.3f at the screen centre (%d,%d)\n",
               t->face[(size_t)y * (size_t)t->width + (size_t)x], d, x, y);
}

int main(int argc, char **argv)
{
    Options opt;
    Error err;
    const Rasterizer *rz;
    int status = cli_parse(&CLI, argc, argv, &opt);                      /* parse */
    if (status != CLI_CONTINUE)
        return status;
    if (!choose_rasterizer(&opt, &rz, &err))
        return error_report(CLI.program, &err, EXIT_USAGE);
    const char *compare = opt.extra[FLAG_COMPARE_NAIVE];
    long differing = 0;

    Render r;
    status = render_load(&r, &opt, &err);                                /* set up */
    if (status != EXIT_OK)
        return error_report(CLI.program, &err, status);
    render_print_warnings(&r, CLI.program);

    Target t;
    Inspection ins;
    bool ok = target_init(&t, opt.width, opt.height, rz->clear_value, &err);
    if (ok) {
        clear_depth(&t);                                                 /* clear: 1/d = 0 */
        ok = inspect_begin(&ins, &r, &t, rz, &INVERSE_DEPTH, &opt, &err) &&   /* watch */
             render_faces(&r, &t, rz, NULL, 0, inspect_after_face, &ins, &err) && /* draw */
             render_write(&r, &t, rz, &opt, &err) &&                     /* write */
             (!compare || compare_with_naive(&r, &opt, &SCANLINE_ZBUFFER,
                                             &SCANLINE_ZBUFFER_NAIVE, compare, &differing, &err));
    }
    if (ok) {
        render_print_summary(stdout, &r, &t, rz, &opt);                  /* report */
        if (rz == &SCANLINE_ZBUFFER_NAIVE)
            printf("  depth-interp naive: d was stepped along edges and spans, not 1/d\n");
        if (compare)
            printf("  the naive rule shows another face at %ld pixels\n  wrote %s\n",
                   differing, compare);
        print_front_object(&t);
    }
    status = ok ? inspect_report(stdout, &ins, &t, &err) : EXIT_RUN_FAILED; /* tools */
    target_free(&t);
    render_free(&r);
    return status == EXIT_RUN_FAILED ? error_report(CLI.program, &err, status) : status;
}
