/* test_guard_band_precision.c: the guard-band clipper (guard_band.h) with
 * corners as far away as a double goes. Where an edge is cut, the new corner
 * must lie on the true edge, to a millionth of a pixel, however far the other
 * end is: with an end 1e30 pixels away, a cut point computed as
 * a * (1 - t) + b * t, with t rounded to 1, lands a million pixels off the
 * edge (the extreme-coordinate tests of every lesson then draw the wrong
 * pixels). Expected corners are worked out by hand in each test. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <float.h>
#include <math.h>

#include "guard_band.h"

#define W 40
#define H 30
#define TOLERANCE 1e-6 /* pixels */
#define BAND_RIGHT (W + (double)GUARD_BAND) /* 1048616 */
#define BAND_TOP (-(double)GUARD_BAND)      /* -1048576 */

static void expect_corner(const ScreenVertex *got, double x, double y, double d, int k)
{
    if (fabs(got->x - x) > TOLERANCE || fabs(got->y - y) > TOLERANCE ||
        fabs(got->d - d) > 1e-12)
        fail_msg("corner %d is (%.17g, %.17g, d %.17g), expected (%.17g, %.17g, d %.17g)", k,
                 got->x, got->y, got->d, x, y, d);
}

static void cut_next_to_a_corner_1e30_away_lies_on_the_edge(void **state)
{
    (void)state;
    /* a = (3.25, 4.75) and b = (35.5, 20.25) on the screen, f = (1e30, -1e30):
     * the edges b-f and f-a run at slope -1 (to 1 part in 1e29).
     *   right side x = 1048616 cuts b-f at y = 20.25 - (1048616 - 35.5) = -1048560.25
     *                        and f-a at y = 4.75 - (1048616 - 3.25) = -1048608,
     *   which is above the top side y = -1048576: that side cuts the right
     *   side's own edge at (1048616, -1048576) and f-a at
     *   x = 3.25 + (4.75 + 1048576) = 1048584.
     * So: a, b, (1048616, -1048560.25), (1048616, -1048576), (1048584, -1048576).
     * All corners at d = 2, so every new one is at d = 2 by either rule. */
    const ScreenVertex in[3] = {{3.25, 4.75, 2}, {35.5, 20.25, 2}, {1e30, -1e30, 2}};
    const DepthLinearity rules[2] = {LINEAR_D, LINEAR_INV_D};
    for (int r = 0; r < 2; r++) {
        ScreenVertex out[GUARD_BAND_MAX_OUT(3)];
        assert_int_equal(guard_band_clip(in, 3, W, H, rules[r], out), 5);
        expect_corner(&out[0], 3.25, 4.75, 2, 0);
        expect_corner(&out[1], 35.5, 20.25, 2, 1);
        expect_corner(&out[2], BAND_RIGHT, -1048560.25, 2, 2);
        expect_corner(&out[3], BAND_RIGHT, BAND_TOP, 2, 3);
        expect_corner(&out[4], 1048584.0, BAND_TOP, 2, 4);
    }
}

static void depth_of_a_cut_follows_the_rule(void **state)
{
    (void)state;
    /* From a = (0, 10, d 1) to f = (1e30, 10, d 3), cut at x = 1048616:
     * t = 1048616 / 1e30. d linear: 1 + 2 t; 1/d linear: 1 / (1 - t + t / 3).
     * Both are 1 to within 1e-23: the cut must not come out as 3, f's depth. */
    const ScreenVertex in[3] = {{0, 10, 1}, {1e30, 10, 3}, {0, 20, 1}};
    ScreenVertex out[GUARD_BAND_MAX_OUT(3)];
    assert_int_equal(guard_band_clip(in, 3, W, H, LINEAR_D, out), 4);
    expect_corner(&out[1], BAND_RIGHT, 10, 1, 1);
    assert_int_equal(guard_band_clip(in, 3, W, H, LINEAR_INV_D, out), 4);
    expect_corner(&out[1], BAND_RIGHT, 10, 1, 1);
}

