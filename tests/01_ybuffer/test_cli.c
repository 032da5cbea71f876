/* test_cli.c: build/bin/01_ybuffer run end to end: what it prints, what it
 * writes, and how it refuses bad input (message, exit status, no output). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test_support.h"

#define PROGRAM "01_ybuffer"
#define TEXT_MAX 4096

/* The summary of the default run; the runs are the ones derived in test_ybuffer.c. */
#define DEFAULT_SUMMARY                                                          \
    "3 segments drawn into 800 columns, in the order 1 2 3\n"                    \
    "  1 red     (20,34)-(744,400): won 333 columns: 20-119, 512-744\n"          \
    "  2 green   (120,434)-(444,400): won 268 columns: 120-329, 387-444\n"       \
    "  3 blue    (330,463)-(594,200): won 124 columns: 330-386, 445-511\n"       \
    "  nothing: 75 columns: 0-19, 745-799\n"                                     \
    "column tests: 1315 made, 1174 passed (y > stored), 141 failed\n"

static void expect_same_pixels(const Image *a, const Image *b, const char *what)
{
    expect_count(b->width, a->width, "picture width");
    expect_count(b->height, a->height, "picture height");
    size_t n = (size_t)a->width * (size_t)a->height * 3;
    if (memcmp(a->rgb, b->rgb, n) != 0)
        fail_msg("%s: the pictures differ", what);
}

static void default_run_prints_the_summary_and_writes_three_pictures(void **state)
{
    (void)state;
    const char *dir = test_dir("l01_default");
    Path out = in_dir(dir, "render.png"), yb = in_dir(dir, "yb.png"),
         scene = in_dir(dir, "scene.png");
    const char *args[] = {"--out", out.path, "--ybuffer-out", yb.path, "--scene-out",
                          scene.path, NULL};
    RunResult r = run_program(PROGRAM, args);
    expect_no_message(r.err, PROGRAM);
    expect_count(0, r.status, "exit status");
    char want[TEXT_MAX];
    snprintf(want, sizeof want, DEFAULT_SUMMARY "wrote %s, %s, %s\n", out.path, yb.path,
             scene.path);
    assert_string_equal(r.out, want);
    run_result_free(&r);

    Image im = read_png(out.path);
    expect_count(800, im.width, "picture width");
    expect_count(16, im.height, "picture height"); /* the one row, repeated to --height 16 */
    expect_image(&im, "01_ybuffer", "default_render");
    image_free(&im);
    im = read_png(yb.path);
    expect_image(&im, "01_ybuffer", "default_ybuffer");
    image_free(&im);
    im = read_png(scene.path);
    expect_image(&im, "01_ybuffer", "default_scene");
    image_free(&im);
}

static void no_arguments_writes_out_01_ybuffer_png(void **state)
{
    (void)state;
    const char *args[] = {NULL};
    const char *dir = test_dir("l01_default"); /* not the student's out/ */
    RunResult r = run_program_in(dir, PROGRAM, args);
    expect_count(0, r.status, "exit status");
    assert_string_equal(r.out, DEFAULT_SUMMARY "wrote out/01_ybuffer.png\n");
    assert_true(file_exists(path_join(dir, "out/01_ybuffer.png")));
    run_result_free(&r);
}

static void missing_output_directories_are_created(void **state)
{
    (void)state;
    const char *dir = test_dir("l01_mkdir");
    Path out = in_dir(dir, "new/deeper/render.png");
    const char *args[] = {"--out", out.path, NULL};
    RunResult r = run_program(PROGRAM, args);
    expect_count(0, r.status, "exit status");
    assert_true(file_exists(out.path));
    run_result_free(&r);
}

/* Order 312 draws blue first: at the tie column 387 (green and blue both
 * 406) blue is now the one that stays. Every other column is unchanged. */
