/* test_cli.c: the shared command line. Every bad line must give exactly one
 * message, naming the flag and the value, and exit status 2; good lines must
 * land in the right fields; the camera is completed from the scene and checked.
 *
 * Three made-up lessons:
 *   02_test     takes every shared flag, plus --painter (a switch) and --max-faces N
 *   01_test     a 1-D lesson: --trace X and --ascii only, no scene, no camera
 *   03_partial  takes --scene/--obj and --shade, nothing else */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "harness/cli.h"

static const LessonFlag EXTRA_FLAGS[] = {
    {.flag = "--painter", .metavar = NULL, .help = "draw back to front, no depth buffer"},
    {.flag = "--max-faces", .metavar = "N", .help = "draw at most N faces"},
};
enum { EXTRA_PAINTER, EXTRA_MAX_FACES };

static const LessonCli SPEC_3D = {
    .program = "02_test",
    .purpose = "A test lesson that takes every flag.",
    .groups = CLI_ALL_3D,
    .extra = EXTRA_FLAGS,
    .n_extra = 2,
    .defaults = {.out = "out/02_test.png", .width = 800, .height = 600,
                 .scene = "triangles3", .shade = SHADE_FLAT},
};

static const LessonCli SPEC_1D = {
    .program = "01_test",
    .purpose = "A test lesson in one dimension.",
    .groups = CLI_TRACE | CLI_ASCII,
    .defaults = {.out = "out/01_test.png", .width = 800, .height = 600},
};

static const LessonCli SPEC_PARTIAL = {
    .program = "03_partial",
    .purpose = "A test lesson that takes a few groups.",
    .groups = CLI_SCENE | CLI_SHADE,
    .defaults = {.out = "out/03_partial.png", .width = 640, .height = 480,
                 .scene = "triangles3"},
};

#define MAX_ARGS 12

/* argv = program, args..., NULL */
static int parse(const LessonCli *spec, const char *const *args, Options *opt, Error *err)
{
    char *argv[MAX_ARGS + 2];
    int argc = 0;
    argv[argc++] = (char *)spec->program;
    for (int i = 0; args[i]; i++)
        argv[argc++] = (char *)args[i];
    argv[argc] = NULL;
    err->msg[0] = '\0';
    return cli_parse_quiet(spec, argc, argv, opt, err);
}

/* ---- Bad command lines ------------------------------------------------------ */

typedef struct {
    const LessonCli *spec;
    const char *args[MAX_ARGS];
    const char *message;
} BadLine;

static const char LONG_FLAG[] =
    "--aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa";

