/* test_ascii.c: --ascii prints the depth buffer as digits.
 *
 * First the two 8x3 z-buffers of John De Goes' 1990s text on the Z-buffer,
 * where the series starts, drawn by the lessons themselves: a triangle facing
 * the camera at d = 5, alone,
 *
 *     ...55...
 *     ..5555..
 *     .555555.
 *
 * then a quad at d = 6 behind it that covers the whole screen:
 *
 *     66655666
 *     66555566
 *     65555556
 *
 * (the text leaves the empty pixels blank; --ascii prints '.').
 *
 * The scene, derived by hand: the camera at the origin looks down -Z, up +Y,
 * fovy = 2 atan(0.6), on an 8x3 image (aspect 8/3). Then f = 1/tan(fovy/2) = 5/3
 * and
 *     x_s = (x_ndc + 1) * 8/2 = 4 + 4 (f / aspect) X/d = 4 + (5/2) X/d
 *     y_s = (1 - y_ndc) * 3/2 = 3/2 - (3/2) f Y/d   = 3/2 - (5/2) Y/d
 * At d = 5: x_s = 4 + X/2, y_s = 3/2 - Y/2. The triangle (0,4,-5), (-8,-4,-5),
 * (8,-4,-5) lands on (4,-0.5), (0,3.5), (8,3.5): at the pixel centres' rows
 * y = 0.5, 1.5, 2.5 it spans 3..5, 2..6, 1..7, and covers the centres
 * 3.5..4.5, 2.5..5.5, 1.5..6.5, exactly the text's pixels (no centre lies on
 * an edge: each is half a pixel away). The quad at d = 6 has corners at X, Y = ±20,
 * i.e. x_s = 4 ± 8.3, y_s = 1.5 ± 8.3: far beyond the screen on every side.
 *
 * Lessons 02 and 03 store d: the values are the whole numbers 5 and 6, so the
 * maps print exactly as the text's. Lesson 04 stores 1/d: 0.2 and 0.1667 are not
 * whole numbers, so they are printed in ten steps, nearest (largest 1/d,
 * the d = 5 triangle) as 0 and farthest (the d = 6 quad) as 9: the same shapes
 * with 0 for 5 and 9 for 6. docs/tools.md shows both.
 *
 * Then lesson 01's one row, and ascii_print itself on values chosen so that
 * each digit's boundary is known. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness/ascii.h"
#include "test_support.h"

#define FOVY_TAN_06 "61.92751306414704" /* 2 atan(0.6) in degrees */

static const char *const TRIANGLE_AT_5 =
    "# a triangle facing the camera at d = 5 (test_ascii.c)\n"
    "v 0 4 -5\nv -8 -4 -5\nv 8 -4 -5\n"
    "f 1 2 3\n";

static const char *const TRIANGLE_AT_5_QUAD_AT_6 =
    "# the triangle at d = 5, then a quad at d = 6 behind it, larger than the view\n"
    "v 0 4 -5\nv -8 -4 -5\nv 8 -4 -5\n"
    "v -20 -20 -6\nv 20 -20 -6\nv 20 20 -6\nv -20 20 -6\n"
    "f 1 2 3\nf 4 5 6 7\n";

/* What follows the line starting with legend_start: the legend itself in
 * *legend, the rows as the return value. */
static const char *ascii_part(const char *out, const char *legend_start, char *legend,
                              size_t size)
{
    const char *at = strstr(out, legend_start);
    if (!at || (at != out && at[-1] != '\n'))
        return NULL;
    const char *eol = strchr(at, '\n');
    if (!eol)
        return NULL;
    snprintf(legend, size, "%.*s", (int)(eol - at), at);
    return eol + 1;
}

static void expect_text_map(const char *lesson, const char *obj_text, const char *legend_want,
                            const char *rows_want)
{
    const char *dir = test_dir("tools_ascii");
    const char *obj = write_text_in(dir, "map.obj", obj_text);
    const char *args[] = {"--obj", obj, "--out", path_join(dir, "map.png"), "--width", "8",
                          "--height", "3", "--eye", "0,0,0", "--target", "0,0,-1", "--up",
                          "0,1,0", "--fovy", FOVY_TAN_06, "--near", "1", "--far", "100",
                          "--ascii", NULL};
    RunResult r = run_program(lesson, args);
    if (r.status != 0)
        fail_msg("%s --ascii exited with %d: %s", lesson, r.status, r.err);
    char legend[256];
    const char *rows = ascii_part(r.out, "depth buffer 8x3, ", legend, sizeof legend);
    if (!rows || strcmp(rows, rows_want) != 0 || strncmp(legend, legend_want, strlen(legend_want)))
        fail_msg("%s --ascii printed:\n%s\nexpected a legend starting \"%s\", then\n%s", lesson,
                 r.out, legend_want, rows_want);
    run_result_free(&r);
}