static void order_312_changes_only_the_tie_column(void **state)
{
    (void)state;
    const char *dir = test_dir("l01_order");
    Path a = in_dir(dir, "123.png"), b = in_dir(dir, "312.png");
    const char *args_a[] = {"--out", a.path, NULL};
    const char *args_b[] = {"--out", b.path, "--order", "312", NULL};
    RunResult r = run_program(PROGRAM, args_a);
    expect_count(0, r.status, "exit status");
    run_result_free(&r);
    r = run_program(PROGRAM, args_b);
    expect_count(0, r.status, "exit status");
    assert_non_null(strstr(r.out, "in the order 3 1 2\n"));
    assert_non_null(strstr(r.out, "  2 green   (120,434)-(444,400): won 267 columns: 120-329, 388-444\n"));
    assert_non_null(strstr(r.out, "  3 blue    (330,463)-(594,200): won 125 columns: 330-387, 445-511\n"));
    run_result_free(&r);

    Image ia = read_png(a.path), ib = read_png(b.path);
    for (int row = 0; row < ia.height; row++)
        for (int x = 0; x < ia.width; x++) {
            Rgb pa = image_get(&ia, x, row), pb = image_get(&ib, x, row);
            bool same = pa.r == pb.r && pa.g == pb.g && pa.b == pb.b;
            if (x == 387) {
                if (!(pa.g == 255 && pb.b == 255))
                    fail_msg("column 387: expected green (order 123) and blue (order 312)");
            } else if (!same) {
                fail_msg("column %d differs between orders 123 and 312", x);
            }
        }
    image_free(&ia);
    image_free(&ib);
}

static void steps_write_a_render_and_a_ybuffer_per_segment(void **state)
{
    (void)state;
    const char *dir = test_dir("l01_steps");
    Path steps = in_dir(dir, "steps"), out = in_dir(dir, "render.png");
    const char *args[] = {"--out", out.path, "--steps", steps.path, NULL};
    RunResult r = run_program(PROGRAM, args);
    expect_count(0, r.status, "exit status");
    run_result_free(&r);
    static const char *const NAMES[] = {"step_0000.png", "step_0000_depth.png",
                                        "step_0001.png", "step_0001_depth.png",
                                        "step_0002.png", "step_0002_depth.png",
                                        "step_0003.png", "step_0003_depth.png"};
    for (int i = 0; i < 8; i++)
        if (!file_exists(path_join(steps.path, NAMES[i])))
            fail_msg("--steps did not write %s", NAMES[i]);
    /* After step 1 only red is there: columns 20..744. */
    Image s1 = read_png(path_join(steps.path, "step_0001.png"));
    expect_count(0, image_get(&s1, 19, 0).r, "red at column 19 after step 1");
    expect_count(255, image_get(&s1, 20, 0).r, "red at column 20 after step 1");
    expect_count(255, image_get(&s1, 744, 0).r, "red at column 744 after step 1");
    expect_count(0, image_get(&s1, 745, 0).r, "red at column 745 after step 1");
    image_free(&s1);
    /* The last step is the final picture. */
    Image s3 = read_png(path_join(steps.path, "step_0003.png")), final = read_png(out.path);
    expect_same_pixels(&s3, &final, "step_0003.png against --out");
    image_free(&s3);
    image_free(&final);
}

static void segments_file_with_the_default_scene_gives_the_default_picture(void **state)
{
    (void)state;
    const char *dir = test_dir("l01_file");
    Path file = in_dir(dir, "scene.txt"), a = in_dir(dir, "file.png"),
         b = in_dir(dir, "default.png");
    write_text(file.path, "# x0 y0 x1 y1 r g b\n"
                          "20 34 744 400 255 0 0\n"
                          "120 434 444 400 0 255 0\n"
                          "330 463 594 200 0 0 255\n");
    const char *args_a[] = {"--segments", file.path, "--out", a.path, NULL};
    const char *args_b[] = {"--out", b.path, NULL};
    RunResult r = run_program(PROGRAM, args_a);
    expect_count(0, r.status, "exit status");
    char want[TEXT_MAX];
    snprintf(want, sizeof want, DEFAULT_SUMMARY "wrote %s\n", a.path);
    assert_string_equal(r.out, want);
    run_result_free(&r);
    r = run_program(PROGRAM, args_b);
    run_result_free(&r);
    Image ia = read_png(a.path), ib = read_png(b.path);
    expect_same_pixels(&ia, &ib, "--segments with the default scene");
    image_free(&ia);
    image_free(&ib);
}