static const BadLine BAD_LINES[] = {
    /* sizes */
    {&SPEC_3D, {"--width", "abc"}, "--width: 'abc' is not a whole number"},
    {&SPEC_3D, {"--width", "0"}, "--width: 0 is out of range (1 to 16384)"},
    {&SPEC_3D, {"--height", "16385"}, "--height: 16385 is out of range (1 to 16384)"},
    {&SPEC_3D, {"--width", "-3"}, "--width: -3 is out of range (1 to 16384)"},
    {&SPEC_3D, {"--width", "12.5"}, "--width: '12.5' is not a whole number"},
    {&SPEC_3D, {"--width", ""}, "--width: '' is not a whole number"},
    {&SPEC_3D, {"--width", " 5"}, "--width: ' 5' is not a whole number"},
    /* a control character would break the one-line message: it shows as '?' */
    {&SPEC_3D, {"--width", "5\nx"}, "--width: '5?x' is not a whole number"},
    {&SPEC_3D, {"--shade", "\033[31mred"}, "--shade: '?[31mred' is not one of flat, id, depth"},
    {&SPEC_3D, {"--foo\r\nx"}, "unknown flag '--foo?\?x' (try --help)"},
    {&SPEC_3D, {"--height", "99999999999999999999"},
     "--height: 99999999999999999999 is out of range (1 to 16384)"},
    /* numbers and vectors */
    {&SPEC_3D, {"--eye", "nan,0,0"}, "--eye: 'nan,0,0' is not three finite numbers X,Y,Z"},
    {&SPEC_3D, {"--eye", "1,2"}, "--eye: '1,2' is not three finite numbers X,Y,Z"},
    {&SPEC_3D, {"--up", "1,2,3,4"}, "--up: '1,2,3,4' is not three finite numbers X,Y,Z"},
    {&SPEC_3D, {"--target", "1e999,0,0"},
     "--target: '1e999,0,0' is not three finite numbers X,Y,Z"},
    {&SPEC_3D, {"--target", "1, 2, 3"}, "--target: '1, 2, 3' is not three finite numbers X,Y,Z"},
    {&SPEC_3D, {"--fovy", "inf"}, "--fovy: 'inf' is not a finite number"},
    {&SPEC_3D, {"--near", "0.1x"}, "--near: '0.1x' is not a finite number"},
    {&SPEC_3D, {"--near", "-1,2"}, "--near: '-1,2' is not a finite number"},
    {&SPEC_3D, {"--far", "NaN"}, "--far: 'NaN' is not a finite number"},
    /* flags themselves */
    {&SPEC_3D, {"--foo"}, "unknown flag '--foo' (try --help)"},
    {&SPEC_3D, {"-x"}, "unknown flag '-x' (try --help)"},
    {&SPEC_3D, {LONG_FLAG},
     "unknown flag '--aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa...' (try --help)"},
    {&SPEC_3D, {"--out"}, "--out needs a value"},
    {&SPEC_3D, {"--out", "--width", "5"}, "--out needs a value"},
    {&SPEC_3D, {"--width", "100", "--fovy"}, "--fovy needs a value"},
    {&SPEC_3D, {"--width", "5", "--width", "6"}, "--width given twice"},
    {&SPEC_3D, {"--ascii", "--ascii"}, "--ascii given twice"},
    {&SPEC_3D, {"foo"}, "unexpected argument 'foo'"},
    {&SPEC_3D, {"-"}, "unexpected argument '-'"},
    {&SPEC_3D, {"--width", "10", "20"}, "unexpected argument '20'"},
    {&SPEC_3D, {"--out", ""}, "--out: the file name is empty"},
    {&SPEC_3D, {"--steps", ""}, "--steps: the directory name is empty"},
    /* an output may not replace an input or another output */
    {&SPEC_3D, {"--obj", "m.obj", "--out", "m.obj"}, "--obj and --out both name m.obj"},
    {&SPEC_3D, {"--out", "a.pfm", "--depth-out", "a.pfm"}, "--out and --depth-out both name a.pfm"},
    {&SPEC_3D, {"--out", "i.png", "--id-out", "i.png"}, "--out and --id-out both name i.png"},
    {&SPEC_3D, {"--id-out", "x", "--overdraw-out", "x"}, "--overdraw-out and --id-out both name x"},
    {&SPEC_3D, {"--depth-out", "x", "--overdraw-out", "x"},
     "--depth-out and --overdraw-out both name x"},
    {&SPEC_3D, {"--obj", "out/02_test.png"}, "--obj and --out both name out/02_test.png"},
    /* scene, shade */
    {&SPEC_3D, {"--scene", "triangles3", "--obj", "m.obj"},
     "--scene and --obj cannot be used together"},
    {&SPEC_3D, {"--obj", "m.obj", "--scene", "triangles3"},
     "--scene and --obj cannot be used together"},
    {&SPEC_3D, {"--shade", "x"}, "--shade: 'x' is not one of flat, id, depth"},
    {&SPEC_3D, {"--shade", "FLAT"}, "--shade: 'FLAT' is not one of flat, id, depth"},
    /* --trace: X,Y, checked against the image size once every flag is read */
    {&SPEC_3D, {"--trace", "900,3"}, "--trace: pixel (900,3) is outside the 800x600 image"},
    {&SPEC_3D, {"--trace", "-1,0"}, "--trace: pixel (-1,0) is outside the 800x600 image"},
    {&SPEC_3D, {"--trace", "10,10", "--width", "10"},
     "--trace: pixel (10,10) is outside the 10x600 image"},
    {&SPEC_3D, {"--trace", "5"}, "--trace: '5' is not a pixel X,Y (two whole numbers)"},
    {&SPEC_3D, {"--trace", "1,2,3"}, "--trace: '1,2,3' is not a pixel X,Y (two whole numbers)"},
    /* the lesson's own flags */
    {&SPEC_3D, {"--painter", "--painter"}, "--painter given twice"},
    {&SPEC_3D, {"--max-faces"}, "--max-faces needs a value"},
    {&SPEC_3D, {"--max-faces", "3", "--max-faces", "4"}, "--max-faces given twice"},
    /* flags of groups a lesson does not take */
    {&SPEC_1D, {"--eye", "0,0,0"}, "--eye does not apply to 01_test (it has no camera)"},
    {&SPEC_1D, {"--obj", "m.obj"}, "--obj does not apply to 01_test (it draws its own scene only)"},
    {&SPEC_1D, {"--shade", "id"}, "--shade does not apply to 01_test (it has one way of shading)"},
    {&SPEC_1D, {"--painter"}, "unknown flag '--painter' (try --help)"},
    {&SPEC_1D, {"--id-out", "i.png"}, "--id-out does not apply to 01_test (it has no faces)"},
    {&SPEC_PARTIAL, {"--depth-out", "d.pfm"},
     "--depth-out does not apply to 03_partial (it writes no depth buffer)"},
    {&SPEC_PARTIAL, {"--overdraw-out", "o.pgm"},
     "--overdraw-out does not apply to 03_partial (it counts no overdraw)"},
    {&SPEC_PARTIAL, {"--trace", "1,1"},
     "--trace does not apply to 03_partial (it traces no pixel)"},
    {&SPEC_PARTIAL, {"--compare", "r.png"},
     "--compare does not apply to 03_partial (it compares no pictures)"},
    {&SPEC_PARTIAL, {"--steps", "dir"}, "--steps does not apply to 03_partial (it saves no steps)"},
    {&SPEC_PARTIAL, {"--ascii"}, "--ascii does not apply to 03_partial (it prints no text picture)"},
    /* --trace X in one dimension */
    {&SPEC_1D, {"--trace", "3,4"}, "--trace: '3,4' is not a column X (a whole number)"},
    {&SPEC_1D, {"--trace", "800"}, "--trace: column 800 is outside the 800-pixel-wide image"},
    {&SPEC_1D, {"--width", "50", "--trace", "-2"},
     "--trace: column -2 is outside the 50-pixel-wide image"},
    /* --ascii prints one character per pixel: at most 120x60 (120 in one dimension) */
    {&SPEC_3D, {"--ascii"},
     "--ascii: the image is 800x600; --ascii prints at most 120x60 (use --width and --height)"},
    {&SPEC_3D, {"--ascii", "--width", "120", "--height", "61"},
     "--ascii: the image is 120x61; --ascii prints at most 120x60 (use --width and --height)"},
    {&SPEC_1D, {"--width", "121", "--ascii"},
     "--ascii: the row is 121 pixels wide; --ascii prints at most 120 (use --width)"},
    /* --compare's diff picture goes next to --out: it may not overwrite REF */
    {&SPEC_3D, {"--out", "p.png", "--compare", "p.diff.png"},
     "--compare names p.diff.png, where the diff picture of --out goes"},
};

