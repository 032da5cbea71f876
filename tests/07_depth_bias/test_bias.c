/* test_bias.c: lesson 07's depth bias worked on paper. m, the steepest slope
 * of z_w on the screen, for a face facing the camera (0) and for grazing
 * faces, from z_w = f/(f-n) (1 - n/d) at the corners (CONVENTIONS); r, the
 * smallest step of each format, 1/(2^bits - 1) or 2^(e - 23) with e the
 * exponent of the face's largest z_w; o with and without a clamp; and the
 * depth test with o: the decal drawn second wins the pixel it ties without. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "depth_bias.h"
#include "scanline.h"
#include "state.h"
#include "test_support.h"

#define NEAR 0.1
#define FAR 1000.0
/* Standard mapping, near 0.1, far 1000: z_w = A + B/d with A = f/(f-n) and
 * B = -n f/(f-n) (CONVENTIONS.md), written out here. */
#define A (1000.0 / 999.9)
#define B (-100.0 / 999.9)

static void expect_close(double expected, double actual, const char *what)
{
    observe_near(actual, expected, 1e-9 * fabs(expected) + 1e-18);
    if (!(fabs(actual - expected) <= 1e-9 * fabs(expected) + 1e-18))
        fail_msg("%s: expected %.12g, got %.12g", what, expected, actual);
}

/* m of a triangle: lesson 06's plane of z_w, set up from its corners in
 * float32, then depth_slope. */
static double m_of(const DepthSetup *s, ScreenVertex a, ScreenVertex b, ScreenVertex c)
{
    DepthPlane p = depth_plane(s, (ScreenVertex[3]){a, b, c});
    return depth_slope(&p);
}

/* The plane is worked out in float32: a slope on paper holds to 1e-4 of itself. */
static void expect_float_close(double expected, double actual, const char *what)
{
    observe_near(actual, expected, 1e-4 * fabs(expected));
    if (!(fabs(actual - expected) <= 1e-4 * fabs(expected)))
        fail_msg("%s: expected %.9g, got %.9g", what, expected, actual);
}

/* A face at one depth, d = 10 everywhere: z_w does not change across it. */
static void facing_face_has_no_slope(void **state)
{
    (void)state;
    DepthSetup s = depth_setup(UNORM24, STANDARD, NEAR, FAR);
    ScreenVertex a = {10, 10, 10}, b = {90, 10, 10}, c = {90, 70, 10};
    expect_close(0, m_of(&s, a, b, c), "m of a face facing the camera");
}

/* Grazing faces: d goes from 2 to 4 across them. Corners (0,0) d 2, (100,0)
 * d 4, (0,100) d 2: along x z_w changes by B (1/4 - 1/2) over 100 pixels,
 * along y not at all: m = |B| / 400. Corners (0,0) d 2, (100,0) d 4, (0,50)
 * d 4: |dz/dx| = |B| / 400, |dz/dy| = |B| / 4 / 50 = |B| / 200; m is the
 * larger, not sqrt of the sum of squares. */
static void grazing_face_slope_is_the_larger_of_the_two(void **state)
{
    (void)state;
    DepthSetup s = depth_setup(UNORM24, STANDARD, NEAR, FAR);
    ScreenVertex o = {0, 0, 2}, x4 = {100, 0, 4};
    expect_float_close(-B / 400, m_of(&s, o, x4, (ScreenVertex){0, 100, 2}),
                       "m, z_w changing along x");
    ScreenVertex y4 = {0, 50, 4};
    expect_float_close(-B / 200, m_of(&s, o, x4, y4), "m, the larger slope (along y)");
    /* The same plane as a quad's two triangles: 1/d is affine on the screen,
     * 1/2 - x/400 - y/200, so at (50, 25) 1/d = 1/2 - 1/8 - 1/8 = 1/4, d = 4. */
    ScreenVertex mid = {50, 25, 4};
    expect_float_close(-B / 200, m_of(&s, o, x4, mid), "m of a quad's first triangle");
    expect_float_close(-B / 200, m_of(&s, o, mid, y4), "m of its second");
    /* The format does not change m: it is a slope of z_w itself. */
    s = depth_setup(FLOAT32, STANDARD, NEAR, FAR);
    expect_float_close(-B / 200, m_of(&s, o, x4, y4), "m at float32");
}

/* r: unorm, one code whatever the face; float32, one step of the float at
 * the face's largest z_w, 2^(e - 23) for z_w = 1.f x 2^e. */