#define LEGEND_AS_IS \
    "depth buffer 8x3, digit = d itself (all values are whole numbers 0-9); '.' = empty"

static void maps_print_as_the_zbuffer_text_draws_them_storing_d(void **state)
{
    (void)state;
    static const char *const LESSONS[] = {"02_zbuffer", "03_perspective_z"};
    for (int i = 0; i < 2; i++) {
        expect_text_map(LESSONS[i], TRIANGLE_AT_5, LEGEND_AS_IS, "...55...\n..5555..\n.555555.\n");
        expect_text_map(LESSONS[i], TRIANGLE_AT_5_QUAD_AT_6, LEGEND_AS_IS,
                        "66655666\n66555566\n65555556\n");
    }
}

static void text_maps_print_stored_inverse_d_nearest_as_0(void **state)
{
    (void)state;
    /* One value only (1/d = 0.2 everywhere): the range is empty, every pixel is step 0. */
    expect_text_map("04_scanline_inverse_z", TRIANGLE_AT_5,
                    "depth buffer 8x3, stored 1/d in ten steps: 0 = nearest (1/d=0.2) .. "
                    "9 = farthest (1/d=0.2)",
                    "...00...\n..0000..\n.000000.\n");
    /* 1/5 nearest is 0, 1/6 farthest is 9. */
    expect_text_map("04_scanline_inverse_z", TRIANGLE_AT_5_QUAD_AT_6,
                    "depth buffer 8x3, stored 1/d in ten steps: 0 = nearest (1/d=0.2) .. "
                    "9 = farthest (1/d=0.16666",
                    "99900999\n99000099\n90000009\n");
}

/* Lesson 01, one row of 10 columns:
 *   whole numbers: segment (0,3)-(9,3) then (2,7)-(5,7) in front: 3377773333
 *   otherwise: (0,0)-(9,90), y = 10 x. Nearest is the largest y, 90, as 0;
 *   farthest 0 as 9; step = floor(10 (y - 90) / (0 - 90)) = floor((90 - y) / 9):
 *   x = 0..9 gives 10->9, 80/9 = 8.9->8, 7.8->7, 6.7->6, 5.6->5, 4.4->4, 3.3->3,
 *   2.2->2, 1.1->1, 0. */