static void bad_lines_give_their_exact_message_and_status_2(void **state)
{
    (void)state;
    int failures = 0, n = (int)(sizeof BAD_LINES / sizeof BAD_LINES[0]);
    for (int k = 0; k < n; k++) {
        const BadLine *b = &BAD_LINES[k];
        Options opt;
        Error err;
        int status = parse(b->spec, b->args, &opt, &err);
        if (status != EXIT_USAGE || strcmp(err.msg, b->message) != 0) {
            print_error("BAD_LINES[%d] (%s %s %s ...):\n  status %d, message \"%s\"\n"
                        "  wanted status 2, message \"%s\"\n",
                        k, b->spec->program, b->args[0], b->args[1] ? b->args[1] : "",
                        status, err.msg, b->message);
            failures++;
        }
    }
    if (failures)
        fail_msg("%d of %d bad command lines were not refused as expected (listed above)",
                 failures, n);
    assert_true(n >= 25);
}

static void unknown_scene_lists_the_known_ones(void **state)
{
    (void)state;
    /* The list comes from scene.c, whatever scenes it has; triangles3 must be one. */
    char want[ERROR_MSG_MAX] = "--scene: no scene named 'nosuch' (known: ";
    for (int i = 0; i < scene_count(); i++) {
        if (i)
            strcat(want, ", ");
        strcat(want, scene_at(i)->name);
    }
    strcat(want, ")");
    assert_non_null(strstr(want, "triangles3"));

    const char *args[] = {"--scene", "nosuch", NULL};
    Options opt;
    Error err;
    assert_int_equal(parse(&SPEC_3D, args, &opt, &err), EXIT_USAGE);
    assert_string_equal(err.msg, want);
}

