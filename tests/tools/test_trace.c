/* test_trace.c: --trace X,Y prints a pixel's history exactly, in every lesson.
 *
 * The scene is made by hand: three triangles, each at one view depth (so every
 * fragment brings exactly that depth, whatever the interpolation), all
 * covering pixel (40,15), written to an OBJ file in this order:
 *
 *     face 0 at d = 5      passes against the cleared buffer
 *     face 1 at d = 8      fails: 8 is farther than the stored 5
 *     face 2 at d = 4      passes: 4 is nearer than 5
 *
 * The camera sits at the origin looking down -Z, up +Y, with
 * fovy = 2 atan(0.6) (61.927513...°), on an 80x30 image (aspect 8/3):
 *     f = 1 / tan(fovy / 2) = 5/3,
 *     x_ndc = (f / aspect) X/d = (5/8) X/d     x_s = (x_ndc + 1) * 40 = 40 + 25 X/d
 *     y_ndc = f Y/d = (5/3) Y/d                y_s = (1 - y_ndc) * 15 = 15 - 25 Y/d
 * so a screen corner (x_s, y_s) at depth d is the point
 *     X = (x_s - 40) d / 25,  Y = (15 - y_s) d / 25,  Z = -d.
 * Screen corners, and why pixel (40,15), centre (40.5, 15.5), is inside:
 *     face 0 (25,25) (50,25) (35,0):  at y = 15.5 the edges are at x = 28.8 and 44.3
 *     face 1 (30,5)  (65,5)  (45,30): at y = 15.5 the edges are at x = 36.3 and 56.6
 *     face 2 (15,10) (55,10) (40,28): at y = 15.5 the edges are at x = 22.6 and 50.4
 * Pixel (0,0) is covered by none of them.
 *
 * Lessons 02 and 03 store d and clear to inf; lesson 04 stores 1/d and clears
 * to 0, so its lines read 1/5 = 0.2, 1/8 = 0.125, 1/4 = 0.25. All of these are
 * printed as the shortest text that gives back the stored float (trace.h).
 *
 * Lesson 01 is traced on its own scene (docs/01_ybuffer.md), column 400:
 *     red   (20,34)-(744,400):   y = 34 + 366 * 380 / 724 = 226.10 -> 226
 *     green (120,434)-(444,400): y = 434 - 34 * 280 / 324 = 404.62 -> 405
 *     blue  (330,463)-(594,200): y = 463 - 263 * 70 / 264 = 393.27 -> 393
 * red passes against the cleared column (-inf), green passes (405 > 226), blue
 * fails (393 < 405): green, segment 2, wins. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness/depth_rule.h"
#include "test_support.h"

#define FOVY_TAN_06 "61.92751306414704" /* 2 atan(0.6) in degrees */

static const char *const THREE_TRIANGLES =
    "# three triangles over pixel (40,15): d = 5, 8, 4 (see test_trace.c)\n"
    "v -3 -2 -5\nv 2 -2 -5\nv -1 3 -5\n"
    "v -3.2 3.2 -8\nv 8 3.2 -8\nv 1.6 -4.8 -8\n"
    "v -4 0.8 -4\nv 2.4 0.8 -4\nv 0 -2.08 -4\n"
    "f 1 2 3\nf 4 5 6\nf 7 8 9\n";

/* The text after the summary: from the line that starts with `first` on. */
static const char *from_line(const char *out, const char *first)
{
    for (const char *line = out; line; line = strchr(line, '\n')) {
        line += line != out; /* past the newline */
        if (strncmp(line, first, strlen(first)) == 0)
            return line;
    }
    return NULL;
}

static void expect_trace(const char *lesson, const char *pixel, const char *expected)
{
    const char *dir = test_dir("tools_trace");
    const char *obj = write_text_in(dir, "three.obj", THREE_TRIANGLES);
    const char *args[] = {"--obj", obj, "--out", path_join(dir, "three.png"), "--width", "80",
                          "--height", "30", "--eye", "0,0,0", "--target", "0,0,-1", "--up",
                          "0,1,0", "--fovy", FOVY_TAN_06, "--near", "1", "--far", "100",
                          "--trace", pixel, NULL};
    RunResult r = run_program(lesson, args);
    if (r.status != 0)
        fail_msg("%s --trace %s exited with %d: %s", lesson, pixel, r.status, r.err);
    const char *got = from_line(r.out, strncmp(expected, "no ", 3) == 0 ? "no " : "trace ");
    if (!got || strcmp(got, expected) != 0)
        fail_msg("%s --trace %s printed:\n%s\nexpected, after the summary:\n%s", lesson, pixel,
                 r.out, expected);
    run_result_free(&r);
}

static void three_triangles_traced_in_order_storing_d(void **state)
{
    (void)state;
    static const char *const LESSONS[] = {"02_zbuffer", "03_perspective_z"};
    for (int i = 0; i < 2; i++)
        expect_trace(LESSONS[i], "40,15",
                     "trace pixel (40,15): 3 fragments\n"
                     "  1. face 0   d=5            stored=inf          passed\n"
                     "  2. face 1   d=8            stored=5            failed\n"
                     "  3. face 2   d=4            stored=5            passed\n"
                     "winner: face 2, stored d=4\n");
}

static void three_triangles_traced_in_order_storing_inverse_d(void **state)
{
    (void)state;
    expect_trace("04_scanline_inverse_z", "40,15",
                 "trace pixel (40,15): 3 fragments\n"
                 "  1. face 0   1/d=0.2          stored=0            passed\n"
                 "  2. face 1   1/d=0.125        stored=0.2          failed\n"
                 "  3. face 2   1/d=0.25         stored=0.2          passed\n"
                 "winner: face 2, stored 1/d=0.25\n");
}

