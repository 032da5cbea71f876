/* main.c: lesson 02, the z-buffer.
 *
 * Parse the command line, load the scene, clear the buffers, draw every face
 * through the z-buffer (raster.c), write the pictures and report.
 * --painter draws back to front without depth (painter.c); --bug makes one of
 * two classic mistakes on purpose (bugs.c); --trace, --ascii, --compare and
 * --steps watch the depth test decide (common/inspect.h). */
#include <stdio.h>
#include <string.h>

#include "bugs.h"
#include "cli.h"
#include "inspect.h"
#include "painter.h"
#include "raster.h"
#include "render.h"

enum { FLAG_PAINTER, FLAG_BUG, FLAG_COUNT };

static const LessonFlag FLAGS[FLAG_COUNT] = {
    [FLAG_PAINTER] = {"--painter", NULL, "draw back to front by mean depth, no depth buffer"},
    [FLAG_BUG] = {"--bug", "NAME", "make a classic mistake: separate-buffers or clear-zero"},
};

static const LessonCli CLI = {
    .program = "02_zbuffer",
    .purpose = "Lesson 02: the z-buffer, with depth interpolated linearly on the screen.",
    .groups = CLI_ALL_3D,
    .extra = FLAGS,
    .n_extra = FLAG_COUNT,
    .defaults = {.out = "out/02_zbuffer.png", .width = 800, .height = 600,
                 .scene = "triangles3", .shade = SHADE_FLAT},
};

/* What --trace and --ascii show: the buffer keeps view depth d, smaller is nearer. */
static const DepthRule DEPTH = {"depth buffer", "d", "face", SMALLER_IS_NEARER};

typedef enum { ZBUFFER_RIGHT, PAINTER, BUG_SEPARATE_BUFFERS, BUG_CLEAR_ZERO } Method;

static const char *const METHOD_NOTE[] = {
    [ZBUFFER_RIGHT] = NULL,
    [PAINTER] = "painter's algorithm: faces back to front by mean depth, no depth buffer",
    [BUG_SEPARATE_BUFFERS] = "bug separate-buffers: each object had a depth buffer of its own",
    [BUG_CLEAR_ZERO] = "bug clear-zero: the depth buffer was cleared to 0, so no fragment passed",
};

static bool choose_method(const Options *opt, Method *m, Error *err)
{
    const char *painter = opt->extra[FLAG_PAINTER], *bug = opt->extra[FLAG_BUG];
    *m = ZBUFFER_RIGHT;
    if (painter && bug)
        return error_set(err, "--painter and --bug cannot be used together");
    if (painter)
        *m = PAINTER;
    else if (bug && strcmp(bug, "separate-buffers") == 0)
        *m = BUG_SEPARATE_BUFFERS;
    else if (bug && strcmp(bug, "clear-zero") == 0)
        *m = BUG_CLEAR_ZERO;
    else if (bug)
        return error_set(err, "--bug: '%s' is not one of separate-buffers, clear-zero", bug);
    if (*m != ZBUFFER_RIGHT && *m != BUG_CLEAR_ZERO && opt->steps_dir)
        return error_set(err, "--steps follows one depth buffer face by face; it cannot be "
                              "used with --painter or --bug separate-buffers");
    return true;
}

static bool draw(Method m, Render *r, Target *t, Inspection *ins, Error *err)
{
    switch (m) {
    case PAINTER: return draw_painter(r, t, &ZBUFFER, err);
    case BUG_SEPARATE_BUFFERS: return draw_separate_buffers(r, t, &ZBUFFER, err);
    case ZBUFFER_RIGHT:
    case BUG_CLEAR_ZERO: break;
    }
    return render_faces(r, t, &ZBUFFER, NULL, 0, inspect_after_face, ins, err); /* mesh order */
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

    Render r;
    status = render_load(&r, &opt, &err);                           /* set up */
    if (status != EXIT_OK)
        return error_report(CLI.program, &err, status);
    render_print_warnings(&r, CLI.program);

    Target t;
    Inspection ins;
    float clear = method == BUG_CLEAR_ZERO ? CLEAR_ZERO_BUG : ZBUFFER.clear_value;
    bool ok = target_init(&t, opt.width, opt.height, clear, &err) && /* clear */
              inspect_begin(&ins, &r, &t, &ZBUFFER, &DEPTH, &opt, &err) && /* watch */
              draw(method, &r, &t, &ins, &err) &&                    /* draw */
              render_write(&r, &t, &ZBUFFER, &opt, &err);            /* write */
    if (ok) {
        render_print_summary(stdout, &r, &t, &ZBUFFER, &opt);        /* report */
        if (METHOD_NOTE[method])
            printf("  %s\n", METHOD_NOTE[method]);
    }
    status = ok ? inspect_report(stdout, &ins, &t, &err) : EXIT_RUN_FAILED; /* tools */
    target_free(&t);
    render_free(&r);
    return status == EXIT_RUN_FAILED ? error_report(CLI.program, &err, status) : status;
}