/* cli_parse prints "<program>: error: <msg>" on stderr, one line. */
static void cli_parse_prints_one_error_line_on_stderr(void **state)
{
    (void)state;
    FILE *capture = tmpfile();
    assert_non_null(capture);
    fflush(stderr);
    int saved = dup(STDERR_FILENO);
    dup2(fileno(capture), STDERR_FILENO);

    char *argv[] = {"02_test", "--width", "0", NULL};
    Options opt;
    int status = cli_parse(&SPEC_3D, 3, argv, &opt);

    fflush(stderr);
    dup2(saved, STDERR_FILENO);
    close(saved);
    char text[256] = "";
    rewind(capture);
    size_t n = fread(text, 1, sizeof text - 1, capture);
    text[n] = '\0';
    fclose(capture);

    assert_int_equal(status, EXIT_USAGE);
    assert_string_equal(text, "02_test: error: --width: 0 is out of range (1 to 16384)\n");
}

/* ---- Good command lines ------------------------------------------------------- */

static void no_arguments_give_the_lesson_defaults(void **state)
{
    (void)state;
    const char *args[] = {NULL};
    Options opt;
    Error err;
    assert_int_equal(parse(&SPEC_3D, args, &opt, &err), CLI_CONTINUE);
    assert_string_equal(opt.out, "out/02_test.png");
    assert_int_equal(opt.width, 800);
    assert_int_equal(opt.height, 600);
    assert_string_equal(opt.scene, "triangles3");
    assert_null(opt.obj);
    assert_int_equal(opt.shade, SHADE_FLAT);
    assert_false(opt.eye_set || opt.target_set || opt.up_set || opt.fovy_set || opt.near_set ||
                 opt.far_set);
    assert_false(opt.trace_set);
    assert_false(opt.ascii);
    assert_null(opt.depth_out);
    assert_null(opt.id_out);
    assert_null(opt.extra[EXTRA_PAINTER]);
    assert_null(opt.extra[EXTRA_MAX_FACES]);
}