static void empty_segments_file_draws_nothing(void **state)
{
    (void)state;
    const char *dir = test_dir("l01_empty");
    Path file = in_dir(dir, "empty.txt"), out = in_dir(dir, "render.png");
    write_text(file.path, "");
    const char *args[] = {"--segments", file.path, "--out", out.path, NULL};
    RunResult r = run_program(PROGRAM, args);
    expect_count(0, r.status, "exit status");
    char want[TEXT_MAX];
    snprintf(want, sizeof want,
             "no segments drawn into 800 columns\n"
             "  nothing: 800 columns: 0-799\n"
             "column tests: 0 made, 0 passed (y > stored), 0 failed\n"
             "wrote %s\n",
             out.path);
    assert_string_equal(r.out, want);
    run_result_free(&r);
    Image im = read_png(out.path);
    for (int x = 0; x < im.width; x++)
        expect_pixel(&im, x, 0, (Rgb){0, 0, 0}, "nothing drawn");
    image_free(&im);
}

/* A vertical segment wins its one column; one off screen wins none. */
static void vertical_and_off_screen_segments_from_a_file(void **state)
{
    (void)state;
    const char *dir = test_dir("l01_vertical");
    Path file = in_dir(dir, "v.txt"), out = in_dir(dir, "render.png");
    write_text(file.path, "100 10 100 50 255 255 0\n-300 5 -1 5 0 255 255\n");
    const char *args[] = {"--segments", file.path, "--out", out.path, "--width", "200", NULL};
    RunResult r = run_program(PROGRAM, args);
    expect_count(0, r.status, "exit status");
    char want[TEXT_MAX];
    snprintf(want, sizeof want,
             "2 segments drawn into 200 columns, in the order 1 2\n"
             "  1 yellow  (100,10)-(100,50): won 1 column: 100\n"
             "  2 cyan    (-300,5)-(-1,5): won 0 columns\n"
             "  nothing: 199 columns: 0-99, 101-199\n"
             "column tests: 1 made, 1 passed (y > stored), 0 failed\n"
             "wrote %s\n",
             out.path);
    assert_string_equal(r.out, want);
    run_result_free(&r);
}

static void bad_order_is_a_usage_error(void **state)
{
    (void)state;
    const char *dir = test_dir("l01_bad_order");
    Path out = in_dir(dir, "render.png");
    const char *args[] = {"--out", out.path, "--order", "12", NULL};
    expect_run_refused(PROGRAM, args, 2,
                       "--order '12': expected each of 1..3 exactly once, as digits (e.g. 312) "
                       "or separated by commas",
                       out.path);
    const char *args2[] = {"--out", out.path, "--order", "332", NULL};
    expect_run_refused(PROGRAM, args2, 2,
                       "--order '332': expected each of 1..3 exactly once, as digits (e.g. 312) "
                       "or separated by commas",
                       out.path);
}

static void missing_segments_file_fails_with_status_1(void **state)
{
    (void)state;
    const char *dir = test_dir("l01_missing");
    Path out = in_dir(dir, "render.png"), file = in_dir(dir, "nope.txt");
    const char *args[] = {"--out", out.path, "--segments", file.path, NULL};
    char msg[TEXT_MAX];
    snprintf(msg, sizeof msg, "cannot read %s: No such file or directory", file.path);
    expect_run_refused(PROGRAM, args, 1, msg, out.path);
}

