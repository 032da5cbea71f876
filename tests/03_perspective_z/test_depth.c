/* test_depth.c: what lesson 03 teaches, checked in-process: 1/d is blended
 * with the barycentric weights and inverted (the worked example of a z-buffer
 * chapter of a Lua rasterizer tutorial, chosen pixels, the true depth of
 * triangles3's surfaces), the naive rule is still lesson 02's, the guard band
 * follows each rule, and --bug negated-w lets the farthest surface win. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include "bugs.h"
#include "raster.h"
#include "naive.h"
#include "harness/render.h"
#include "test_support.h"

static Target new_target(int width, int height, const Rasterizer *rz)
{
    Target t;
    Error err;
    if (!render_target_init(&t, rz, width, height, &err))
        fail_msg("target_init: %s", err.msg);
    return t;
}

static void draw_screen_triangle(Target *t, const Rasterizer *rz, ScreenVertex a,
                                 ScreenVertex b, ScreenVertex c, int face)
{
    ScreenVertex v[3] = {a, b, c};
    ScreenFace f = screen_triangle(v, face);
    DrawContext ctx = {0.1, 1000, t->width, t->height};
    rz->draw_face(t, NULL, &f, &ctx);
}

static void expect_relative(double got, double want, double tolerance, const char *what)
{
    observe_near(got, want, tolerance * fabs(want));
    if (!(fabs(got - want) <= tolerance * fabs(want)))
        fail_msg("%s: got %.9g, expected %.9g (relative error %.2g, allowed %.1g)", what, got,
                 want, fabs(got - want) / fabs(want), tolerance);
}

/* ---- The rule itself ----------------------------------------------------------- */

/* The worked example of a z-buffer chapter of a Lua rasterizer tutorial:
 * corners at depths 2, 3 and 4, weights 0.5, 0.3 and 0.2. Blending 1/d:
 * 0.5/2 + 0.3/3 + 0.2/4 = 0.25 + 0.1 + 0.05 = 0.4, so d = 1/0.4 = 2.5.
 * Blending d itself: 1 + 0.9 + 0.8 = 2.7, farther than the surface really is
 * there. (interpolate_depth takes the corners' 1/d, as
 * draw_triangle works them out once per triangle.) */
static void worked_example_gives_2_5_and_naive_gives_2_7(void **state)
{
    (void)state;
    Barycentric w = {0.5, 0.3, 0.2};
    double right = interpolate_depth(w, 1.0 / 2, 1.0 / 3, 1.0 / 4);
    double naive = interpolate_depth_naive(w, 2, 3, 4);
    observe_near(right, 2.5, 1e-12);
    observe_near(naive, 2.7, 1e-12);
    if (fabs(right - 2.5) > 1e-12)
        fail_msg("interpolate_depth gave %.17g, the worked example says 2.5", right);
    if (fabs(naive - 2.7) > 1e-12)
        fail_msg("interpolate_depth_naive gave %.17g, the weighted average is 2.7", naive);
}

/* At a corner the weights are (1, 0, 0): both rules give that corner's depth. */
static void both_rules_give_the_corner_depth_at_a_corner(void **state)
{
    (void)state;
    Barycentric at_corner1 = {0, 1, 0};
    assert_true(interpolate_depth(at_corner1, 1.0 / 2, 1.0 / 7, 1.0 / 4) == 7);
    assert_true(interpolate_depth_naive(at_corner1, 2, 7, 4) == 7);
}

/* Corners (0, 0, d 1), (64, 0, d 2), (0, 64, d 4). At a pixel centre
 * (px, py) = (x + 0.5, y + 0.5) the weights of the last two corners are px/64
 * and py/64, so
 *     1/d = (1 - px/64 - py/64) / 1 + (px/64) / 2 + (py/64) / 4
 *         = 1 - px/128 - 3 py/256
 * and the naive d = 1 + px/64 + 3 py/64. For pixel (15, 31): 1/d =
 * 1 - 15.5/128 - 94.5/256 = 0.509765625, d = 1.96168...; naive 2.71875. */
static void inverse_depth_is_linear_at_chosen_pixels(void **state)
{
    (void)state;
    const int pixels[5][2] = {{15, 31}, {40, 10}, {0, 0}, {62, 0}, {3, 57}};
    ScreenVertex a = {0, 0, 1}, b = {64, 0, 2}, c = {0, 64, 4};
    Target right = new_target(64, 64, &ZBUFFER), naive = new_target(64, 64, &ZBUFFER_NAIVE);
    draw_screen_triangle(&right, &ZBUFFER, a, b, c, 0);
    draw_screen_triangle(&naive, &ZBUFFER_NAIVE, a, b, c, 0);
    for (int k = 0; k < 5; k++) {
        int x = pixels[k][0], y = pixels[k][1];
        double px = x + 0.5, py = y + 0.5;
        char what[64];
        snprintf(what, sizeof what, "perspective depth at pixel (%d,%d)", x, y);
        expect_relative(target_depth_at(&right, x, y), 1 / (1 - px / 128 - 3 * py / 256), 1e-6,
                        what);
        snprintf(what, sizeof what, "naive depth at pixel (%d,%d)", x, y);
        expect_relative(target_depth_at(&naive, x, y), 1 + px / 64 + 3 * py / 64, 1e-6, what);
    }
    /* The two rules agree at the corners and nowhere inside: the naive depth
     * is always the larger, since the average of d exceeds 1 / (average of 1/d). */
    assert_true(target_depth_at(&naive, 15, 31) - target_depth_at(&right, 15, 31) > 0.7);
    target_free(&right);
    target_free(&naive);
}