static void every_flag_lands_in_its_field(void **state)
{
    (void)state;
    const char *args[] = {"--out", "a.png", "--width", "120", "--height", "60", /* --ascii max */
                          "--eye", "-1,2.5,3", "--target", "0,0,-1", NULL};
    const char *more[] = {"--up", "0,1,0", "--fovy", "45", "--near", "0.5", "--far", "50",
                          "--shade", "depth", "--trace", "10,20", NULL};
    const char *rest[] = {"--depth-out", "d.pfm", "--overdraw-out", "o.pgm", "--id-out", "i.png",
                          "--ascii",
                          "--compare", "ref.png", "--steps", "steps", "--painter",
                          "--max-faces", "12", NULL};
    /* one argv of all three lists */
    char *argv[64];
    int argc = 0;
    argv[argc++] = "02_test";
    for (int i = 0; args[i]; i++) argv[argc++] = (char *)args[i];
    for (int i = 0; more[i]; i++) argv[argc++] = (char *)more[i];
    for (int i = 0; rest[i]; i++) argv[argc++] = (char *)rest[i];
    argv[argc] = NULL;

    Options opt;
    Error err = {""};
    assert_int_equal(cli_parse_quiet(&SPEC_3D, argc, argv, &opt, &err), CLI_CONTINUE);
    assert_string_equal(opt.out, "a.png");
    assert_int_equal(opt.width, 120);
    assert_int_equal(opt.height, 60);
    assert_true(opt.eye_set && opt.eye.x == -1 && opt.eye.y == 2.5 && opt.eye.z == 3);
    assert_true(opt.target_set && opt.target.x == 0 && opt.target.z == -1);
    assert_true(opt.up_set && opt.up.y == 1);
    assert_true(opt.fovy_set && opt.fovy == 45);
    assert_true(opt.near_set && opt.near == 0.5);
    assert_true(opt.far_set && opt.far == 50);
    assert_int_equal(opt.shade, SHADE_DEPTH);
    assert_true(opt.trace_set);
    assert_int_equal(opt.trace_x, 10);
    assert_int_equal(opt.trace_y, 20);
    assert_string_equal(opt.depth_out, "d.pfm");
    assert_string_equal(opt.overdraw_out, "o.pgm");
    assert_string_equal(opt.id_out, "i.png");
    assert_true(opt.ascii);
    assert_string_equal(opt.compare, "ref.png");
    assert_string_equal(opt.steps_dir, "steps");
    assert_string_equal(opt.extra[EXTRA_PAINTER], ""); /* a switch that was given */
    assert_string_equal(opt.extra[EXTRA_MAX_FACES], "12");
    assert_string_equal(opt.scene, "triangles3"); /* the default, untouched */
}

static void obj_replaces_the_default_scene(void **state)
{
    (void)state;
    const char *args[] = {"--obj", "models/cube.obj", NULL};
    Options opt;
    Error err;
    assert_int_equal(parse(&SPEC_3D, args, &opt, &err), CLI_CONTINUE);
    assert_string_equal(opt.obj, "models/cube.obj");
    assert_null(opt.scene);
}

static void scene_by_name(void **state)
{
    (void)state;
    const char *args[] = {"--scene", "triangles3", "--shade", "id", NULL};
    Options opt;
    Error err;
    assert_int_equal(parse(&SPEC_3D, args, &opt, &err), CLI_CONTINUE);
    assert_string_equal(opt.scene, "triangles3");
    assert_int_equal(opt.shade, SHADE_ID);
}

static void values_may_start_with_a_minus_sign(void **state)
{
    (void)state;
    /* -0.5 is a value, not a flag: it reaches the camera check, which refuses it. */
    const char *args[] = {"--eye", "-1,-2,-3", "--near", "-0.5", NULL};
    Options opt;
    Error err;
    assert_int_equal(parse(&SPEC_3D, args, &opt, &err), CLI_CONTINUE);
    assert_true(opt.eye.x == -1 && opt.eye.y == -2 && opt.eye.z == -3);
    assert_true(opt.near == -0.5);
    assert_false(cli_resolve_camera(&opt, NULL, &err));
    assert_string_equal(err.msg, "--near: -0.5 is out of range (near must be greater than 0)");
}

static void trace_in_one_dimension_takes_a_column(void **state)
{
    (void)state;
    const char *args[] = {"--trace", "7", "--width", "8", NULL};
    Options opt;
    Error err;
    assert_int_equal(parse(&SPEC_1D, args, &opt, &err), CLI_CONTINUE);
    assert_true(opt.trace_set);
    assert_int_equal(opt.trace_x, 7); /* the last column of 8 */
    assert_int_equal(opt.trace_y, 0);
}

static void trace_on_the_last_pixel_is_inside(void **state)
{
    (void)state;
    const char *args[] = {"--width", "4", "--height", "3", "--trace", "3,2", NULL};
    Options opt;
    Error err;
    assert_int_equal(parse(&SPEC_3D, args, &opt, &err), CLI_CONTINUE);
    assert_int_equal(opt.trace_x, 3);
    assert_int_equal(opt.trace_y, 2);
}