static void pixel_no_face_reached_says_so_with_the_clear_value(void **state)
{
    (void)state;
    expect_trace("02_zbuffer", "0,0", "no fragment reached pixel (0,0); stored: inf (cleared)\n");
    expect_trace("03_perspective_z", "0,0",
                 "no fragment reached pixel (0,0); stored: inf (cleared)\n");
    expect_trace("04_scanline_inverse_z", "0,0",
                 "no fragment reached pixel (0,0); stored: 0 (cleared)\n");
}

static void ybuffer_column_traced_with_segments_numbered_from_one(void **state)
{
    (void)state;
    const char *dir = test_dir("tools_trace_01");
    const char *args[] = {"--out", path_join(dir, "row.png"), "--trace", "400", NULL};
    RunResult r = run_program("01_ybuffer", args);
    assert_int_equal(r.status, 0);
    const char *expected = "trace column 400: 3 fragments\n"
                           "  1. segment 1   y=226          stored=-inf         passed\n"
                           "  2. segment 2   y=405          stored=226          passed\n"
                           "  3. segment 3   y=393          stored=405          failed\n"
                           "winner: segment 2, stored y=405\n";
    const char *got = from_line(r.out, "trace ");
    if (!got || strcmp(got, expected) != 0)
        fail_msg("01_ybuffer --trace 400 printed:\n%s\nexpected at the end:\n%s", r.out, expected);
    run_result_free(&r);

    const char *empty[] = {"--out", path_join(dir, "row.png"), "--trace", "10", NULL};
    r = run_program("01_ybuffer", empty); /* red starts at column 20 */
    assert_int_equal(r.status, 0);
    got = from_line(r.out, "no ");
    if (!got || strcmp(got, "no fragment reached column 10; stored: -inf (cleared)\n") != 0)
        fail_msg("01_ybuffer --trace 10 printed:\n%s", r.out);
    run_result_free(&r);
}

/* The clear-zero bug of lesson 02: every fragment fails against 0, and the
 * trace says that nothing won. Pixel (40,15) gets the three faces' d in order. */
static void trace_shows_every_fragment_failing_in_the_clear_zero_bug(void **state)
{
    (void)state;
    const char *dir = test_dir("tools_trace_bug");
    const char *obj = write_text_in(dir, "three.obj", THREE_TRIANGLES);
    const char *args[] = {"--obj", obj, "--out", path_join(dir, "three.png"), "--width", "80",
                          "--height", "30", "--eye", "0,0,0", "--target", "0,0,-1", "--up",
                          "0,1,0", "--fovy", FOVY_TAN_06, "--near", "1", "--far", "100",
                          "--trace", "40,15", "--bug", "clear-zero", NULL};
    RunResult r = run_program("02_zbuffer", args);
    assert_int_equal(r.status, 0);
    const char *expected = "trace pixel (40,15): 3 fragments\n"
                           "  1. face 0   d=5            stored=0            failed\n"
                           "  2. face 1   d=8            stored=0            failed\n"
                           "  3. face 2   d=4            stored=0            failed\n"
                           "winner: none (no fragment passed), stored d=0\n";
    const char *got = from_line(r.out, "trace ");
    if (!got || strcmp(got, expected) != 0)
        fail_msg("02_zbuffer --bug clear-zero --trace 40,15 printed:\n%s\nexpected at the end:\n%s",
                 r.out, expected);
    run_result_free(&r);
}

/* format_stored: the fewest digits (6 to 9) that read back as the same float.
 * 4.25 and 0.2f need few; 1/6 as a float is 0.16666667163..., and 0.166667
 * reads back as another float, so it takes 8 digits. The float just above 5.1f
 * (5.09999990463) is 5.10000038147: "5.1" and "5.100000" read back as 5.1f,
 * "5.1000004" as itself, so a near-tie never prints as a tie. A unorm code
 * prints whole: 16351140 would read back from "1.635114e+07", but not to a
 * reader comparing it with the codes beside it. */
static void stored_values_print_with_the_fewest_digits_that_read_back(void **state)
{
    (void)state;
    char buf[STORED_TEXT_MAX];
    assert_string_equal(format_stored(4.25f, buf), "4.25");
    assert_string_equal(format_stored(0.2f, buf), "0.2");
    assert_string_equal(format_stored(1.0f / 6.0f, buf), "0.16666667");
    assert_string_equal(format_stored(5.1f, buf), "5.1");
    assert_string_equal(format_stored(nextafterf(5.1f, 6.0f), buf), "5.1000004");
    assert_string_equal(format_stored(16351140.0f, buf), "16351140");
    assert_string_equal(format_stored(16777215.0f, buf), "16777215");
    assert_string_equal(format_stored(1.0f, buf), "1");
    assert_string_equal(format_stored(-0.0f, buf), "-0");
    assert_string_equal(format_stored(INFINITY, buf), "inf");
    assert_string_equal(format_stored(-INFINITY, buf), "-inf");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(three_triangles_traced_in_order_storing_d),
        cmocka_unit_test(three_triangles_traced_in_order_storing_inverse_d),
        cmocka_unit_test(pixel_no_face_reached_says_so_with_the_clear_value),
        cmocka_unit_test(ybuffer_column_traced_with_segments_numbered_from_one),
        cmocka_unit_test(trace_shows_every_fragment_failing_in_the_clear_zero_bug),
        cmocka_unit_test(stored_values_print_with_the_fewest_digits_that_read_back),
    };
    return cmocka_run_group_tests_name("tools: --trace", tests, NULL, NULL);
}