/* ---- The true depth of a surface ------------------------------------------------- */

/* The camera of triangles3: eye (0, 0, 10) looking down -Z, up +Y, fovy 45,
 * 200 x 150. View space is world space moved by -10 along z. The centre of
 * pixel (x, y) lies on the view ray through
 *     r = (x_ndc * aspect * tan(22.5 deg), y_ndc * tan(22.5 deg), -1),
 *     x_ndc = 2 (x + 0.5) / 200 - 1,   y_ndc = 1 - 2 (y + 0.5) / 150,
 * and the point of that ray at view depth d is d * r. It meets the plane
 * through the view-space corners a, b, c (normal n = (b - a) x (c - a)) where
 * n . (d r - a) = 0, that is at d = (n . a) / (n . r). */
static double ray_plane_depth(int x, int y, Vec3 a, Vec3 b, Vec3 c)
{
    const Vec3 eye = {0, 0, 10};
    double t = tan(22.5 * PI / 180), aspect = 200.0 / 150.0;
    double x_ndc = 2 * (x + 0.5) / 200 - 1, y_ndc = 1 - 2 * (y + 0.5) / 150;
    Vec3 r = {x_ndc * aspect * t, y_ndc * t, -1};
    a = vec3_sub(a, eye), b = vec3_sub(b, eye), c = vec3_sub(c, eye);
    Vec3 n = vec3_cross(vec3_sub(b, a), vec3_sub(c, a));
    return vec3_dot(n, a) / vec3_dot(n, r);
}

/* One pixel in each overlap of triangles3 (chosen in lesson 02's tests), the
 * face in front there and its corners, as scene.c builds them. */
typedef struct {
    int x, y;
    int32_t front;
    Vec3 a, b, c;
} Overlap;

static const Overlap OVERLAPS[3] = {
    {70, 90, 0, {-3, -2, 1}, {4, -1, -1}, {-3, 0, 1}},      /* red over blue */
    {100, 40, 2, {0, 3.5, 1}, {-3, -3, -1}, {1.5, 2.5, 1}}, /* blue over green */
    {125, 90, 1, {3, -1.5, 1}, {-1, 4, -1}, {1.5, -2.5, 1}}, /* green over red */
};

/* The depth kept at each overlap is the true depth of the front surface there,
 * where the pixel's ray meets its plane: 9.419, 9.398, 9.442, where lesson 02
 * kept 9.489, 9.466, 9.515. */
static void triangles3_depth_is_where_the_ray_meets_the_plane(void **state)
{
    (void)state;
    Options opt = {0};
    Error err;
    Render r;
    opt.width = 200;
    opt.height = 150;
    opt.scene = "triangles3";
    if (render_load(&r, &opt, &err) != EXIT_OK)
        fail_msg("render_load: %s", err.msg);
    Target t = new_target(200, 150, &ZBUFFER);
    assert_true(render_faces(&r, &t, &ZBUFFER, NULL, 0, NULL, NULL, &err));
    for (int k = 0; k < 3; k++) {
        const Overlap *o = &OVERLAPS[k];
        observe_value("face", target_face_at(&t, o->x, o->y));
        if (target_face_at(&t, o->x, o->y) != o->front)
            fail_msg("pixel (%d,%d): face %d should be in front, the z-buffer shows face %d",
                     o->x, o->y, o->front, target_face_at(&t, o->x, o->y));
        char what[64];
        snprintf(what, sizeof what, "depth at pixel (%d,%d)", o->x, o->y);
        expect_relative(target_depth_at(&t, o->x, o->y),
                        ray_plane_depth(o->x, o->y, o->a, o->b, o->c), 1e-5, what);
    }
    target_free(&t);
    render_free(&r);
}

/* ---- The guard band follows the rule ---------------------------------------------- */

/* A triangle millions of pixels across, around a 32 x 24 screen: draw_face
 * cuts it at the guard band (2^20 pixels out) before drawing, and the new
 * corners must get their depth by the same rule as the pixels, or the depth
 * on the screen comes out wrong. The expected depth is the rule applied to
 * the whole triangle, with weights from areas in doubles:
 *     w_a = area(p, b, c) / area(a, b, c), ...   (corners are whole pixels) */
