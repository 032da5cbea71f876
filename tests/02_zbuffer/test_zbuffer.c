/* test_zbuffer.c: what lesson 02 teaches, checked in-process: the depth test
 * resolves triangles3 where the painter cannot, depth is interpolated linearly
 * on the screen, and the two bugs do what the page says. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include "bugs.h"
#include "painter.h"
#include "raster.h"
#include "harness/render.h"
#include "test_support.h"

enum { RED = 0, GREEN = 1, BLUE = 2 }; /* the faces of triangles3, in scene order */

/* triangles3 at 200 x 150 with its own camera: eye (0, 0, 10), fovy 45. */
static void load_triangles3(Render *r, Target *t, const Rasterizer *rz)
{
    Options opt = {0};
    Error err;
    opt.width = 200;
    opt.height = 150;
    opt.scene = "triangles3";
    if (render_load(r, &opt, &err) != EXIT_OK)
        fail_msg("render_load: %s", err.msg);
    if (!render_target_init(t, rz, opt.width, opt.height, &err))
        fail_msg("render_target_init: %s", err.msg);
}

/* Three pixels, one in each overlap of triangles3, picked by hand at 200 x 150.
 * The camera maps (x, y, z) to d = 10 - z, x_s = (1.81066 x / d + 1) * 100,
 * y_s = (1 - 2.41421 y / d) * 75 (f = 1 / tan 22.5 deg = 2.41421, over the
 * aspect 4/3 for x). The corners land at
 *   red    (39.64, 115.24, d 9)  (165.84, 91.46, d 11)  (39.64, 75.00, d 9)
 *   green  (160.36, 105.18, d 9) (83.54, 9.16, d 11)    (130.18, 125.30, d 9)
 *   blue   (100.00, 4.59, d 9)   (50.62, 124.38, d 11)  (130.18, 24.70, d 9)
 * Barycentric weights at the pixel centres, then d = 9 + 2 * (tip's weight):
 *   (70, 90):  red  tip weight 0.2445, d 9.489;  blue 0.6914, d 10.383 -> red wins
 *   (100, 40): blue tip weight 0.2330, d 9.466;  green 0.7103, d 10.421 -> blue wins
 *   (125, 90): green tip weight 0.2575, d 9.515; red 0.6803, d 10.361 -> green wins
 * (The true depths, by intersecting the view ray with each plane, give the
 * same winners: 9.419 vs 10.294, 9.398 vs 10.335, 9.442 vs 10.270.) */
typedef struct { int x, y; int32_t front, back; } Overlap;
static const Overlap OVERLAPS[3] = {
    {70, 90, RED, BLUE},
    {100, 40, BLUE, GREEN},
    {125, 90, GREEN, RED},
};
static const char *const NAMES[3] = {"red", "green", "blue"};

static void zbuffer_resolves_the_cycle_of_triangles3(void **state)
{
    (void)state;
    Render r;
    Target t;
    Error err;
    load_triangles3(&r, &t, &ZBUFFER);
    assert_true(render_faces(&r, &t, &ZBUFFER, NULL, 0, NULL, NULL, &err));
    for (int k = 0; k < 3; k++) {
        const Overlap *o = &OVERLAPS[k];
        observe_value("face", target_face_at(&t, o->x, o->y));
        if (target_face_at(&t, o->x, o->y) != o->front)
            fail_msg("pixel (%d,%d): %s should cover %s, the z-buffer shows face %d", o->x,
                     o->y, NAMES[o->front], NAMES[o->back], target_face_at(&t, o->x, o->y));
    }
    target_free(&t);
    render_free(&r);
}

/* All three triangles have mean depth (9 + 9 + 11) / 3: the painter keeps
 * mesh order, red, green, blue, so blue is painted over red at (70, 90). */
static void painter_gets_triangles3_wrong(void **state)
{
    (void)state;
    Render r;
    Target t;
    Error err;
    load_triangles3(&r, &t, &ZBUFFER);
    assert_true(draw_painter(&r, &t, &ZBUFFER, &err));
    expect_target_face(&t, 70, 90, BLUE, "");  /* wrong: red is nearer here */
    expect_target_face(&t, 100, 40, BLUE, ""); /* right by luck of the order */
    expect_target_face(&t, 125, 90, GREEN, "");
    expect_count(0, t.stats.failed, "fragments failed"); /* no depth test ever said no */
    target_free(&t);
    render_free(&r);
}

/* Whatever the order, painting gets one of the three overlaps wrong: in the
 * cycle red > blue > green > red, the face painted last covers both others. */
static void no_painting_order_is_right_for_triangles3(void **state)
{
    (void)state;
    const int orders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    const int alone[3] = {0, 1, 2}; /* each face in a buffer of its own: painting */
    for (int p = 0; p < 6; p++) {
        Render r;
        Target t;
        Error err;
        load_triangles3(&r, &t, &ZBUFFER);
        assert_true(draw_in_own_buffers(&r, &t, &ZBUFFER, orders[p], alone, 3, &err));
        int right = 0;
        for (int k = 0; k < 3; k++)
            right += target_face_at(&t, OVERLAPS[k].x, OVERLAPS[k].y) == OVERLAPS[k].front;
        if (right == 3)
            fail_msg("painting in order %d %d %d got every overlap right", orders[p][0],
                     orders[p][1], orders[p][2]);
        target_free(&t);
        render_free(&r);
    }
}

