/* test_tool_flags.c: every lesson takes every inspection tool, or refuses it
 * clearly. One table: each lesson found in lessons/ (so a new lesson is tested
 * without touching this file) times each of --trace, --ascii, --compare and
 * --steps.
 *
 * A lesson that takes a flag must show its effect:
 *   --trace    a history of the pixel (or column): a "trace ..." line ending
 *              with a "winner: ..." line, or "no fragment reached ..."
 *   --ascii    a legend line, then one row of 40 characters from "0123456789."
 *              per pixel row (one row for the one-row lesson 01)
 *   --compare  the same command twice: the second run, comparing with the
 *              first run's picture, says "compare: the images match", exits
 *              0 and writes the diff picture next to --out
 *   --steps    DIR/step_0000.png and DIR/step_0001.png with their _depth.png,
 *              each the size of the picture
 * A lesson that does not take it must exit 2 with the one line
 *   "<lesson>: error: <flag> does not apply to <lesson> (<reason>)".
 * Lessons 01 to 04 must take all four (the tools were built for them). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness/image_io.h"
#include "test_support.h"

#define MAX_LESSONS 64
#define NAME_MAX_LEN 64
#define WIDTH 40
#define HEIGHT 20
#define WIDTH_TEXT "40"
#define HEIGHT_TEXT "20"

/* The lessons that must take every tool: the first four. */
static const char *const MUST_TAKE_ALL[] = {"01_ybuffer", "02_zbuffer", "03_perspective_z",
                                            "04_scanline_inverse_z"};

typedef enum { TOOL_TRACE, TOOL_ASCII, TOOL_COMPARE, TOOL_STEPS, TOOL_COUNT } Tool;
static const char *const TOOL_FLAG[TOOL_COUNT] = {"--trace", "--ascii", "--compare", "--steps"};

/* lessons/NN_name directories, sorted. */
static int find_lessons(char names[MAX_LESSONS][NAME_MAX_LEN])
{
    DIR *d = opendir("lessons");
    if (!d)
        fail_msg("cannot open lessons/: tests run from the top of the tree");
    int n = 0;
    for (struct dirent *e; (e = readdir(d)) && n < MAX_LESSONS;) {
        const char *s = e->d_name;
        if (s[0] >= '0' && s[0] <= '9' && s[1] >= '0' && s[1] <= '9' && s[2] == '_' &&
            strlen(s) < NAME_MAX_LEN)
            snprintf(names[n++], NAME_MAX_LEN, "%.*s", NAME_MAX_LEN - 1, s);
    }
    closedir(d);
    qsort(names, (size_t)n, NAME_MAX_LEN, compare_strings);
    return n;
}

static bool must_take_all(const char *lesson)
{
    for (size_t i = 0; i < sizeof MUST_TAKE_ALL / sizeof MUST_TAKE_ALL[0]; i++)
        if (strcmp(lesson, MUST_TAKE_ALL[i]) == 0)
            return true;
    return false;
}

/* A lesson that draws one row traces a column: its --help says "--trace X ". */
static bool is_one_row(const char *lesson)
{
    const char *args[] = {"--help", NULL};
    RunResult r = run_program(lesson, args);
    bool one_row = strstr(r.out, "--trace X ") != NULL;
    run_result_free(&r);
    return one_row;
}

static bool is_refusal(const char *lesson, const char *flag, const RunResult *r)
{
    char start[160];
    int n = snprintf(start, sizeof start, "%s: error: %s does not apply to %s (", lesson, flag,
                     lesson);
    if (n < 0 || (size_t)n >= sizeof start)
        fail_msg("the refusal of %s by %s is too long to check", flag, lesson);
    size_t len = strlen(r->err);
    return r->status == 2 && strncmp(r->err, start, strlen(start)) == 0 && len > 2 &&
           strcmp(r->err + len - 2, ")\n") == 0 && strchr(r->err, '\n') == r->err + len - 1;
}