static void malformed_segments_file_names_the_line(void **state)
{
    (void)state;
    const char *dir = test_dir("l01_malformed");
    Path out = in_dir(dir, "render.png"), file = in_dir(dir, "bad.txt");
    write_text(file.path, "20 34 744 400 255 0 0\n\n1 2 3 4 5\n");
    const char *args[] = {"--out", out.path, "--segments", file.path, NULL};
    char msg[TEXT_MAX];
    snprintf(msg, sizeof msg, "%s:3: expected 7 numbers 'x0 y0 x1 y1 r g b', got 5",
             file.path);
    expect_run_refused(PROGRAM, args, 1, msg, out.path);

    write_text(file.path, "20 34 744 400 255 300 0\n");
    snprintf(msg, sizeof msg, "%s:1: g 300 is out of range 0..255", file.path);
    expect_run_refused(PROGRAM, args, 1, msg, out.path);
}

static void two_outputs_with_one_name_are_refused(void **state)
{
    (void)state;
    const char *dir = test_dir("l01_same");
    Path out = in_dir(dir, "x.png");
    const char *args[] = {"--out", out.path, "--scene-out", out.path, NULL};
    char msg[TEXT_MAX];
    snprintf(msg, sizeof msg, "--out and --scene-out both name %s", out.path);
    expect_run_refused(PROGRAM, args, 2, msg, out.path);
}

static void unknown_flag_and_bad_width_are_usage_errors(void **state)
{
    (void)state;
    const char *dir = test_dir("l01_usage");
    Path out = in_dir(dir, "x.png");
    const char *a1[] = {"--out", out.path, "--bogus", NULL};
    expect_run_refused(PROGRAM, a1, 2, "unknown flag '--bogus' (try --help)", out.path);
    const char *a2[] = {"--out", out.path, "--width", "0", NULL};
    expect_run_refused(PROGRAM, a2, 2, "--width: 0 is out of range (1 to 16384)", out.path);
    const char *a3[] = {"--out", out.path, "--order", NULL};
    expect_run_refused(PROGRAM, a3, 2, "--order needs a value", out.path);
}

static void unwritable_output_fails_with_status_1(void **state)
{
    (void)state;
    const char *dir = test_dir("l01_unwritable");
    Path blocker = in_dir(dir, "a-file"), out = in_dir(dir, "a-file/render.png");
    write_text(blocker.path, "not a directory\n");
    const char *args[] = {"--out", out.path, NULL};
    RunResult r = run_program(PROGRAM, args);
    /* The reason after the path is file.c's wording; the lesson's part is the
     * program name, the path, one line, status 1 and no picture. */
    char want[TEXT_MAX];
    snprintf(want, sizeof want, "01_ybuffer: error: cannot create directory %s: ", blocker.path);
    if (strncmp(r.err, want, strlen(want)) != 0)
        fail_msg("stderr: \"%s\", expected it to start with \"%s\"", r.err, want);
    assert_ptr_equal(strchr(r.err, '\n'), r.err + strlen(r.err) - 1); /* one line */
    expect_count(1, r.status, "exit status");
    assert_false(file_exists(out.path));
    run_result_free(&r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(default_run_prints_the_summary_and_writes_three_pictures),
        cmocka_unit_test(no_arguments_writes_out_01_ybuffer_png),
        cmocka_unit_test(missing_output_directories_are_created),
        cmocka_unit_test(order_312_changes_only_the_tie_column),
        cmocka_unit_test(steps_write_a_render_and_a_ybuffer_per_segment),
        cmocka_unit_test(segments_file_with_the_default_scene_gives_the_default_picture),
        cmocka_unit_test(empty_segments_file_draws_nothing),
        cmocka_unit_test(vertical_and_off_screen_segments_from_a_file),
        cmocka_unit_test(bad_order_is_a_usage_error),
        cmocka_unit_test(missing_segments_file_fails_with_status_1),
        cmocka_unit_test(malformed_segments_file_names_the_line),
        cmocka_unit_test(two_outputs_with_one_name_are_refused),
        cmocka_unit_test(unknown_flag_and_bad_width_are_usage_errors),
        cmocka_unit_test(unwritable_output_fails_with_status_1),
    };
    return cmocka_run_group_tests_name("01_ybuffer: command line", tests, NULL, NULL);
}
