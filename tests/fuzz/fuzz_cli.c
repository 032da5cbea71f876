/* fuzz_cli.c: the shared command line (common/harness/cli.c) against any arguments
 * (make fuzz FUZZ=cli).
 *
 * The first byte picks one of three made-up lessons (every 3-D flag and two
 * of its own; a 1-D lesson; a lesson taking a few groups); the rest is split
 * at NUL bytes into argv. Whatever the arguments, cli_parse_quiet must return
 * CLI_CONTINUE, EXIT_OK (--help, --version) or EXIT_USAGE with a message of
 * one line; when it continues, the options must keep the rules of cli.h:
 * sizes 1 .. 16384, --trace inside the image, finite camera numbers. A
 * camera that cli_resolve_camera accepts must give finite matrices and
 * 0 < near < far, 0 < fovy < 180. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "camera.h"
#include "harness/cli.h"
#include "harness/image_io.h"

#include "fuzz_quiet.h"

#define MAX_ARGS 64

static const LessonFlag EXTRA[] = {
    {.flag = "--painter", .metavar = NULL, .help = "a switch"},
    {.flag = "--bug", .metavar = "NAME", .help = "a flag with a value"},
};

static const LessonCli SPECS[] = {
    {.program = "fuzz_3d", .purpose = "every flag", .groups = CLI_ALL_3D, .extra = EXTRA,
     .n_extra = 2,
     .defaults = {.out = "out/x.png", .width = 800, .height = 600, .scene = "triangles3",
                  .shade = SHADE_FLAT}},
    {.program = "fuzz_1d", .purpose = "one row", .groups = CLI_TRACE | CLI_ASCII | CLI_STEPS,
     .defaults = {.out = "out/y.png", .width = 800, .height = 16}},
    {.program = "fuzz_partial", .purpose = "some groups",
     .groups = CLI_SCENE | CLI_SHADE | CLI_TRACE,
     .defaults = {.out = "out/z.png", .width = 64, .height = 48, .scene = "triangles3"}},
};
#define SPEC_COUNT ((int)(sizeof SPECS / sizeof SPECS[0]))

static void check(bool ok, const char *what)
{
    if (!ok) {
        fprintf(stderr, "fuzz_cli: broken invariant: %s\n", what);
        abort();
    }
}

static bool vec_finite(Vec3 v)
{
    return isfinite(v.x) && isfinite(v.y) && isfinite(v.z);
}

static bool matrix_finite(Mat4 m)
{
    for (int r = 0; r < 4; r++)
        for (int c = 0; c < 4; c++)
            if (!isfinite(m.m[r][c]))
                return false;
    return true;
}

static void check_options(const LessonCli *spec, Options *opt)
{
    check(opt->width >= 1 && opt->width <= IMAGE_MAX_SIDE, "width in range");
    check(opt->height >= 1 && opt->height <= IMAGE_MAX_SIDE, "height in range");
    if (opt->trace_set)
        check(opt->trace_x >= 0 && opt->trace_x < opt->width && opt->trace_y >= 0 &&
                  opt->trace_y < opt->height,
              "--trace inside the image");
    check(!(opt->scene && opt->obj), "not both --scene and --obj");
    check(vec_finite(opt->eye) && vec_finite(opt->target) && vec_finite(opt->up),
          "camera vectors finite");
    check(isfinite(opt->fovy) && isfinite(opt->near) && isfinite(opt->far),
          "camera numbers finite");
    if (!(spec->groups & CLI_CAMERA))
        return;
    const SceneInfo *scene = opt->scene ? scene_find(opt->scene) : NULL;
    Error err;
    err.msg[0] = '\0';
    if (cli_resolve_camera(opt, scene, &err)) {
        check(opt->near > 0 && opt->far > opt->near, "0 < near < far");
        check(opt->fovy > 0 && opt->fovy < 180, "0 < fovy < 180");
        check(matrix_finite(look_at(opt->eye, opt->target, opt->up)), "view matrix finite");
        check(matrix_finite(perspective(opt->fovy, (double)opt->width / opt->height,
                                        opt->near, opt->far)),
              "projection finite");
    } else {
        check(err.msg[0] != '\0' && strchr(err.msg, '\n') == NULL, "camera error is one line");
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size == 0)
        return 0;
    const LessonCli *spec = &SPECS[data[0] % SPEC_COUNT];
    /* argv strings must be NUL-terminated: copy, then split at every NUL. */
    char *text = malloc(size);
    if (!text)
        return 0;
    memcpy(text, data + 1, size - 1);
    text[size - 1] = '\0';
    char *argv[MAX_ARGS + 2];
    int argc = 0;
    argv[argc++] = (char *)spec->program;
    for (char *s = text; s < text + size - 1 && argc <= MAX_ARGS; s += strlen(s) + 1)
        argv[argc++] = s;
    argv[argc] = NULL;

    Options opt;
    Error err;
    err.msg[0] = '\0';
    int status = cli_parse_quiet(spec, argc, argv, &opt, &err);
    if (status == CLI_CONTINUE)
        check_options(spec, &opt);
    else if (status == EXIT_USAGE)
        check(err.msg[0] != '\0' && strchr(err.msg, '\n') == NULL, "usage error is one line");
    else
        check(status == EXIT_OK, "status is CLI_CONTINUE, EXIT_OK or EXIT_USAGE");
    free(text);
    return 0;
}