/* The depth kept at the overlap pixels is the naive one above: d linear on the screen. */
static void depth_of_triangles3_is_linear_on_the_screen(void **state)
{
    (void)state;
    Render r;
    Target t;
    Error err;
    load_triangles3(&r, &t, &ZBUFFER);
    assert_true(render_faces(&r, &t, &ZBUFFER, NULL, 0, NULL, NULL, &err));
    const double naive[3] = {9.489, 9.466, 9.515}, perspective[3] = {9.419, 9.398, 9.442};
    for (int k = 0; k < 3; k++) {
        double d = target_depth_at(&t, OVERLAPS[k].x, OVERLAPS[k].y);
        observe_near(d, naive[k], 1e-3);
        if (fabs(d - naive[k]) > 1e-3)
            fail_msg("pixel (%d,%d): depth %.5f, the linear interpolation by hand gives %.3f",
                     OVERLAPS[k].x, OVERLAPS[k].y, d, naive[k]);
        /* ... and so not the true depth of the surface there (lesson 03). */
        assert_true(fabs(d - perspective[k]) > 0.05);
    }
    target_free(&t);
    render_free(&r);
}

/* Corners (0, 0, d 1), (64, 0, d 3), (0, 64, d 5). At the centre (x + 0.5,
 * y + 0.5) the weights of the last two corners are (x + 0.5) / 64 and
 * (y + 0.5) / 64, so d = 1 + 2 (x + 0.5) / 64 + 4 (y + 0.5) / 64:
 *   pixel (15, 31):  1 + 31/64 + 126/64 = 3.453125
 *   pixel (40, 10):  1 + 81/64 + 42/64  = 2.921875
 *   pixel (0, 0):    1 + 1/64 + 2/64    = 1.046875
 *   pixel (62, 0):   1 + 125/64 + 2/64  = 2.984375
 * All exact in binary, and in a float. */
static void depth_is_interpolated_linearly_at_chosen_pixels(void **state)
{
    (void)state;
    Target t;
    Error err;
    assert_true(render_target_init(&t, &ZBUFFER, 64, 64, &err));
    ScreenVertex v[3] = {{0, 0, 1}, {64, 0, 3}, {0, 64, 5}};
    ScreenFace f = screen_triangle(v, 0);
    DrawContext ctx = {0.1, 100, t.width, t.height};
    draw_face(&t, NULL, &f, &ctx);
    const struct { int x, y; float d; } want[4] = {
        {15, 31, 3.453125f}, {40, 10, 2.921875f}, {0, 0, 1.046875f}, {62, 0, 2.984375f}};
    for (int k = 0; k < 4; k++)
        observe_near(target_depth_at(&t, want[k].x, want[k].y), want[k].d, 0.0);
    for (int k = 0; k < 4; k++)
        if (target_depth_at(&t, want[k].x, want[k].y) != want[k].d)
            fail_msg("pixel (%d,%d): depth %.9g, by hand %.9g", want[k].x, want[k].y,
                     target_depth_at(&t, want[k].x, want[k].y), want[k].d);
    target_free(&t);
}

/* interpolate_depth itself: weights 0.5, 0.3, 0.2 of depths 2, 3, 4 give
 * 1 + 0.9 + 0.8 = 2.7 (the naive average; 1/d-linear would give 2.5). */
static void interpolate_depth_is_the_weighted_average(void **state)
{
    (void)state;
    Barycentric w = {0.5, 0.3, 0.2};
    assert_true(fabs(interpolate_depth(w, 2, 3, 4) - 2.7) < 1e-12);
}

/* The far plane: a triangle at d = 60 with far = 50 tests no fragment. */
static void fragments_beyond_far_are_discarded_untested(void **state)
{
    (void)state;
    Target t;
    Error err;
    assert_true(render_target_init(&t, &ZBUFFER, 16, 16, &err));
    ScreenVertex v[3] = {{1, 1, 60}, {15, 1, 60}, {1, 15, 60}};
    ScreenFace f = screen_triangle(v, 0);
    DrawContext ctx = {0.1, 50, t.width, t.height};
    draw_face(&t, NULL, &f, &ctx);
    expect_count(0, t.stats.tested, "fragments tested");
    expect_target_face(&t, 3, 3, NO_FACE, "");
    target_free(&t);
}

/* ---- The bugs ------------------------------------------------------------------ */