static void sizes_at_both_ends_of_the_range(void **state)
{
    (void)state;
    const char *args[] = {"--width", "1", "--height", "16384", NULL};
    Options opt;
    Error err;
    assert_int_equal(parse(&SPEC_3D, args, &opt, &err), CLI_CONTINUE);
    assert_int_equal(opt.width, 1);
    assert_int_equal(opt.height, 16384);
}

/* ---- --help and --version ----------------------------------------------------- */

/* Runs the parser with stdout sent to a buffer; returns its status. */
static int parse_capturing_stdout(const LessonCli *spec, const char *const *args, char *text,
                                  size_t size)
{
    FILE *capture = tmpfile();
    assert_non_null(capture);
    fflush(stdout);
    int saved = dup(STDOUT_FILENO);
    dup2(fileno(capture), STDOUT_FILENO);
    Options opt;
    Error err;
    int status = parse(spec, args, &opt, &err);
    fflush(stdout);
    dup2(saved, STDOUT_FILENO);
    close(saved);
    rewind(capture);
    size_t n = fread(text, 1, size - 1, capture);
    text[n] = '\0';
    fclose(capture);
    return status;
}

static void help_exits_0_and_lists_what_the_lesson_takes(void **state)
{
    (void)state;
    static char text[16384];
    const char *args[] = {"--help", NULL};
    assert_int_equal(parse_capturing_stdout(&SPEC_3D, args, text, sizeof text), EXIT_OK);
    const char *must[] = {"Usage: 02_test [options]", "A test lesson that takes every flag.",
                          "--eye X,Y,Z", "--trace X,Y", "--shade MODE", "--painter",
                          "--max-faces N", "draw at most N faces", "Scenes:", "triangles3",
                          "Exit status:", "  2  bad command line", "  3  --compare",
                          "(default: 800)", "(default: out/02_test.png)"};
    for (size_t i = 0; i < sizeof must / sizeof must[0]; i++)
        if (!strstr(text, must[i]))
            fail_msg("--help text lacks \"%s\":\n%s", must[i], text);
}

static void help_of_a_1d_lesson_leaves_out_what_it_does_not_take(void **state)
{
    (void)state;
    static char text[16384];
    const char *args[] = {"--help", NULL};
    assert_int_equal(parse_capturing_stdout(&SPEC_1D, args, text, sizeof text), EXIT_OK);
    assert_non_null(strstr(text, "--trace X "));
    assert_non_null(strstr(text, "--ascii"));
    const char *must_not[] = {"--eye", "--scene", "--obj", "--shade", "Scenes:", "  3  "};
    for (size_t i = 0; i < sizeof must_not / sizeof must_not[0]; i++)
        if (strstr(text, must_not[i]))
            fail_msg("--help of a 1-D lesson mentions \"%s\":\n%s", must_not[i], text);
}

static void version_exits_0_with_the_series_version(void **state)
{
    (void)state;
    char text[256];
    const char *args[] = {"--version", NULL};
    assert_int_equal(parse_capturing_stdout(&SPEC_3D, args, text, sizeof text), EXIT_OK);
    assert_string_equal(text, "02_test (hidden-surface lessons) " SERIES_VERSION "\n");
}

static void arguments_are_read_left_to_right(void **state)
{
    (void)state;
    char text[16384];
    /* --help first: help wins over the bad width after it */
    const char *help_first[] = {"--help", "--width", "0", NULL};
    assert_int_equal(parse_capturing_stdout(&SPEC_3D, help_first, text, sizeof text), EXIT_OK);
    /* a bad width first: the error wins */
    const char *error_first[] = {"--width", "0", "--help", NULL};
    assert_int_equal(parse_capturing_stdout(&SPEC_3D, error_first, text, sizeof text),
                     EXIT_USAGE);
    assert_string_equal(text, "");
}

/* ---- The camera ---------------------------------------------------------------- */