/* Runs lesson with the common arguments (--out dir/picture.png, 40x20) plus
 * extra, which ends with NULL. */
static RunResult run_with(const char *lesson, const char *out, const char *const *extra)
{
    const char *args[16] = {"--out", out, "--width", WIDTH_TEXT, "--height", HEIGHT_TEXT};
    int n = 6;
    for (int k = 0; extra[k] && n < 15; k++)
        args[n++] = extra[k];
    args[n] = NULL;
    return run_program(lesson, args);
}

static bool line_starts_with(const char *text, const char *start)
{
    size_t n = strlen(start);
    if (strncmp(text, start, n) == 0)
        return true;
    for (const char *p = strchr(text, '\n'); p; p = strchr(p + 1, '\n'))
        if (strncmp(p + 1, start, n) == 0)
            return true;
    return false;
}

static void expect_trace_effect(const char *lesson, bool one_row, const RunResult *r)
{
    char head[64], none[64];
    if (one_row) {
        snprintf(head, sizeof head, "trace column %d: ", WIDTH / 2);
        snprintf(none, sizeof none, "no fragment reached column %d;", WIDTH / 2);
    } else {
        snprintf(head, sizeof head, "trace pixel (%d,%d): ", WIDTH / 2, HEIGHT / 2);
        snprintf(none, sizeof none, "no fragment reached pixel (%d,%d);", WIDTH / 2, HEIGHT / 2);
    }
    bool traced = line_starts_with(r->out, head) && line_starts_with(r->out, "winner: ");
    if (!traced && !line_starts_with(r->out, none))
        fail_msg("%s --trace printed no history of its pixel:\n%s", lesson, r->out);
}

/* The legend line, then `rows` lines of WIDTH characters from "0123456789.". */
static void expect_ascii_effect(const char *lesson, int rows, const RunResult *r)
{
    const char *legend = strstr(r->out, "'.' = empty\n");
    if (!legend)
        fail_msg("%s --ascii printed no legend ending \"'.' = empty\":\n%s", lesson, r->out);
    const char *p = legend + strlen("'.' = empty\n");
    for (int row = 0; row < rows; row++) {
        size_t n = strspn(p, "0123456789.");
        if (n != WIDTH || p[n] != '\n')
            fail_msg("%s --ascii: row %d is not %d digits or dots:\n%s", lesson, row, WIDTH,
                     r->out);
        p += n + 1;
    }
}

static void expect_png_of_size(const char *lesson, const char *path, int width, int height)
{
    Image im;
    Error err;
    if (!image_read_png(&im, path, &err))
        fail_msg("%s --steps: %s", lesson, err.msg);
    if (im.width != width || im.height != height)
        fail_msg("%s --steps: %s is %dx%d, not %dx%d", lesson, path, im.width, im.height, width,
                 height);
    image_free(&im);
}