static void collinear_far_triangle_stays_on_its_line(void **state)
{
    (void)state;
    /* (1.5, 1.5), (1e30, 1e30), (20.5, 20.5) all lie on y = x: every corner of
     * what is left must too, or a triangle of no area gains some and covers
     * pixel centres on the line. */
    const ScreenVertex in[3] = {{1.5, 1.5, 1}, {1e30, 1e30, 1}, {20.5, 20.5, 1}};
    ScreenVertex out[GUARD_BAND_MAX_OUT(3)];
    int n = guard_band_clip(in, 3, W, H, LINEAR_D, out);
    assert_true(n >= 3);
    for (int k = 0; k < n; k++)
        if (fabs(out[k].y - out[k].x) > TOLERANCE)
            fail_msg("corner %d (%.17g, %.17g) is off the line y = x", k, out[k].x, out[k].y);
}

static void corners_near_the_largest_double_give_finite_corners(void **state)
{
    (void)state;
    /* Two corners at +-DBL_MAX, one on the screen: differences of coordinates
     * would overflow to infinity, and an infinity would become NaN at the next
     * side. What is left must be finite and inside the band. */
    const ScreenVertex tris[][3] = {
        {{-DBL_MAX, DBL_MAX, 1}, {DBL_MAX, DBL_MAX, 1}, {5, 5, 1}},
        {{-DBL_MAX, -DBL_MAX, 1}, {DBL_MAX, DBL_MAX, 2}, {5, 25, 3}},
        {{DBL_MAX, -DBL_MAX, 1}, {-DBL_MAX, 1e308, 2}, {20, 15, 3}},
        /* found by fuzz_02_zbuffer: cut at the left side from (1e300, 1e300)
         * towards y = -DBL_MAX, t rounds to 1 and a + (b - a) t overflowed to
         * -infinity, which the right side then turned into NaN */
        {{-2147483649.0, -DBL_MAX, 1}, {-2.1e-243, 1e300, 2}, {1e300, 1e300, 3}},
    };
    const DepthLinearity rules[2] = {LINEAR_D, LINEAR_INV_D};
    for (int k = 0; k < (int)(sizeof tris / sizeof tris[0]) * 2; k++) {
        ScreenVertex out[GUARD_BAND_MAX_OUT(3)];
        int n = guard_band_clip(tris[k / 2], 3, W, H, rules[k % 2], out);
        assert_true(n >= 3);
        for (int j = 0; j < n; j++) {
            if (!isfinite(out[j].x) || !isfinite(out[j].y) || !isfinite(out[j].d))
                fail_msg("triangle %d: corner %d is (%g, %g, d %g)", k / 2, j, out[j].x,
                         out[j].y, out[j].d);
            assert_true(guard_band_contains(&out[j], 1, W, H));
        }
    }
}

static void folded_polygon_is_dropped_within_its_buffer(void **state)
{
    (void)state;
    /* Found by fuzz_03_perspective_z: one corner 1e88 and one 1e300 pixels
     * away, so that the edge between them, both ends beyond 2^53 pixels, cannot
     * be cut to a pixel. Rounding folds what is left of the triangle, and the
     * bottom side then met it more than twice: the cut polygon grew past the
     * GUARD_BAND_MAX_OUT(3) corners the caller has room for. It must not be
     * written past that room, and there is no right picture of it: 0. */
    const ScreenVertex in[3] = {{-88.359375, -2097152, 1},
                                {-1e30, 3.6902938333690378e+88, 1},
                                {1e300, 1e300, 1}};
    struct {
        ScreenVertex out[GUARD_BAND_MAX_OUT(3)];
        ScreenVertex after[8]; /* must stay as set here */
    } buf;
    for (int k = 0; k < 8; k++)
        buf.after[k] = (ScreenVertex){12345, 12345, 12345};
    assert_int_equal(guard_band_clip(in, 3, 4, 4096, LINEAR_D, buf.out), 0);
    for (int k = 0; k < 8; k++)
        assert_true(buf.after[k].x == 12345 && buf.after[k].y == 12345 &&
                    buf.after[k].d == 12345);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(cut_next_to_a_corner_1e30_away_lies_on_the_edge),
        cmocka_unit_test(depth_of_a_cut_follows_the_rule),
        cmocka_unit_test(collinear_far_triangle_stays_on_its_line),
        cmocka_unit_test(corners_near_the_largest_double_give_finite_corners),
        cmocka_unit_test(folded_polygon_is_dropped_within_its_buffer),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
