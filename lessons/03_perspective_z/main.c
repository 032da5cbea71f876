/* main.c: lesson 03, perspective-correct depth.
 *
 * Parse the command line, load the scene, clear the buffers, draw every face
 * through the z-buffer with 1/d interpolated on the screen (raster.c), write
 * the pictures and report.
 * --depth-interp naive draws with lesson 02's rule instead; --compare-naive
 * draws with both and marks where they disagree (common/compare_naive.c);
 * --bug negated-w makes a classic mistake on purpose (bugs.c); --trace,
 * --ascii, --compare and --steps watch the depth test decide (common/inspect.h). */
#include <stdio.h>
#include <string.h>

#include "bugs.h"
#include "cli.h"
#include "compare_naive.h"
#include "inspect.h"
#include "raster.h"
#include "render.h"

enum { FLAG_DEPTH_INTERP, FLAG_COMPARE_NAIVE, FLAG_BUG, FLAG_COUNT };

static const LessonFlag FLAGS[FLAG_COUNT] = {
    [FLAG_DEPTH_INTERP] = {"--depth-interp", "RULE",
                           "perspective (1/d linear, the default) or naive (d linear, lesson 02)"},
    [FLAG_COMPARE_NAIVE] = {"--compare-naive", "FILE.png",
                            "also write where the naive rule shows another face (magenta)"},
    [FLAG_BUG] = {"--bug", "NAME", "make a classic mistake: negated-w"},
};

static const LessonCli CLI = {
    .program = "03_perspective_z",
    .purpose = "Lesson 03: the z-buffer with perspective-correct depth, 1/d interpolated "
               "on the screen.",
    .groups = CLI_ALL_3D,
    .extra = FLAGS,
    .n_extra = FLAG_COUNT,
    .defaults = {.out = "out/03_perspective_z.png", .width = 800, .height = 600,
                 .scene = "grazing", .shade = SHADE_FLAT},
};

/* What --trace and --ascii show: the buffer keeps view depth d, smaller is
 * nearer; under --bug negated-w it keeps -d, with the same test. */
static const DepthRule DEPTH = {"depth buffer", "d", "face", SMALLER_IS_NEARER};
static const DepthRule NEGATED_DEPTH = {"depth buffer", "-d", "face", SMALLER_IS_NEARER};

typedef enum { PERSPECTIVE, NAIVE, BUG_NEGATED_W } Method;

static const Rasterizer *const RASTERIZER[] = {
    [PERSPECTIVE] = &ZBUFFER,
    [NAIVE] = &ZBUFFER_NAIVE,
    [BUG_NEGATED_W] = &NEGATED_W_BUG,
};

static const char *const METHOD_NOTE[] = {
    [PERSPECTIVE] = NULL,
    [NAIVE] = "depth-interp naive: d was interpolated linearly on the screen, as in lesson 02",
    [BUG_NEGATED_W] = "bug negated-w: the buffer held -d, so the farthest surface won each pixel",
};

static bool choose_method(const Options *opt, Method *m, Error *err)
{
    const char *interp = opt->extra[FLAG_DEPTH_INTERP], *bug = opt->extra[FLAG_BUG];
    *m = PERSPECTIVE;
    if (interp && strcmp(interp, "naive") == 0)
        *m = NAIVE;
    else if (interp && strcmp(interp, "perspective") != 0)
        return error_set(err, "--depth-interp: '%s' is not one of perspective, naive", interp);
    if (bug && *m == NAIVE)
        return error_set(err, "--bug and --depth-interp naive cannot be used together");
    if (bug && strcmp(bug, "negated-w") == 0)
        *m = BUG_NEGATED_W;
    else if (bug)
        return error_set(err, "--bug: '%s' is not one of negated-w", bug);
    const char *compare = opt->extra[FLAG_COMPARE_NAIVE];
    return !compare || compare_naive_path_ok(opt, compare, err);
}

int main(int argc, char **argv)
{
    Options opt;
    Error err;
    Method method;
    int status = cli_parse(&CLI, argc, argv, &opt);                 /* parse */
    if (status != CLI_CONTINUE)
        return status;
    if (!choose_method(&opt, &method, &err))
        return error_report(CLI.program, &err, EXIT_USAGE);
    const Rasterizer *rz = RASTERIZER[method];
    const char *compare = opt.extra[FLAG_COMPARE_NAIVE];
    long differing = 0;

    Render r;
    status = render_load(&r, &opt, &err);                           /* set up */
    if (status != EXIT_OK)
        return error_report(CLI.program, &err, status);
    render_print_warnings(&r, CLI.program);

    Target t;
    Inspection ins;
    const DepthRule *rule = method == BUG_NEGATED_W ? &NEGATED_DEPTH : &DEPTH;
    bool ok = target_init(&t, opt.width, opt.height, rz->clear_value, &err) && /* clear */
              inspect_begin(&ins, &r, &t, rz, rule, &opt, &err) &&             /* watch */
              render_faces(&r, &t, rz, NULL, 0, inspect_after_face, &ins, &err) && /* draw */
              render_write(&r, &t, rz, &opt, &err) &&                        /* write */
              (!compare || compare_with_naive(&r, &opt, &ZBUFFER, &ZBUFFER_NAIVE, compare,
                                              &differing, &err));
    if (ok) {
        render_print_summary(stdout, &r, &t, rz, &opt);                      /* report */
        if (METHOD_NOTE[method])
            printf("  %s\n", METHOD_NOTE[method]);
        if (compare)
            printf("  the naive rule shows another face at %ld pixels\n  wrote %s\n",
                   differing, compare);
    }
    status = ok ? inspect_report(stdout, &ins, &t, &err) : EXIT_RUN_FAILED; /* tools */
    target_free(&t);
    render_free(&r);
    return status == EXIT_RUN_FAILED ? error_report(CLI.program, &err, status) : status;
}