static const SceneInfo TEST_SCENE = {
    .name = "test", .about = "a scene for the camera tests",
    .eye = {1, 2, 3}, .target = {0, 1, 0}, .up = {0, 0, 1},
    .fovy = 50, .near = 0.25, .far = 40,
};

static bool resolve(const char *const *args, const SceneInfo *scene, Options *opt, Error *err)
{
    assert_int_equal(parse(&SPEC_3D, args, opt, err), CLI_CONTINUE);
    return cli_resolve_camera(opt, scene, err);
}

static void camera_defaults_without_a_scene(void **state)
{
    (void)state;
    const char *args[] = {"--obj", "m.obj", NULL};
    Options opt;
    Error err;
    assert_true(resolve(args, NULL, &opt, &err));
    assert_true(opt.eye.x == 0 && opt.eye.y == 0 && opt.eye.z == 3);
    assert_true(opt.target.x == 0 && opt.target.y == 0 && opt.target.z == 0);
    assert_true(opt.up.x == 0 && opt.up.y == 1 && opt.up.z == 0);
    assert_true(opt.fovy == 60 && opt.near == 0.1 && opt.far == 100);
}

static void camera_comes_from_the_scene(void **state)
{
    (void)state;
    const char *args[] = {NULL};
    Options opt;
    Error err;
    assert_true(resolve(args, &TEST_SCENE, &opt, &err));
    assert_true(opt.eye.x == 1 && opt.eye.y == 2 && opt.eye.z == 3);
    assert_true(opt.target.y == 1);
    assert_true(opt.up.z == 1);
    assert_true(opt.fovy == 50 && opt.near == 0.25 && opt.far == 40);
}

static void camera_flags_override_only_what_they_name(void **state)
{
    (void)state;
    const char *args[] = {"--eye", "0,0,9", "--far", "90", NULL};
    Options opt;
    Error err;
    assert_true(resolve(args, &TEST_SCENE, &opt, &err));
    assert_true(opt.eye.x == 0 && opt.eye.y == 0 && opt.eye.z == 9); /* given */
    assert_true(opt.far == 90);                                      /* given */
    assert_true(opt.target.y == 1 && opt.up.z == 1);                 /* the scene's */
    assert_true(opt.fovy == 50 && opt.near == 0.25);                 /* the scene's */
}

typedef struct {
    const char *args[MAX_ARGS];
    const char *message;
} BadCamera;

static const BadCamera BAD_CAMERAS[] = {
    {{"--eye", "0,1,0"}, "--eye and --target are the same point"},          /* TEST_SCENE target */
    {{"--eye", "0,0,0", "--target", "0,0,0"}, "--eye and --target are the same point"},
    /* the scene's up is +z; looking straight down -z makes them parallel */
    {{"--eye", "0,0,5", "--target", "0,0,-5"},
     "--up is parallel to the view direction from --eye to --target"},
    {{"--eye", "0,0,5", "--target", "0,0,0", "--up", "0,0,-2"},
     "--up is parallel to the view direction from --eye to --target"},
    {{"--up", "0,0,0"}, "--up is the zero vector"},
    {{"--fovy", "180"}, "--fovy: 180 is out of range (0 < fovy < 180 degrees)"},
    {{"--fovy", "0"}, "--fovy: 0 is out of range (0 < fovy < 180 degrees)"},
    {{"--fovy", "-30"}, "--fovy: -30 is out of range (0 < fovy < 180 degrees)"},
    {{"--near", "0"}, "--near: 0 is out of range (near must be greater than 0)"},
    {{"--near", "2", "--far", "2"}, "--far: 2 is out of range (far must be greater than near, 2)"},
    {{"--far", "0.1"}, "--far: 0.1 is out of range (far must be greater than near, 0.25)"},
    {{"--eye", "1e308,0,0", "--target", "-1e308,0,0", "--up", "0,1,0"},
     "--eye and --target are too far apart"},
    {{"--near", "1", "--far", "1e308"},
     "--fovy, --near and --far give a projection too large to compute"},
};