/* Camera at the origin looking down -Z, fovy 90, 64 x 64: a point (x, y, -d)
 * lands at x_s = 32 + 32 x / d, y_s = 32 - 32 y / d.
 *   object A, face 0: square of half-size 1 at d = 2 -> pixels 16 .. 48
 *   object B, face 1: square of half-size 4 at d = 8 -> pixels 16 .. 48
 *             face 2: triangle (-4, -4, -8), (2, -2, -6), (2, 2, -6) -> (16, 48),
 *             (42.7, 42.7), (42.7, 21.3); it shares its first vertex with face 1,
 *             so it belongs to object B. It holds the centre (32.5, 32.5): that
 *             lies right of x + y = 64, above the edge through (16, 48) and
 *             (42.7, 42.7), left of x = 42.7; its depth there is between 6 and 8.
 * At the centre pixel (32, 32) all three overlap: A is nearest. */
static void build_two_objects(Render *r)
{
    Mesh m;
    Error err;
    mesh_init(&m);
    const Vec3 p[10] = {
        {-1, -1, -2}, {1, -1, -2}, {1, 1, -2}, {-1, 1, -2},   /* A */
        {-4, -4, -8}, {4, -4, -8}, {4, 4, -8}, {-4, 4, -8},   /* B, far */
        {2, -2, -6}, {2, 2, -6},                              /* B, nearer */
    };
    for (int i = 0; i < 10; i++)
        assert_true(mesh_add_vertex(&m, p[i], &err) >= 0);
    const int a[4] = {0, 1, 2, 3}, b[4] = {4, 5, 6, 7}, c[3] = {4, 8, 9};
    assert_true(mesh_add_face(&m, a, 4, -1, &err) >= 0);
    assert_true(mesh_add_face(&m, b, 4, -1, &err) >= 0);
    assert_true(mesh_add_face(&m, c, 3, -1, &err) >= 0);
    Camera cam;
    camera_init(&cam, vec3(0, 0, 0), vec3(0, 0, -1), vec3(0, 1, 0), 90, 1, 100, 64, 64);
    assert_true(render_from_mesh(r, &m, &cam, "two objects", &err));
}

static void objects_are_faces_joined_by_vertices(void **state)
{
    (void)state;
    Render r;
    build_two_objects(&r);
    int object[3];
    assert_int_equal(find_objects(&r.mesh, object), 2);
    assert_int_equal(object[0], 0);
    assert_int_equal(object[1], 1);
    assert_int_equal(object[2], 1);
    render_free(&r);
}

static void separate_buffers_let_the_last_object_cover_the_first(void **state)
{
    (void)state;
    Render r;
    Target right, wrong;
    Error err;
    build_two_objects(&r);
    assert_true(render_target_init(&right, &ZBUFFER, 64, 64, &err));
    assert_true(render_target_init(&wrong, &ZBUFFER, 64, 64, &err));
    assert_true(render_faces(&r, &right, &ZBUFFER, NULL, 0, NULL, NULL, &err));
    assert_true(draw_separate_buffers(&r, &wrong, &ZBUFFER, &err));
    /* One buffer: A (d 2) is in front at the centre. Separate buffers: B was
     * drawn after A into a buffer where A does not exist, and within B its
     * nearer face 2 (d about 6) still hides face 1 (d 8). */
    expect_target_face(&right, 32, 32, 0, "");
    expect_target_face(&wrong, 32, 32, 2, "");
    /* --depth-out shows the depth of what is on screen: face 2's, not A's 2. */
    assert_true(target_depth_at(&wrong, 32, 32) > 5);
    target_free(&right);
    target_free(&wrong);
    render_free(&r);
}

/* Cleared to 0: every d > 0 fails d < 0. Nothing is drawn, every fragment fails. */
static void clear_to_zero_draws_nothing(void **state)
{
    (void)state;
    Render r;
    Target t;
    Error err;
    load_triangles3(&r, &t, &CLEAR_ZERO_BUG);
    assert_true(render_faces(&r, &t, &ZBUFFER, NULL, 0, NULL, NULL, &err));
    expect_at_least(1, t.stats.tested, "fragments tested");
    expect_count(0, t.stats.passed, "fragments passed");
    expect_count(t.stats.tested, t.stats.failed, "fragments failed");
    for (int i = 0; i < t.width * t.height; i++)
        if (t.face[i] != NO_FACE)
            fail_msg("pixel %d was drawn with the buffer cleared to 0", i);
    target_free(&t);
    render_free(&r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(zbuffer_resolves_the_cycle_of_triangles3),
        cmocka_unit_test(painter_gets_triangles3_wrong),
        cmocka_unit_test(no_painting_order_is_right_for_triangles3),
        cmocka_unit_test(depth_of_triangles3_is_linear_on_the_screen),
        cmocka_unit_test(depth_is_interpolated_linearly_at_chosen_pixels),
        cmocka_unit_test(interpolate_depth_is_the_weighted_average),
        cmocka_unit_test(fragments_beyond_far_are_discarded_untested),
        cmocka_unit_test(objects_are_faces_joined_by_vertices),
        cmocka_unit_test(separate_buffers_let_the_last_object_cover_the_first),
        cmocka_unit_test(clear_to_zero_draws_nothing),
    };
    return cmocka_run_group_tests_name("02_zbuffer", tests, NULL, NULL);
}