static double area2(double ax, double ay, double bx, double by, double px, double py)
{
    return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

static void huge_triangle_keeps_each_rules_depth_through_the_guard_band(void **state)
{
    (void)state;
    ScreenVertex a = {-3e6, -2e6, 2}, b = {4e6, -1e6, 40}, c = {-1e6, 5e6, 10};
    double whole = area2(a.x, a.y, b.x, b.y, c.x, c.y);
    Target right = new_target(32, 24, &ZBUFFER), naive = new_target(32, 24, &ZBUFFER_NAIVE);
    draw_screen_triangle(&right, &ZBUFFER, a, b, c, 0);
    draw_screen_triangle(&naive, &ZBUFFER_NAIVE, a, b, c, 0);
    for (int y = 0; y < 24; y += 23)
        for (int x = 0; x < 32; x += 31) { /* the four corner pixels of the screen */
            double px = x + 0.5, py = y + 0.5;
            double wa = area2(b.x, b.y, c.x, c.y, px, py) / whole;
            double wb = area2(c.x, c.y, a.x, a.y, px, py) / whole;
            double wc = 1 - wa - wb;
            char what[96];
            snprintf(what, sizeof what, "perspective depth at (%d,%d) after the guard band", x, y);
            expect_relative(target_depth_at(&right, x, y), 1 / (wa / a.d + wb / b.d + wc / c.d),
                            1e-6, what);
            snprintf(what, sizeof what, "naive depth at (%d,%d) after the guard band", x, y);
            expect_relative(target_depth_at(&naive, x, y), wa * a.d + wb * b.d + wc * c.d, 1e-6,
                            what);
        }
    target_free(&right);
    target_free(&naive);
}

/* The far plane: a triangle at d = 60 with far = 50 tests no fragment. */
static void fragments_beyond_far_are_discarded_untested(void **state)
{
    (void)state;
    Target t = new_target(16, 16, &ZBUFFER);
    ScreenVertex v[3] = {{1, 1, 60}, {15, 1, 60}, {1, 15, 60}};
    ScreenFace f = screen_triangle(v, 0);
    DrawContext ctx = {0.1, 50, t.width, t.height};
    draw_face(&t, NULL, &f, &ctx);
    expect_count(0, t.stats.tested, "fragments tested");
    expect_target_face(&t, 3, 3, NO_FACE, "");
    target_free(&t);
}

/* ---- The negated-w bug ----------------------------------------------------------- */

/* Two squares on a 32 x 32 screen, each two triangles: face 0 over pixels
 * 8 .. 23 at d = 2 (near), face 1 over pixels 4 .. 27 at d = 8 (far). */
static void draw_two_squares(Target *t, const Rasterizer *rz, bool far_first)
{
    for (int k = 0; k < 2; k++) {
        bool near = far_first ? k == 1 : k == 0;
        double lo = near ? 8 : 4, hi = near ? 24 : 28, d = near ? 2 : 8;
        ScreenVertex p = {lo, lo, d}, q = {hi, lo, d}, r = {hi, hi, d}, s = {lo, hi, d};
        draw_screen_triangle(t, rz, p, q, r, near ? 0 : 1);
        draw_screen_triangle(t, rz, p, r, s, near ? 0 : 1);
    }
}

/* With -d stored and d < stored kept, -8 < -2: the far square wins where they
 * overlap, in either order. The buffer holds -8 there, and reading it back as
 * view depth (--depth-out) gives 8, the depth of the face on the screen. */
static void negated_w_lets_the_far_square_cover_the_near_one(void **state)
{
    (void)state;
    for (int order = 0; order < 2; order++) {
        Target right = new_target(32, 32, &ZBUFFER), bug = new_target(32, 32, &NEGATED_W_BUG);
        draw_two_squares(&right, &ZBUFFER, order);
        draw_two_squares(&bug, &NEGATED_W_BUG, order);
        expect_target_face(&right, 16, 16, 0, "");
        assert_true(target_depth_at(&right, 16, 16) == 2);
        if (target_face_at(&bug, 16, 16) != 1)
            fail_msg("draw order %d: with -d stored the far square should cover the near one "
                     "at (16,16), face %d is there", order, target_face_at(&bug, 16, 16));
        assert_true(target_depth_at(&bug, 16, 16) == -8);
        float *d = render_view_depth(&bug, &NEGATED_W_BUG);
        assert_non_null(d);
        assert_true(d[16 * 32 + 16] == 8);
        assert_true(isinf(d[0])); /* background */
        free(d);
        target_free(&right);
        target_free(&bug);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(worked_example_gives_2_5_and_naive_gives_2_7),
        cmocka_unit_test(both_rules_give_the_corner_depth_at_a_corner),
        cmocka_unit_test(inverse_depth_is_linear_at_chosen_pixels),
        cmocka_unit_test(triangles3_depth_is_where_the_ray_meets_the_plane),
        cmocka_unit_test(huge_triangle_keeps_each_rules_depth_through_the_guard_band),
        cmocka_unit_test(fragments_beyond_far_are_discarded_untested),
        cmocka_unit_test(negated_w_lets_the_far_square_cover_the_near_one),
    };
    return cmocka_run_group_tests_name("03_perspective_z depth", tests, NULL, NULL);
}