static void ybuffer_row_prints_y_itself_or_in_ten_steps_largest_nearest(void **state)
{
    (void)state;
    const char *dir = test_dir("tools_ascii_01");
    struct {
        const char *segments, *legend, *row;
    } cases[] = {
        {"0 3 9 3 255 0 0\n2 7 5 7 0 255 0\n",
         "y-buffer 10 columns, digit = y itself (all values are whole numbers 0-9); '.' = empty",
         "3377773333\n"},
        {"0 0 9 90 255 0 0\n",
         "y-buffer 10 columns, stored y in ten steps: 0 = nearest (y=90) .. 9 = farthest (y=0); "
         "'.' = empty",
         "9876543210\n"},
        {"3 1 5 1 255 0 0\n", "y-buffer 10 columns, digit = y itself", "...111....\n"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        const char *file = write_text_in(dir, "segments.txt", cases[k].segments);
        const char *args[] = {"--segments", file, "--out", path_join(dir, "row.png"), "--width",
                              "10", "--ascii", NULL};
        RunResult r = run_program("01_ybuffer", args);
        assert_int_equal(r.status, 0);
        char legend[256];
        const char *row = ascii_part(r.out, "y-buffer 10 columns, ", legend, sizeof legend);
        if (!row || strcmp(row, cases[k].row) != 0 ||
            strncmp(legend, cases[k].legend, strlen(cases[k].legend)) != 0)
            fail_msg("01_ybuffer --ascii on\n%sprinted:\n%s\nexpected \"%s\" then %s",
                     cases[k].segments, r.out, cases[k].legend, cases[k].row);
        run_result_free(&r);
    }
}

/* ---- ascii_print on its own ------------------------------------------------- */

static char *print_to_text(const float *values, int width, int height, const DepthRule *rule)
{
    char *text = NULL;
    size_t len = 0;
    FILE *mem = open_memstream(&text, &len);
    assert_non_null(mem);
    ascii_print(mem, values, width, height, rule);
    fclose(mem);
    return text;
}

static const DepthRule STORES_D = {"depth buffer", "d", "face", SMALLER_IS_NEARER};

/* Range 10 .. 20, one step = 1: 10 -> 0, 10.99 -> 0, 11 -> 1, 19.99 -> 9,
 * 20 (the farthest, step 10) -> 9; NAN is empty. */
static void steps_are_tenths_of_the_range_nearest_first(void **state)
{
    (void)state;
    const float v[8] = {10.0f, 10.99f, 11.0f, 15.5f, 19.99f, 20.0f, NAN, 12.0f};
    char *text = print_to_text(v, 4, 2, &STORES_D);
    assert_string_equal(text, "depth buffer 4x2, stored d in ten steps: 0 = nearest (d=10) .. "
                              "9 = farthest (d=20); '.' = empty\n"
                              "0015\n99.2\n");
    free(text);
}

static void larger_is_nearer_reverses_the_digits(void **state)
{
    (void)state;
    const DepthRule inverse = {"depth buffer", "1/d", "face", LARGER_IS_NEARER};
    const float v[3] = {0.5f, 0.25f, 0.375f}; /* 0.5 nearest: 0; 0.25 farthest: 9; middle: 5 */
    char *text = print_to_text(v, 3, 1, &inverse);
    assert_string_equal(text, "depth buffer 3 columns, stored 1/d in ten steps: 0 = nearest "
                              "(1/d=0.5) .. 9 = farthest (1/d=0.25); '.' = empty\n"
                              "095\n");
    free(text);
}

static void whole_digits_print_as_themselves_unless_one_is_not(void **state)
{
    (void)state;
    const float whole[4] = {0.0f, 9.0f, NAN, 3.0f};
    char *text = print_to_text(whole, 4, 1, &STORES_D);
    assert_string_equal(text, "depth buffer 4 columns, digit = d itself (all values are whole "
                              "numbers 0-9); '.' = empty\n09.3\n");
    free(text);
    const float ten[2] = {0.0f, 10.0f}; /* 10 is not one digit: steps, 0 -> 0, 10 -> 9 */
    text = print_to_text(ten, 2, 1, &STORES_D);
    assert_string_equal(text, "depth buffer 2 columns, stored d in ten steps: 0 = nearest (d=0) "
                              ".. 9 = farthest (d=10); '.' = empty\n09\n");
    free(text);
}

static void empty_buffer_prints_dots_and_says_nothing_was_drawn(void **state)
{
    (void)state;
    const float v[2] = {NAN, NAN};
    char *text = print_to_text(v, 1, 2, &STORES_D);
    assert_string_equal(text, "depth buffer 1x2, nothing drawn; '.' = empty\n.\n.\n");
    free(text);
}

static void larger_than_120x60_is_refused_with_the_size(void **state)
{
    (void)state;
    const char *args[] = {"--width", "121", "--height", "60", "--ascii", NULL};
    RunResult r = run_program("02_zbuffer", args);
    assert_int_equal(r.status, 2);
    assert_string_equal(r.err, "02_zbuffer: error: --ascii: the image is 121x60; --ascii prints "
                               "at most 120x60 (use --width and --height)\n");
    run_result_free(&r);
    const char *tall[] = {"--width", "120", "--height", "61", "--ascii", NULL};
    r = run_program("02_zbuffer", tall);
    assert_int_equal(r.status, 2);
    assert_non_null(strstr(r.err, "the image is 120x61"));
    run_result_free(&r);
    const char *row[] = {"--ascii", NULL}; /* lesson 01: 800 columns by default */
    r = run_program("01_ybuffer", row);
    assert_int_equal(r.status, 2);
    assert_string_equal(r.err, "01_ybuffer: error: --ascii: the row is 800 pixels wide; --ascii "
                               "prints at most 120 (use --width)\n");
    run_result_free(&r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(maps_print_as_the_zbuffer_text_draws_them_storing_d),
        cmocka_unit_test(text_maps_print_stored_inverse_d_nearest_as_0),
        cmocka_unit_test(ybuffer_row_prints_y_itself_or_in_ten_steps_largest_nearest),
        cmocka_unit_test(steps_are_tenths_of_the_range_nearest_first),
        cmocka_unit_test(larger_is_nearer_reverses_the_digits),
        cmocka_unit_test(whole_digits_print_as_themselves_unless_one_is_not),
        cmocka_unit_test(empty_buffer_prints_dots_and_says_nothing_was_drawn),
        cmocka_unit_test(larger_than_120x60_is_refused_with_the_size),
    };
    return cmocka_run_group_tests_name("tools: --ascii", tests, NULL, NULL);
}