static void bad_cameras_are_refused_naming_the_flags(void **state)
{
    (void)state;
    int failures = 0, n = (int)(sizeof BAD_CAMERAS / sizeof BAD_CAMERAS[0]);
    for (int k = 0; k < n; k++) {
        Options opt;
        Error err;
        bool ok = resolve(BAD_CAMERAS[k].args, &TEST_SCENE, &opt, &err);
        if (ok || strcmp(err.msg, BAD_CAMERAS[k].message) != 0) {
            print_error("BAD_CAMERAS[%d] (%s %s ...): %s \"%s\", wanted \"%s\"\n", k,
                        BAD_CAMERAS[k].args[0], BAD_CAMERAS[k].args[1],
                        ok ? "accepted" : "refused with", ok ? "" : err.msg,
                        BAD_CAMERAS[k].message);
            failures++;
        }
    }
    if (failures)
        fail_msg("%d of %d bad cameras were not refused as expected (listed above)", failures,
                 n);
}

static void nearly_parallel_up_is_still_fine(void **state)
{
    (void)state;
    /* up tilted 0.01 (sine about 0.01) from the view direction: a valid camera */
    const char *args[] = {"--eye", "0,0,5", "--target", "0,0,0", "--up", "0.01,0,1", NULL};
    Options opt;
    Error err;
    assert_true(resolve(args, &TEST_SCENE, &opt, &err));
}

/* ---- Value parsers ---------------------------------------------------------- */

static void value_parsers_accept_exact_forms(void **state)
{
    (void)state;
    long n;
    double d;
    Vec3 v;
    Error err;
    assert_true(parse_int("--n", "+42", 0, 100, &n, &err) && n == 42);
    assert_true(parse_int("--n", "-7", -10, 10, &n, &err) && n == -7);
    assert_false(parse_int("--n", "11", -10, 10, &n, &err));
    assert_string_equal(err.msg, "--n: 11 is out of range (-10 to 10)");
    assert_true(parse_double("--x", "-2.5e-3", &d, &err) && d == -2.5e-3);
    assert_false(parse_double("--x", "", &d, &err));
    assert_string_equal(err.msg, "--x: '' is not a finite number");
    assert_true(parse_vec3("--v", "1,-2,3e1", &v, &err) && v.x == 1 && v.y == -2 && v.z == 30);
    assert_false(parse_vec3("--v", "1,2,", &v, &err));
    assert_string_equal(err.msg, "--v: '1,2,' is not three finite numbers X,Y,Z");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(bad_lines_give_their_exact_message_and_status_2),
        cmocka_unit_test(unknown_scene_lists_the_known_ones),
        cmocka_unit_test(cli_parse_prints_one_error_line_on_stderr),
        cmocka_unit_test(no_arguments_give_the_lesson_defaults),
        cmocka_unit_test(every_flag_lands_in_its_field),
        cmocka_unit_test(obj_replaces_the_default_scene),
        cmocka_unit_test(scene_by_name),
        cmocka_unit_test(values_may_start_with_a_minus_sign),
        cmocka_unit_test(trace_in_one_dimension_takes_a_column),
        cmocka_unit_test(trace_on_the_last_pixel_is_inside),
        cmocka_unit_test(sizes_at_both_ends_of_the_range),
        cmocka_unit_test(help_exits_0_and_lists_what_the_lesson_takes),
        cmocka_unit_test(help_of_a_1d_lesson_leaves_out_what_it_does_not_take),
        cmocka_unit_test(version_exits_0_with_the_series_version),
        cmocka_unit_test(arguments_are_read_left_to_right),
        cmocka_unit_test(camera_defaults_without_a_scene),
        cmocka_unit_test(camera_comes_from_the_scene),
        cmocka_unit_test(camera_flags_override_only_what_they_name),
        cmocka_unit_test(bad_cameras_are_refused_naming_the_flags),
        cmocka_unit_test(nearly_parallel_up_is_still_fine),
        cmocka_unit_test(value_parsers_accept_exact_forms),
    };
    return cmocka_run_group_tests_name("cli", tests, NULL, NULL);
}
