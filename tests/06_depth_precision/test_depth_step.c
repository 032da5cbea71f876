/* test_depth_step.c: lesson 06's depth formats and mappings, worked out
 * independently here: the mappings from their formulas (CONVENTIONS), the
 * depth step by brute force over the values the format can hold (integer
 * codes, nextafterf), the log mapping's fragments, the issue's figures at near 0.1, far 1000, d = 100
 * worked out on paper, and the depth test's direction, clear value and ties. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "depth_format.h"
#include "scanline.h"
#include "state.h"
#include "test_support.h"

#define NEAR 0.1
#define FAR 1000.0

/* z_w of d, straight from the formulas of CONVENTIONS.md. */
static double z_of(DepthMapping m, double n, double f, double d)
{
    if (m == STANDARD)
        return f / (f - n) * (1 - n / d);
    if (m == LOGARITHMIC)
        return log(d / n) / log(f / n);
    return isinf(f) ? n / d : n / (f - n) * (f / d - 1);
}

/* ... and d of z_w, the same formulas solved for d. */
static double d_of(DepthMapping m, double n, double f, double z)
{
    if (m == STANDARD)
        return n / (1 - z * (f - n) / f);
    if (m == LOGARITHMIC)
        return n * pow(f / n, z);
    return isinf(f) ? n / z : n * f / (z * (f - n) + n);
}

/* The step at d by brute force: the value the format holds for z_w(d), the
 * next one it can hold towards the far plane, and how far apart in d they are. */
static double brute_step(DepthFormat fmt, DepthMapping m, double n, double f, double d)
{
    double z = z_of(m, n, f, d), toward = m == REVERSED ? -1 : 1, z0, z1;
    if (fmt == FLOAT32) {
        float zf = (float)z;
        z0 = zf;
        z1 = nextafterf(zf, (float)(2 * toward));
    } else {
        double max = fmt == UNORM16 ? 65535.0 : 16777215.0, code = floor(z * max + 0.5);
        z0 = code / max;
        z1 = (code + toward) / max;
    }
    return fabs(d_of(m, n, f, z1) - d_of(m, n, f, z0));
}

static void step_matches_brute_force_for_every_format_and_mapping(void **state)
{
    (void)state;
    const double fars[] = {FAR, 100.0, INFINITY};
    const double ds[] = {0.13, 0.5, 1, 2.7, 10, 33, 100, 310, 950};
    int checked = 0;
    for (int fi = 0; fi < 3; fi++)
        for (int fmt = 0; fmt < 3; fmt++)
            for (int m = 0; m < 3; m++) {
                double f = fars[fi];
                if (isinf(f) && m != REVERSED)
                    continue;
                DepthSetup s = depth_setup((DepthFormat)fmt, (DepthMapping)m, NEAR, f);
                for (size_t k = 0; k < sizeof ds / sizeof ds[0]; k++) {
                    double d = ds[k];
                    if (d >= f)
                        continue;
                    double want = brute_step((DepthFormat)fmt, (DepthMapping)m, NEAR, f, d);
                    double got = depth_step(&s, d);
                    /* One step of the format, measured from the value held
                     * (within half a step of z_w(d)) rather than from z_w(d)
                     * as a slope: they differ by about step / d, relatively. */
                    double tolerance = want * (3 * want / d + 1e-6);
                    if (fabs(got - want) > tolerance)
                        fail_msg("format %d mapping %d far %g d %g: depth_step %.9g, brute "
                                 "force %.9g", fmt, m, f, d, got, want);
                    assert_true(fabs(window_depth(&s, d) - z_of((DepthMapping)m, NEAR, f, d)) <
                                1e-12);
                    checked++;
                }
            }
    expect_count(162, checked, "steps checked");
}

/* The issue's figures, on paper: |dz_w/dd| = f n / ((f - n) d^2) = 0.1 / 0.9999
 * * 1e-4 at d = 100 for both mappings; z_w(100) is 0.9991 (standard, a float32
 * step of 2^-24 in [1/2, 1)) and 0.00090009 (reversed, in [2^-11, 2^-10): a
 * step of 2^-34). unorm16 steps by 1/65535, unorm24 by 1/16777215. */