static void resolvable_difference_of_each_format(void **state)
{
    (void)state;
    ScreenVertex facing[3] = {{0, 0, 10}, {50, 0, 10}, {0, 50, 10}};
    ScreenVertex grazing[3] = {{0, 0, 2}, {100, 0, 4}, {0, 100, 2}};
    DepthSetup s = depth_setup(UNORM16, STANDARD, NEAR, FAR);
    expect_close(1 / 65535.0, resolvable_difference(&s, facing, 3), "unorm16, facing");
    expect_close(1 / 65535.0, resolvable_difference(&s, grazing, 3), "unorm16, grazing");
    s = depth_setup(UNORM24, STANDARD, NEAR, FAR);
    expect_close(1 / 16777215.0, resolvable_difference(&s, facing, 3), "unorm24, facing");
    expect_close(1 / 16777215.0, resolvable_difference(&s, grazing, 3), "unorm24, grazing");
    /* Standard: z_w(10) = A (1 - 0.01) = 0.990..., z_w(4) = A 0.975 = 0.975...:
     * both in [1/2, 1), e = -1, r = 2^-24. */
    s = depth_setup(FLOAT32, STANDARD, NEAR, FAR);
    expect_close(ldexp(1, -24), resolvable_difference(&s, facing, 3), "float32, facing");
    expect_close(ldexp(1, -24), resolvable_difference(&s, grazing, 3), "float32, grazing");
    /* Reversed, far at infinity: z_w = n/d. At d = 10, 0.01, in [2^-7, 2^-6):
     * e = -7, r = 2^-30. Corners at d = 10 and d = 1: the largest z_w is 0.1,
     * in [2^-4, 2^-3): e = -4, r = 2^-27. */
    s = depth_setup(FLOAT32, REVERSED, NEAR, INFINITY);
    expect_close(ldexp(1, -30), resolvable_difference(&s, facing, 3), "float32 n/d, d = 10");
    ScreenVertex mixed[3] = {{0, 0, 10}, {100, 0, 1}, {0, 100, 10}};
    expect_close(ldexp(1, -27), resolvable_difference(&s, mixed, 3), "float32 n/d, d 1 to 10");
}

/* o = m FACTOR + r UNITS; a positive clamp is a ceiling, a negative one a floor. */
static void offset_adds_both_terms_then_clamps(void **state)
{
    (void)state;
    double m = 1e-4, r = ldexp(1, -24);
    DepthBias bias = {.factor = -1, .units = -2};
    expect_close(-1e-4 - 2 * r, polygon_offset(&bias, m, r), "o = -m - 2r");
    bias.clamp = -1e-5;
    expect_close(-1e-5, polygon_offset(&bias, m, r), "o floored at -1e-5");
    bias.clamp = 1e-5;
    expect_close(-1e-4 - 2 * r, polygon_offset(&bias, m, r), "a ceiling leaves a negative o");
    bias = (DepthBias){.factor = 3, .units = 0, .clamp = 1e-4};
    expect_close(1e-4, polygon_offset(&bias, m, r), "o = 3m capped at 1e-4");
}

static Target one_pixel(LessonState *s)
{
    Target t;
    Error err;
    assert_true(target_init(&t, 1, 1, &err));
    clear_depth(&t, s);
    return t;
}

/* A base and a decal at the same 1/d tie (the first keeps the pixel); with
 * the decal's o one code nearer, the decal wins. */
static void offset_moves_the_decal_in_front_of_its_base(void **state)
{
    (void)state;
    LessonState s = {.depth = depth_setup(UNORM24, STANDARD, NEAR, FAR)};
    float inv_d = (float)(1.0 / 7.0);
    Target t = one_pixel(&s);
    Primitive base = {.target = &t, .state = &s, .face = 0,
                      .plane = depth_plane(&s.depth, (ScreenVertex[3]){{0, 0, 7}, {4, 0, 7}, {0, 4, 7}})};
    Primitive decal = base;
    decal.face = 1;
    assert_true(depth_test(&base, 0, 0, inv_d));
    assert_false(depth_test(&decal, 0, 0, inv_d));
    expect_count(0, t.face[0], "without bias: the base, drawn first");
    decal.offset = -1 / 16777215.0f;
    assert_true(depth_test(&decal, 0, 0, inv_d));
    expect_count(1, t.face[0], "with o = -1 code: the decal");
    target_free(&t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(facing_face_has_no_slope),
        cmocka_unit_test(grazing_face_slope_is_the_larger_of_the_two),
        cmocka_unit_test(resolvable_difference_of_each_format),
        cmocka_unit_test(offset_adds_both_terms_then_clamps),
        cmocka_unit_test(offset_moves_the_decal_in_front_of_its_base),
    };
    return cmocka_run_group_tests_name("07_depth_bias bias", tests, NULL, NULL);
}