static void check_tool(const char *lesson, Tool tool, bool one_row)
{
    char dir[512], out[600], ref[600], steps[600], diff[600];
    snprintf(dir, sizeof dir, "%s", test_dir("tools_flags"));
    snprintf(out, sizeof out, "%s/picture.png", dir);
    snprintf(ref, sizeof ref, "%s/reference.png", dir);
    snprintf(steps, sizeof steps, "%s/steps", dir);
    snprintf(diff, sizeof diff, "%s/picture.diff.png", dir);
    char pixel[32];
    if (one_row)
        snprintf(pixel, sizeof pixel, "%d", WIDTH / 2);
    else
        snprintf(pixel, sizeof pixel, "%d,%d", WIDTH / 2, HEIGHT / 2);

    if (tool == TOOL_COMPARE) { /* the reference: the same picture, drawn first */
        const char *none[] = {NULL};
        RunResult first = run_with(lesson, ref, none);
        if (first.status != 0)
            fail_msg("%s exited with %d drawing the reference: %s", lesson, first.status,
                     first.err);
        run_result_free(&first);
    }
    const char *extra[TOOL_COUNT][3] = {
        [TOOL_TRACE] = {"--trace", pixel, NULL},
        [TOOL_ASCII] = {"--ascii", NULL, NULL},
        [TOOL_COMPARE] = {"--compare", ref, NULL},
        [TOOL_STEPS] = {"--steps", steps, NULL},
    };
    RunResult r = run_with(lesson, out, extra[tool]);
    if (is_refusal(lesson, TOOL_FLAG[tool], &r)) {
        if (must_take_all(lesson))
            fail_msg("%s refuses %s, but lessons 01-04 must take it: %s", lesson,
                     TOOL_FLAG[tool], r.err);
        run_result_free(&r);
        return;
    }
    if (r.status != 0)
        fail_msg("%s %s exited with %d, neither a clear refusal (exit 2, \"... does not apply "
                 "to ...\") nor success:\n%s", lesson, TOOL_FLAG[tool], r.status, r.err);
    int picture_height = HEIGHT; /* lesson 01 repeats its row over the picture's height too */
    switch (tool) {
    case TOOL_TRACE: expect_trace_effect(lesson, one_row, &r); break;
    case TOOL_ASCII: expect_ascii_effect(lesson, one_row ? 1 : HEIGHT, &r); break;
    case TOOL_COMPARE:
        if (!strstr(r.out, "compare: the images match\n") || !file_exists(diff))
            fail_msg("%s --compare against its own picture: expected \"compare: the images "
                     "match\" and %s:\n%s", lesson, diff, r.out);
        break;
    case TOOL_STEPS:
        for (int k = 0; k < 2; k++) {
            char frame[700], depth[700];
            snprintf(frame, sizeof frame, "%s/step_%04d.png", steps, k);
            snprintf(depth, sizeof depth, "%s/step_%04d_depth.png", steps, k);
            expect_png_of_size(lesson, frame, WIDTH, picture_height);
            expect_png_of_size(lesson, depth, WIDTH, picture_height);
        }
        break;
    case TOOL_COUNT: break;
    }
    run_result_free(&r);
}

static void every_lesson_takes_every_tool_or_refuses_it_clearly(void **state)
{
    (void)state;
    char lessons[MAX_LESSONS][NAME_MAX_LEN];
    int n = find_lessons(lessons);
    if (n < 4)
        fail_msg("found %d lessons in lessons/, expected at least 01 to 04", n);
    for (int i = 0; i < n; i++) {
        bool one_row = is_one_row(lessons[i]);
        for (int tool = 0; tool < TOOL_COUNT; tool++)
            check_tool(lessons[i], (Tool)tool, one_row);
    }
}

/* The knot scene has 3072 faces: 6146 pictures would be written. --steps
 * refuses before anything is drawn or written. */
static void steps_refuses_a_mesh_of_more_than_2000_faces(void **state)
{
    (void)state;
    char dir[512], out[600], steps[600];
    snprintf(dir, sizeof dir, "%s", test_dir("tools_steps_limit"));
    snprintf(out, sizeof out, "%s/knot.png", dir);
    snprintf(steps, sizeof steps, "%s/steps", dir);
    const char *args[] = {"--scene", "knot", "--out", out, "--steps", steps, NULL};
    RunResult r = run_program("02_zbuffer", args);
    assert_int_equal(r.status, 1);
    assert_string_equal(r.err, "02_zbuffer: error: --steps: the mesh has 3072 faces; --steps "
                               "writes two pictures per face and takes at most 2000 faces\n");
    run_result_free(&r);
    assert_false(file_exists(steps));
    assert_false(file_exists(out));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_lesson_takes_every_tool_or_refuses_it_clearly),
        cmocka_unit_test(steps_refuses_a_mesh_of_more_than_2000_faces),
    };
    return cmocka_run_group_tests_name("tools: every lesson, every flag", tests, NULL, NULL);
}