static void issue_figures_at_near_0_1_far_1000_d_100(void **state)
{
    (void)state;
    const struct {
        DepthFormat fmt;
        DepthMapping m;
        double metres;
    } FIG[] = {
        {UNORM16, STANDARD, 1.5257496},   {UNORM16, REVERSED, 1.5257496},
        {UNORM24, STANDARD, 0.0059598688}, {UNORM24, REVERSED, 0.0059598688},
        {FLOAT32, STANDARD, 0.0059598684}, {FLOAT32, REVERSED, 5.8201840e-6},
        /* log: |dz_w/dd| = 1 / (d log(f/n)), z_w(100) = 3/4 (a float32 step of 2^-24). */
        {UNORM16, LOGARITHMIC, 0.014054079}, {UNORM24, LOGARITHMIC, 5.4897910e-5},
        {FLOAT32, LOGARITHMIC, 5.4897907e-5},
    };
    for (size_t k = 0; k < sizeof FIG / sizeof FIG[0]; k++) {
        DepthSetup s = depth_setup(FIG[k].fmt, FIG[k].m, NEAR, FAR);
        double got = depth_step(&s, 100);
        observe_near(got, FIG[k].metres, 1e-6 * FIG[k].metres);
        if (fabs(got - FIG[k].metres) > 1e-6 * FIG[k].metres)
            fail_msg("format %d mapping %d: step at d = 100 is %.9g m, the page says %.9g m",
                     FIG[k].fmt, FIG[k].m, got, FIG[k].metres);
    }
}

/* Round to nearest, codes clamped to [0, 2^bits - 1]; float32 as it is. */
static void encode_rounds_to_the_nearest_code(void **state)
{
    (void)state;
    assert_true(encode_depth(UNORM16, 0.0f) == 0.0f);
    assert_true(encode_depth(UNORM16, 1.0f) == 65535.0f);
    assert_true(encode_depth(UNORM24, 1.0f) == 16777215.0f);
    assert_true(encode_depth(UNORM16, 0.5f) == 32768.0f);           /* 32767.5 rounds up */
    assert_true(encode_depth(UNORM16, 0.4999f) == 32761.0f);        /* 32760.95 */
    assert_true(encode_depth(UNORM16, 1.0f / 65535 * 0.49f) == 0.0f); /* under half a code */
    assert_true(encode_depth(UNORM16, 1.5f) == 65535.0f);           /* clamped */
    assert_true(encode_depth(UNORM24, -0.25f) == 0.0f);
    assert_true(encode_depth(FLOAT32, 0.3f) == 0.3f);
}

static Target one_pixel(void)
{
    Target t;
    Error err;
    assert_true(target_init(&t, 1, 1, &err));
    return t;
}

/* A fragment of face at view depth d at pixel (0, 0): a triangle facing the
 * camera at d, its plane set up (as draw_triangles sets it up before the
 * scanline), tested as the scanline hands it to depth_test, with its 1/d. */
static bool test_at(Target *t, LessonState *s, int face, double d)
{
    ScreenVertex v[3] = {{0, 0, d}, {4, 0, d}, {0, 4, d}};
    Primitive p = {.target = t, .state = s, .face = face, .plane = depth_plane(&s->depth, v)};
    return depth_test(&p, 0, 0, (float)(1.0 / d));
}

/* A tilted triangle, z_w = n/d (reversed, far = inf, n = 0.1) at its corners
 * (0, 0, d = 1), (8, 0, d = 2), (0, 8, d = 4): z_w = 0.1, 0.05, 0.025, so
 * gx = -0.05 / 8 = -0.00625, gy = -0.075 / 8 = -0.009375 per pixel, and at the
 * centre of pixel (0, 0), half a pixel right and down of corner 0:
 * a0 = 0.1 + 0.5 gx + 0.5 gy = 0.0921875. */
static void a_triangle_plane_from_its_corners(void **state)
{
    (void)state;
    DepthSetup s = depth_setup(FLOAT32, REVERSED, NEAR, INFINITY);
    ScreenVertex v[3] = {{0, 0, 1}, {8, 0, 2}, {0, 8, 4}};
    DepthPlane p = depth_plane(&s, v);
    assert_true(fabs(p.gx - -0.00625) < 1e-8);   /* dz_w/dx */
    assert_true(fabs(p.gy - -0.009375) < 1e-8);  /* dz_w/dy */
    assert_true(fabs(p.a0 - 0.0921875) < 1e-8);  /* z_w at the centre of pixel (0, 0) */
}

/* Log, near 0.1, far 1000: z_w = log(d / 0.1) / log(1e4), so d = 1 gives 1/4
 * and d = 10 gives 1/2. On the tilted triangle above, n/d is a plane (the
 * same as reversed with far = inf): 0.0921875 at the centre of pixel (0, 0),
 * so d = 0.1 / 0.0921875 there and z_w = log(1 / 0.0921875) / log(1e4) =
 * 0.25883. The log of z_w's corners interpolated on the screen would give
 * 0.26411 instead: log depth is written per fragment, not stepped. */
static void log_writes_the_log_of_each_fragments_d(void **state)
{
    (void)state;
    LessonState s = {depth_setup(FLOAT32, LOGARITHMIC, NEAR, FAR)};
    Target t = one_pixel();
    clear_depth(&t, &s);
    assert_true(t.depth[0] == 1.0f); /* the far plane */
    assert_true(test_at(&t, &s, 0, 10));
    observe_near(t.depth[0], 0.5, 1e-6);
    assert_true(fabs(t.depth[0] - 0.5) < 1e-6);
    assert_true(test_at(&t, &s, 1, 1)); /* nearer wins: smaller z_w */
    assert_true(fabs(t.depth[0] - 0.25) < 1e-6);
    assert_false(test_at(&t, &s, 2, 3));
    expect_count(1, t.face[0], "the nearest face");
    ScreenVertex v[3] = {{0, 0, 1}, {8, 0, 2}, {0, 8, 4}};
    Primitive p = {.target = &t, .state = &s, .face = 3, .plane = depth_plane(&s.depth, v)};
    double want = log(1 / 0.0921875) / log(1e4);
    observe_near(fragment_depth(&p, 0, 0), want, 1e-6);
    if (fabs(fragment_depth(&p, 0, 0) - want) > 1e-6)
        fail_msg("log, tilted triangle, pixel (0, 0): z_w %.7f, want %.7f (the log of the "
                 "fragment's own d)", fragment_depth(&p, 0, 0), want);
    target_free(&t);
}

static void standard_clears_to_one_and_keeps_the_smaller(void **state)
{
    (void)state;
    LessonState s = {depth_setup(UNORM24, STANDARD, NEAR, FAR)};
    Target t = one_pixel();
    clear_depth(&t, &s);
    assert_true(t.depth[0] == 16777215.0f);
    assert_true(test_at(&t, &s, 0, 500));  /* anything before far wins */
    assert_true(test_at(&t, &s, 1, 2));    /* nearer wins */
    assert_false(test_at(&t, &s, 2, 3));   /* farther loses */
    expect_count(1, t.face[0], "the nearest face");
    /* z_w(2) = 1000/999.9 (1 - 0.05) = 0.95009501, times 2^24 - 1: 15939948.2 */
    assert_true(t.depth[0] == 15939948.0f);
    target_free(&t);
}

static void reversed_clears_to_zero_and_keeps_the_larger(void **state)
{
    (void)state;
    LessonState s = {depth_setup(FLOAT32, REVERSED, NEAR, INFINITY)};
    Target t = one_pixel();
    clear_depth(&t, &s);
    assert_true(t.depth[0] == 0.0f);
    assert_true(test_at(&t, &s, 0, 1e6)); /* far = inf: a million away still wins */
    assert_true(test_at(&t, &s, 1, 4));
    assert_false(test_at(&t, &s, 2, 8));
    expect_count(1, t.face[0], "the nearest face");
    assert_true(t.depth[0] == 0.025f); /* z_w = n/d, 0.1 / 4 */
    target_free(&t);
}

/* Two fragments that store the same code: the first one drawn keeps the pixel. */
static void a_tie_keeps_the_first_fragment(void **state)
{
    (void)state;
    LessonState s = {depth_setup(UNORM16, STANDARD, NEAR, FAR)};
    Target t = one_pixel();
    clear_depth(&t, &s);
    /* At d = 100 one unorm16 code spans about 1.5 m: 100 and 100.05 tie. */
    assert_true(test_at(&t, &s, 7, 100.05));
    assert_false(test_at(&t, &s, 8, 100));
    expect_count(7, t.face[0], "the first face drawn");
    target_free(&t);
    s.depth = depth_setup(FLOAT32, REVERSED, NEAR, FAR); /* there they are told apart */
    t = one_pixel();
    clear_depth(&t, &s);
    assert_true(test_at(&t, &s, 7, 100.05));
    assert_true(test_at(&t, &s, 8, 100));
    expect_count(8, t.face[0], "the nearer face");
    target_free(&t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(step_matches_brute_force_for_every_format_and_mapping),
        cmocka_unit_test(issue_figures_at_near_0_1_far_1000_d_100),
        cmocka_unit_test(encode_rounds_to_the_nearest_code),
        cmocka_unit_test(a_triangle_plane_from_its_corners),
        cmocka_unit_test(standard_clears_to_one_and_keeps_the_smaller),
        cmocka_unit_test(reversed_clears_to_zero_and_keeps_the_larger),
        cmocka_unit_test(a_tie_keeps_the_first_fragment),
        cmocka_unit_test(log_writes_the_log_of_each_fragments_d),
    };
    return cmocka_run_group_tests_name("06_depth_precision depth step", tests, NULL, NULL);
}
