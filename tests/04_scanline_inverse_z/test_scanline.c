/* test_scanline.c: lesson 04's rasterizer in pure screen space.
 *
 * Every expected map below is derived by hand from the fill rule
 *     a row is drawn when its centre y + 0.5 is in [top, bottom),
 *     a pixel when its centre x + 0.5 is in [left, right),
 * and every expected depth from 1/d being linear on the screen.
 *
 * Coverage is read from Target.overdraw, the fragments tested per pixel,
 * never from the depth or face buffers: those hold what the depth test let
 * through, and a coverage test must not fail because of the comparison
 * (a depth test turned round costs the depth tests, not these). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scanline.h"
#include "test_support.h"

#define FAR 1000.0
#define TWO_PI 6.283185307179586
#define MAP_MAX 64 * 65

static Target make_target(int width, int height)
{
    Target t;
    Error err;
    if (!target_init(&t, width, height, &err))
        fail_msg("target_init: %s", err.msg);
    clear_depth(&t, NULL);
    return t;
}

static ScreenVertex sv(double x, double y, double d)
{
    ScreenVertex v = {x, y, d};
    return v;
}

/* A polygon at one depth d, drawn as one face. */
static void draw_flat(Target *t, const double (*xy)[2], int n, double d, int face)
{
    ScreenVertex v[16];
    for (int i = 0; i < n; i++)
        v[i] = sv(xy[i][0], xy[i][1], d);
    assert_true(draw_polygon(&(Primitive){t, NULL, face}, v, n, FAR));
}

/* The same corners in the other winding. */
static void draw_flat_reversed(Target *t, const double (*xy)[2], int n, double d, int face)
{
    ScreenVertex v[16];
    for (int i = 0; i < n; i++)
        v[i] = sv(xy[n - 1 - i][0], xy[n - 1 - i][1], d);
    assert_true(draw_polygon(&(Primitive){t, NULL, face}, v, n, FAR));
}

/* The buffer as rows of characters. With digits, the view depth d =
 * 1/stored rounded, as De Goes' z-buffer text draws it (blanks for cleared
 * pixels). Without, the coverage: '.' where no fragment was tested, '#'
 * where one was, and the count where more were. */
static void buffer_map(const Target *t, bool digits, char *out)
{
    char *p = out;
    for (int y = 0; y < t->height; y++) {
        for (int x = 0; x < t->width; x++) {
            size_t i = (size_t)y * (size_t)t->width + (size_t)x;
            uint32_t tested = t->overdraw[i];
            if (!digits)
                *p++ = tested == 0 ? '.' : tested == 1 ? '#' : (char)('0' + (tested > 9 ? 9 : tested));
            else if (t->depth[i] == CLEARED_INV_DEPTH)
                *p++ = ' ';
            else
                *p++ = (char)('0' + (int)lround(1.0 / t->depth[i]) % 10);
        }
        *p++ = '\n';
    }
    *p = '\0';
}

static void expect_map(const Target *t, bool digits, const char *const *rows, const char *what)
{
    char actual[MAP_MAX], expected[MAP_MAX] = "";
    buffer_map(t, digits, actual);
    for (int y = 0; y < t->height; y++) {
        strcat(expected, rows[y]);
        strcat(expected, "\n");
    }
    if (strcmp(actual, expected) != 0)
        fail_msg("%s: the buffer does not match.\nexpected:\n%sactual:\n%s", what, expected,
                 actual);
}

/* ---- De Goes' two z-buffers, rebuilt on an 8x3 buffer ------------------- */

/* The triangle apex (4,0), base (0,3)-(8,3), at depth 5. Its left edge is
 * x = 4 - 4y/3, its right edge x = 4 + 4y/3:
 *   row 0, centre y = 0.5: [3.333, 4.667): centres 3.5, 4.5        -> cols 3..4
 *   row 1, centre y = 1.5: [2, 6):         centres 2.5 .. 5.5      -> cols 2..5
 *   row 2, centre y = 2.5: [0.667, 7.333): centres 1.5 .. 6.5      -> cols 1..6
 * which is the first map of De Goes' text. Then a polygon over the whole screen at
 * depth 6 fills only the pixels still cleared (1/6 < 1/5 elsewhere). */
static const double TRIANGLE_AT_5[3][2] = {{4, 0}, {8, 3}, {0, 3}};
static const double SCREEN_POLYGON[4][2] = {{0, 0}, {8, 0}, {8, 3}, {0, 3}};

static void triangle_at_depth_5_in_front_of_nothing(void **state)
{
    (void)state;
    Target t = make_target(8, 3);
    draw_flat(&t, TRIANGLE_AT_5, 3, 5.0, 0);
    const char *map[] = {"   55   ", "  5555  ", " 555555 "};
    expect_map(&t, true, map, "De Goes' first z-buffer");
    expect_count(2 + 4 + 6, t.stats.tested, "fragments tested");
    expect_count(12, t.stats.passed, "fragments passed");
    target_free(&t);
}

static void screen_polygon_at_depth_6_shows_only_around_the_triangle(void **state)
{
    (void)state;
    Target t = make_target(8, 3);
    draw_flat(&t, TRIANGLE_AT_5, 3, 5.0, 0);
    draw_flat(&t, SCREEN_POLYGON, 4, 6.0, 1);
    const char *map[] = {"66655666", "66555566", "65555556"};
    expect_map(&t, true, map, "De Goes' second z-buffer");
    /* 24 fragments of the depth-6 polygon: 12 land on cleared pixels, 12 lose to the 5s. */
    expect_count(12 + 24, t.stats.tested, "fragments tested");
    expect_count(12 + 12, t.stats.passed, "fragments passed");
    expect_count(12, t.stats.failed, "fragments failed");
    target_free(&t);
}

/* Drawn in the other order the result is the same: the buffer, not the order,
 * decides. The triangle's 12 fragments all win over the 6s. */
static void two_buffers_do_not_depend_on_drawing_order(void **state)
{
    (void)state;
    Target t = make_target(8, 3);
    draw_flat(&t, SCREEN_POLYGON, 4, 6.0, 1);
    draw_flat(&t, TRIANGLE_AT_5, 3, 5.0, 0);
    const char *map[] = {"66655666", "66555566", "65555556"};
    expect_map(&t, true, map, "screen polygon first, then the triangle");
    expect_count(24 + 12, t.stats.passed, "fragments passed");
    expect_count(0, t.stats.failed, "fragments failed");
    target_free(&t);
}

/* ---- the buffer: cleared to 0, reversed test, ties ---------------------- */

static void clear_to_zero_means_nothing_drawn(void **state)
{
    (void)state;
    Target t = make_target(5, 4);
    for (size_t i = 0; i < 20; i++) {
        t.depth[i] = 0.25f;
        t.face[i] = 7;
    }
    clear_depth(&t, NULL);
    for (size_t i = 0; i < 20; i++) {
        assert_true(t.depth[i] == 0.0f);
        expect_count(NO_FACE, t.face[i], "face after the clear");
    }
    target_free(&t);
}

/* Any surface in front of the camera has 1/d > 0, so it beats the cleared
 * value, however far it is: d = 900 gives 1/d = 0.0011 > 0. */
static void clear_to_zero_loses_to_a_far_surface(void **state)
{
    (void)state;
    Target t = make_target(1, 1);
    assert_true(depth_test(&(Primitive){&t, NULL, 3}, 0, 0, (float)(1.0 / 900.0)));
    expect_target_face(&t, 0, 0, 3, "");
    target_free(&t);
}

/* Nearer means larger 1/d: 1/2 > 1/4, so the surface at d = 2 wins whichever
 * comes first. */
static void larger_inverse_depth_wins(void **state)
{
    (void)state;
    Target t = make_target(2, 1);
    assert_true(depth_test(&(Primitive){&t, NULL, 1}, 0, 0, (float)(1.0 / 4.0)));  /* far first */
    assert_true(depth_test(&(Primitive){&t, NULL, 2}, 0, 0, (float)(1.0 / 2.0)));  /* near wins over it */
    assert_true(depth_test(&(Primitive){&t, NULL, 2}, 1, 0, (float)(1.0 / 2.0)));  /* near first */
    assert_false(depth_test(&(Primitive){&t, NULL, 1}, 1, 0, (float)(1.0 / 4.0))); /* far loses */
    expect_target_face(&t, 0, 0, 2, "near drawn second");
    expect_target_face(&t, 1, 0, 2, "near drawn first");
    assert_true(t.depth[0] == 0.5f && t.depth[1] == 0.5f);
    expect_count(4, t.stats.tested, "fragments tested");
    expect_count(1, t.stats.failed, "fragments failed");
    expect_count(2, t.overdraw[0], "fragments tested at pixel (0, 0)");
    target_free(&t);
}

static void equal_depth_keeps_the_first_fragment(void **state)
{
    (void)state;
    Target t = make_target(8, 3);
    draw_flat(&t, SCREEN_POLYGON, 4, 6.0, 1);
    draw_flat(&t, SCREEN_POLYGON, 4, 6.0, 2);
    for (size_t i = 0; i < 24; i++)
        expect_count(1, t.face[i], "face (the tie keeps the first)");
    expect_count(24, t.stats.failed, "fragments failed");
    target_free(&t);
}

/* far = 1000: a polygon at d = 1000 is drawn, one at d = 1001 is discarded
 * before the depth test, so none of its fragments is even counted. */
static void far_plane_discards_before_the_test(void **state)
{
    (void)state;
    Target t = make_target(8, 3);
    draw_flat(&t, SCREEN_POLYGON, 4, 1001.0, 1);
    expect_count(0, t.stats.tested, "fragments tested");
    draw_flat(&t, SCREEN_POLYGON, 4, 1000.0, 2);
    expect_count(24, t.stats.tested, "fragments tested");
    expect_target_face(&t, 0, 0, 2, "");
    target_free(&t);
}

/* ---- polygons of 3, 4, 5 and 8 corners, both windings ------------------ */

/* Draws xy in both windings, starting at every corner, and checks each
 * gives the map. */
static void expect_polygon_map(const double (*xy)[2], int n, int width, int height,
                               const char *const *rows, int pixels, const char *what)
{
    for (int reversed = 0; reversed < 2; reversed++) {
        for (int start = 0; start < n; start++) {
            double rotated[16][2];
            for (int i = 0; i < n; i++) {
                rotated[i][0] = xy[(start + i) % n][0];
                rotated[i][1] = xy[(start + i) % n][1];
            }
            Target t = make_target(width, height);
            if (reversed)
                draw_flat_reversed(&t, (const double (*)[2])rotated, n, 2.0, 0);
            else
                draw_flat(&t, (const double (*)[2])rotated, n, 2.0, 0);
            char label[128];
            snprintf(label, sizeof label, "%s (%s winding, starting at corner %d)", what,
                     reversed ? "reversed" : "given", start);
            expect_map(&t, false, rows, label);
            expect_count(pixels, t.stats.tested, "fragments tested");
            target_free(&t);
        }
    }
}

/* The right triangle (0,0) (8,0) (0,8): its hypotenuse x = 8 - y is a right
 * edge. Row y has centre y + 0.5, so the edge is at x = 7.5 - y, which is a
 * pixel centre: excluded. Row y keeps cols 0 .. 6 - y: 7 + 6 + ... + 0 = 28
 * pixels (area 32, minus half of each of the 8 centres on the edge). */
static void triangle_with_its_hypotenuse_on_the_right(void **state)
{
    (void)state;
    const double tri[3][2] = {{0, 0}, {8, 0}, {0, 8}};
    const char *map[] = {"#######.", "######..", "#####...", "####....",
                         "###.....", "##......", "#.......", "........"};
    expect_polygon_map(tri, 3, 8, 8, map, 28, "right triangle, hypotenuse right");
}

/* The other half of the square: (8,0) (8,8) (0,8). The hypotenuse is now a
 * left edge and the centres on it are drawn: row y keeps cols 7 - y .. 7,
 * 1 + 2 + ... + 8 = 36 pixels; with the triangle above, 28 + 36 = 64, each
 * pixel of the square once. */
static void triangle_with_its_hypotenuse_on_the_left(void **state)
{
    (void)state;
    const double tri[3][2] = {{8, 0}, {8, 8}, {0, 8}};
    const char *map[] = {".......#", "......##", ".....###", "....####",
                         "...#####", "..######", ".#######", "########"};
    expect_polygon_map(tri, 3, 8, 8, map, 36, "right triangle, hypotenuse left");
}

/* The square (1,1) (5,1) (5,4) (1,4): horizontal top and bottom edges.
 * Rows with centre in [1, 4): 1, 2, 3; cols with centre in [1, 5): 1 .. 4. */
static void square_with_horizontal_edges(void **state)
{
    (void)state;
    const double quad[4][2] = {{1, 1}, {5, 1}, {5, 4}, {1, 4}};
    const char *map[] = {"......", ".####.", ".####.", ".####.", "......"};
    expect_polygon_map(quad, 4, 6, 5, map, 12, "square");
}

/* The square (0.5,0.5) (2.5,0.5) (2.5,2.5) (0.5,2.5) has every corner on a
 * pixel centre. Rows with centre in [0.5, 2.5): 0 and 1 (2.5 is out);
 * columns with centre in [0.5, 2.5): 0 and 1. Top and left are in, bottom
 * and right are out. */
static void square_on_pixel_centres_keeps_top_and_left(void **state)
{
    (void)state;
    const double quad[4][2] = {{0.5, 0.5}, {2.5, 0.5}, {2.5, 2.5}, {0.5, 2.5}};
    const char *map[] = {"##..", "##..", "....", "...."};
    expect_polygon_map(quad, 4, 4, 4, map, 4, "square on pixel centres");
}

/* The diamond (4,0) (8,4) (4,8) (0,4): edges at 45 degrees through pixel
 * centres. Above y = 4 the span is [4 - yc, 4 + yc), below it
 * [yc - 4, 12 - yc), with yc = y + 0.5:
 *   row 0 [3.5, 4.5) -> col 3      row 4 [0.5, 7.5) -> cols 0..6
 *   row 1 [2.5, 5.5) -> cols 2..4  row 5 [1.5, 6.5) -> cols 1..5
 *   row 2 [1.5, 6.5) -> cols 1..5  row 6 [2.5, 5.5) -> cols 2..4
 *   row 3 [0.5, 7.5) -> cols 0..6  row 7 [3.5, 4.5) -> col 3
 * 32 pixels, the diamond's area: left edges gain what right edges lose. */
static void diamond_with_edges_through_pixel_centres(void **state)
{
    (void)state;
    const double quad[4][2] = {{4, 0}, {8, 4}, {4, 8}, {0, 4}};
    const char *map[] = {"...#....", "..###...", ".#####..", "#######.",
                         "#######.", ".#####..", "..###...", "...#...."};
    expect_polygon_map(quad, 4, 8, 8, map, 32, "diamond");
}

/* The pentagon (0,0) (6,0) (8,2) (8,8) (0,8): a square with its top right
 * corner cut along x = 6 + y (a right edge). Row 0: [0, 6.5) -> cols 0..5;
 * row 1: [0, 7.5) -> cols 0..6; rows 2..7: [0, 8) -> all. 6 + 7 + 48 = 61. */
static void pentagon(void **state)
{
    (void)state;
    const double poly[5][2] = {{0, 0}, {6, 0}, {8, 2}, {8, 8}, {0, 8}};
    const char *map[] = {"######..", "#######.", "########", "########",
                         "########", "########", "########", "########"};
    expect_polygon_map(poly, 5, 8, 8, map, 61, "pentagon");
}

/* The octagon (2,0) (6,0) (8,2) (8,6) (6,8) (2,8) (0,6) (0,2): the square with
 * four corners cut. Rows 0 and 7 have centres 1.5 from a corner: [1.5, 6.5)
 * -> cols 1..5; rows 1 and 6: [0.5, 7.5) -> cols 0..6; rows 2..5 full.
 * 5 + 7 + 32 + 7 + 5 = 56, the octagon's area 64 - 4 * 2. */
static void octagon(void **state)
{
    (void)state;
    const double poly[8][2] = {{2, 0}, {6, 0}, {8, 2}, {8, 6}, {6, 8}, {2, 8}, {0, 6}, {0, 2}};
    const char *map[] = {".#####..", "#######.", "########", "########",
                         "########", "########", "#######.", ".#####.."};
    expect_polygon_map(poly, 8, 8, 8, map, 56, "octagon");
}

/* ---- degenerate polygons ------------------------------------------------ */

/* All corners on y = 2, or on the row centre y = 2.5: [top, bottom) is empty. */
static void zero_height_polygon_draws_nothing(void **state)
{
    (void)state;
    Target t = make_target(8, 4);
    const double flat[3][2] = {{0, 2}, {8, 2}, {4, 2}};
    const double on_centre[4][2] = {{0, 2.5}, {3, 2.5}, {8, 2.5}, {5, 2.5}};
    draw_flat(&t, flat, 3, 2.0, 0);
    draw_flat(&t, on_centre, 4, 2.0, 0);
    expect_count(0, t.stats.tested, "fragments tested");
    target_free(&t);
}

/* A vertical sliver on the column centre x = 3.5: [left, right) is empty. */
static void zero_width_polygon_draws_nothing(void **state)
{
    (void)state;
    Target t = make_target(8, 8);
    const double sliver[3][2] = {{3.5, 0}, {3.5, 8}, {3.5, 4}};
    draw_flat(&t, sliver, 3, 2.0, 0);
    expect_count(0, t.stats.tested, "fragments tested");
    target_free(&t);
}

/* The unit square (2,3)-(3,4) covers exactly pixel (2,3): row 3 (3.5 in
 * [3, 4)), col 2 (2.5 in [2, 3)). */
static void unit_square_covers_one_pixel(void **state)
{
    (void)state;
    Target t = make_target(6, 6);
    const double quad[4][2] = {{2, 3}, {3, 3}, {3, 4}, {2, 4}};
    draw_flat(&t, quad, 4, 2.0, 0);
    expect_count(1, t.stats.tested, "fragments tested");
    expect_count(1, t.overdraw[3 * 6 + 2], "fragments tested at pixel (2, 3)");
    target_free(&t);
}

/* A triangle a fifth of a pixel wide around the centre (2.5, 3.5): top edge
 * y = 3.4 from x = 2.4 to 2.6, apex (2.5, 3.6). At y = 3.5 its span is
 * [2.45, 2.55), which holds the centre 2.5: one pixel. Shifted right by
 * 0.3 pixels it holds no centre: nothing. */
static void tiny_triangles_cover_one_pixel_or_none(void **state)
{
    (void)state;
    Target t = make_target(6, 6);
    const double around[3][2] = {{2.4, 3.4}, {2.6, 3.4}, {2.5, 3.6}};
    const double beside[3][2] = {{2.7, 3.4}, {2.9, 3.4}, {2.8, 3.6}};
    draw_flat(&t, around, 3, 2.0, 0);
    expect_count(1, t.stats.tested, "fragments tested");
    expect_count(1, t.overdraw[3 * 6 + 2], "fragments tested at pixel (2, 3)");
    draw_flat(&t, beside, 3, 2.0, 1);
    expect_count(1, t.stats.tested, "fragments tested");
    target_free(&t);
}

/* A bow tie (the corners of a square in the wrong order) is not convex: the
 * rasterizer refuses it, so that the caller draws its triangles instead. */
static void non_convex_polygon_is_refused(void **state)
{
    (void)state;
    Target t = make_target(8, 8);
    ScreenVertex bowtie[4] = {sv(0, 0, 2), sv(8, 8, 2), sv(8, 0, 2), sv(0, 8, 2)};
    ScreenVertex dart[4] = {sv(0, 0, 2), sv(4, 3, 2), sv(8, 0, 2), sv(4, 8, 2)};
    assert_false(draw_polygon(&(Primitive){&t, NULL, 0}, bowtie, 4, FAR));
    assert_false(draw_polygon(&(Primitive){&t, NULL, 0}, dart, 4, FAR));
    expect_count(0, t.stats.tested, "fragments tested");
    target_free(&t);
}

/* ---- 1/d along edges and spans ------------------------------------------ */

/* The depth at each pixel is 1/d linear on the screen. The quad spans the
 * whole screen, d = 2 on its left side (x = 0) and d = 8 on its right
 * (x = 8): at the centre x + 0.5, 1/d = 1/2 + (x + 0.5) / 8 * (1/8 - 1/2).
 * The test allows 2 float steps (the buffer stores floats). */
static void inverse_depth_is_linear_across_the_span(void **state)
{
    (void)state;
    Target t = make_target(8, 2);
    ScreenVertex quad[4] = {sv(0, 0, 2), sv(8, 0, 8), sv(8, 2, 8), sv(0, 2, 2)};
    assert_true(draw_polygon(&(Primitive){&t, NULL, 0}, quad, 4, FAR));
    for (int y = 0; y < 2; y++)
        for (int x = 0; x < 8; x++) {
            double expected = 0.5 + (x + 0.5) / 8.0 * (0.125 - 0.5);
            float stored = t.depth[y * 8 + x];
            assert_true(fabs(stored - expected) <= 2 * expected * FLT_EPSILON);
        }
    target_free(&t);
}

/* Down an edge 1/d is linear too: the triangle (0,0,d=1) (8,0,d=1) (0,64,d=4)
 * has, on row y, 1/d = 1 + (y + 0.5) / 64 * (1/4 - 1) at every pixel (the
 * top edge holds 1/d = 1 all along). Column 0 is inside while its centre 0.5
 * is left of the hypotenuse x = 8 - y / 8, i.e. for y + 0.5 < 60: rows 0..59. */
static void inverse_depth_is_linear_down_the_edges(void **state)
{
    (void)state;
    Target t = make_target(8, 64);
    ScreenVertex tri[3] = {sv(0, 0, 1), sv(8, 0, 1), sv(0, 64, 4)};
    assert_true(draw_polygon(&(Primitive){&t, NULL, 0}, tri, 3, FAR));
    for (int y = 0; y < 64; y++) {
        double expected = 1.0 + (y + 0.5) / 64.0 * (0.25 - 1.0);
        float stored = t.depth[y * 8];
        if (y < 60)
            observe_near(stored, expected, 2 * expected * FLT_EPSILON);
        if (y >= 60)
            assert_true(stored == CLEARED_INV_DEPTH);
        else if (fabs(stored - expected) > 2 * expected * FLT_EPSILON)
            fail_msg("row %d: 1/d is %.9g, expected %.9g", y, stored, expected);
    }
    target_free(&t);
}

/* Incremental stepping stays accurate over the longest span there is: 16384
 * pixels, d = 1 at x = 0 and d = 100 at x = 16384. Directly,
 *     1/d(x + 0.5) = 1 + (x + 0.5) / 16384 * (1/100 - 1).
 * draw_span reaches pixel x by x additions of the same step in double
 * precision; each addition rounds by at most half an ulp of a value <= 1, so
 * after 16383 of them the error is below 16383 * 2^-53 ~ 1.8e-12. The buffer
 * stores floats, and a float near the far end (1/d ~ 0.01) has a step of
 * 2^-30 ~ 9.3e-10, 500 times larger: so the stored value is the exact value
 * rounded to float, or at worst the float next to it. One float step is the
 * tolerance, and it is enough: no depth test can see finer than the buffer. */
static void stepping_along_a_long_span_stays_accurate(void **state)
{
    (void)state;
    const int w = IMAGE_MAX_SIDE;
    Target t = make_target(w, 1);
    ScreenVertex quad[4] = {sv(0, 0, 1), sv(w, 0, 100), sv(w, 1, 100), sv(0, 1, 1)};
    assert_true(draw_polygon(&(Primitive){&t, NULL, 0}, quad, 4, FAR));
    expect_count(w, t.stats.tested, "fragments tested");
    int worst_x = -1;
    double worst = 0;
    for (int x = 0; x < w; x++) {
        double exact = 1.0 + (x + 0.5) / w * (0.01 - 1.0);
        float rounded = (float)exact;
        float one_step = nextafterf(rounded, INFINITY) - rounded;
        double error = fabs((double)t.depth[x] - exact);
        if (error > one_step && error > worst) {
            worst = error;
            worst_x = x;
        }
    }
    if (worst_x >= 0)
        fail_msg("1/d at pixel %d is off by %g, more than one float step", worst_x, worst);
    /* The last pixel, as the issue asks, checked on its own. */
    double last = 1.0 + (w - 0.5) / w * (0.01 - 1.0);
    assert_true(fabs((double)t.depth[w - 1] - last) <= nextafterf((float)last, 1) - (float)last);
    target_free(&t);
}

/* ---- huge and broken coordinates ---------------------------------------- */

static ScreenFace face_of(const ScreenVertex *v, int n, const Tri *tris, bool convex)
{
    ScreenFace f = {0, n, v, tris, convex, NULL};
    return f;
}

/* A triangle with corners 10^15 pixels away that covers the 8x8 screen: it is
 * clipped to the guard band, walks only the 8 rows on the screen, and tests
 * each of the 64 pixels once. */
static void huge_triangle_covers_the_screen_once(void **state)
{
    (void)state;
    Target t = make_target(8, 8);
    ScreenVertex v[3] = {sv(-1e15, -1e15, 3), sv(3e15, -1e15, 3), sv(-1e15, 3e15, 3)};
    Tri tri = {{0, 1, 2}};
    ScreenFace f = face_of(v, 3, &tri, true);
    DrawContext ctx = {0.1, FAR, t.width, t.height};
    draw_face(&t, NULL, &f, &ctx);
    expect_count(64, t.stats.tested, "fragments tested");
    for (int i = 0; i < 64; i++)
        expect_count(1, t.overdraw[i], "fragments tested per pixel");
    target_free(&t);
}

/* A tall sliver 10^12 pixels high but a screen wide: only screen rows are
 * walked, so it finishes at once; every pixel of the screen is covered. */
static void tall_polygon_walks_only_screen_rows(void **state)
{
    (void)state;
    Target t = make_target(4, 4);
    ScreenVertex v[4] = {sv(0, -1e12, 2), sv(4, -1e12, 2), sv(4, 1e12, 2), sv(0, 1e12, 2)};
    Tri tris[2] = {{{0, 1, 2}}, {{0, 2, 3}}};
    ScreenFace f = face_of(v, 4, tris, true);
    DrawContext ctx = {0.1, FAR, t.width, t.height};
    draw_face(&t, NULL, &f, &ctx);
    expect_count(16, t.stats.tested, "fragments tested");
    target_free(&t);
}

/* NaN, infinity and d <= 0 never reach the pixels: nothing is drawn, nothing
 * crashes. (render.h drops such faces before; this is the rasterizer's own guard.) */
static void broken_corners_draw_nothing(void **state)
{
    (void)state;
    Target t = make_target(8, 8);
    Tri tri = {{0, 1, 2}};
    DrawContext ctx = {0.1, FAR, t.width, t.height};
    const ScreenVertex broken[4][3] = {
        {{NAN, 0, 2}, {8, 0, 2}, {0, 8, 2}},
        {{0, 0, 2}, {INFINITY, 0, 2}, {0, 8, 2}},
        {{0, 0, 2}, {8, 0, 2}, {0, 8, 0}},
        {{0, 0, 2}, {8, 0, 2}, {0, 8, -1}},
    };
    for (int k = 0; k < 4; k++) {
        ScreenFace f = face_of(broken[k], 3, &tri, true);
        draw_face(&t, NULL, &f, &ctx);
        assert_false(draw_polygon(&(Primitive){&t, NULL, 0}, broken[k], 3, FAR));
    }
    expect_count(0, t.stats.tested, "fragments tested");
    target_free(&t);
}

/* ---- faces: convex whole, non-convex as triangles ----------------------- */

/* The dart (0,0) (4,4) (8,0) (4,8), an arrow head pointing down, is not
 * convex: it is drawn as its ear-clipped triangles A = (0,0) (4,4) (4,8) and
 * B = (4,4) (8,0) (4,8), which share the edge x = 4 (right edge of A, left
 * edge of B). On row y, centre yc = y + 0.5:
 *   A spans [yc / 2, min(yc, 4))        B spans [max(8 - yc, 4), 8 - yc / 2)
 *   row 0: [0.25, 0.5)  none            [7.5, 7.75)  col 7
 *   row 1: [0.75, 1.5)  none            [6.5, 7.25)  col 6
 *   row 2: [1.25, 2.5)  col 1           [5.5, 6.75)  cols 5, 6
 *   row 3: [1.75, 3.5)  col 2           [4.5, 6.25)  cols 4, 5
 *   row 4: [2.25, 4)    cols 2, 3       [4, 5.75)    cols 4, 5
 *   row 5: [2.75, 4)    col 3           [4, 5.25)    col 4
 *   row 6: [3.25, 4)    col 3           [4, 4.75)    col 4
 *   row 7: [3.75, 4)    none            [4, 4.25)    none
 * 16 pixels, the dart's area (32 - 16), none twice. */
static void non_convex_face_is_drawn_as_its_triangles(void **state)
{
    (void)state;
    Target t = make_target(8, 8);
    ScreenVertex v[4] = {sv(0, 0, 2), sv(4, 4, 2), sv(8, 0, 2), sv(4, 8, 2)};
    Tri tris[2] = {{{0, 1, 3}}, {{1, 2, 3}}};
    ScreenFace f = face_of(v, 4, tris, false);
    DrawContext ctx = {0.1, FAR, t.width, t.height};
    draw_face(&t, NULL, &f, &ctx);
    const char *map[] = {".......#", "......#.", ".#...##.", "..#.##..",
                         "..####..", "...##...", "...##...", "........"};
    expect_map(&t, false, map, "dart drawn as two triangles");
    expect_count(16, t.stats.tested, "fragments tested");
    target_free(&t);
}

/* A face marked convex that is not convex on the screen is drawn as its
 * triangles too (draw_polygon refuses it): the same 16 pixels. */
static void face_not_convex_on_screen_falls_back_to_triangles(void **state)
{
    (void)state;
    Target t = make_target(8, 8);
    ScreenVertex v[4] = {sv(0, 0, 2), sv(4, 4, 2), sv(8, 0, 2), sv(4, 8, 2)};
    Tri tris[2] = {{{0, 1, 3}}, {{1, 2, 3}}};
    ScreenFace f = face_of(v, 4, tris, true);
    DrawContext ctx = {0.1, FAR, t.width, t.height};
    draw_face(&t, NULL, &f, &ctx);
    expect_count(16, t.stats.tested, "fragments tested");
    target_free(&t);
}

/* ---- coverage equals the edge-function rule of lessons 02 and 03 -------- */

/* The reference, written here from docs/conventions.md: pixel centre P is inside a
 * convex polygon when every edge function E = (b - a) x (P - a), signed for
 * the winding, is > 0, or = 0 on a top edge or a left edge. In integers of
 * 1/256 pixel, as the GPUs' rule is exact. */
static bool reference_inside(const int64_t (*p)[2], int n, int winding, int64_t px, int64_t py)
{
    for (int i = 0; i < n; i++) {
        const int64_t *a = p[i], *b = p[(i + 1) % n];
        int64_t dx = (b[0] - a[0]) * winding, dy = (b[1] - a[1]) * winding;
        int64_t e = dx * (py - a[1]) - dy * (px - a[0]);
        bool top_left = dy < 0 || (dy == 0 && dx > 0);
        if (e < 0 || (e == 0 && !top_left))
            return false;
    }
    return true;
}

static uint64_t lcg_state = 12345;
static double random_unit(void)
{
    lcg_state = lcg_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(lcg_state >> 11) / 9007199254740992.0;
}

static int compare_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* 400 random convex polygons (3 to 12 corners on a circle, some larger than
 * the screen, some half off it), snapped to 1/256: every pixel of a 48x40
 * screen is covered exactly when the reference says so. */
static void coverage_equals_the_edge_function_rule(void **state)
{
    (void)state;
    const int width = 48, height = 40;
    int checked = 0;
    for (int k = 0; k < 400; k++) {
        int n = 3 + (int)(random_unit() * 10);
        double cx = -10 + random_unit() * (width + 20), cy = -10 + random_unit() * (height + 20);
        double r = 0.5 + random_unit() * (k % 4 == 0 ? 200 : 25);
        double angles[12];
        for (int i = 0; i < n; i++)
            angles[i] = random_unit() * TWO_PI;
        qsort(angles, (size_t)n, sizeof angles[0], compare_double);
        int64_t p[12][2];
        ScreenVertex v[12];
        for (int i = 0; i < n; i++) {
            p[i][0] = llround((cx + r * cos(angles[i])) * 256);
            p[i][1] = llround((cy + r * sin(angles[i])) * 256);
            v[i] = sv((double)p[i][0] / 256.0, (double)p[i][1] / 256.0, 2);
        }
        /* Keep only polygons that stayed strictly convex after snapping. */
        int winding = 0;
        bool convex = true;
        for (int i = 0; i < n && convex; i++) {
            const int64_t *a = p[i], *b = p[(i + 1) % n], *c = p[(i + 2) % n];
            int64_t cross = (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]);
            int s = (cross > 0) - (cross < 0);
            if (s == 0 || (winding != 0 && s != winding))
                convex = false;
            winding = s;
        }
        if (!convex)
            continue;
        Target t = make_target(width, height);
        assert_true(draw_polygon(&(Primitive){&t, NULL, 0}, v, n, FAR));
        observe_coverage(&t);
        for (int y = 0; y < height; y++)
            for (int x = 0; x < width; x++) {
                bool expected = reference_inside((const int64_t (*)[2])p, n, winding,
                                                 256 * x + 128, 256 * y + 128);
                bool drawn = t.overdraw[y * width + x] > 0; /* tested, whatever the test said */
                if (expected != drawn)
                    fail_msg("polygon %d (%d corners): pixel (%d, %d) is %s but the edge "
                             "functions say %s", k, n, x, y, drawn ? "drawn" : "not drawn",
                             expected ? "inside" : "outside");
                expect_at_most(1, t.overdraw[y * width + x], "fragments tested per pixel");
            }
        target_free(&t);
        checked++;
    }
    expect_at_least(301, checked, "convex polygons checked"); /* most stay convex */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(triangle_at_depth_5_in_front_of_nothing),
        cmocka_unit_test(screen_polygon_at_depth_6_shows_only_around_the_triangle),
        cmocka_unit_test(two_buffers_do_not_depend_on_drawing_order),
        cmocka_unit_test(clear_to_zero_means_nothing_drawn),
        cmocka_unit_test(clear_to_zero_loses_to_a_far_surface),
        cmocka_unit_test(larger_inverse_depth_wins),
        cmocka_unit_test(equal_depth_keeps_the_first_fragment),
        cmocka_unit_test(far_plane_discards_before_the_test),
        cmocka_unit_test(triangle_with_its_hypotenuse_on_the_right),
        cmocka_unit_test(triangle_with_its_hypotenuse_on_the_left),
        cmocka_unit_test(square_with_horizontal_edges),
        cmocka_unit_test(square_on_pixel_centres_keeps_top_and_left),
        cmocka_unit_test(diamond_with_edges_through_pixel_centres),
        cmocka_unit_test(pentagon),
        cmocka_unit_test(octagon),
        cmocka_unit_test(zero_height_polygon_draws_nothing),
        cmocka_unit_test(zero_width_polygon_draws_nothing),
        cmocka_unit_test(unit_square_covers_one_pixel),
        cmocka_unit_test(tiny_triangles_cover_one_pixel_or_none),
        cmocka_unit_test(non_convex_polygon_is_refused),
        cmocka_unit_test(inverse_depth_is_linear_across_the_span),
        cmocka_unit_test(inverse_depth_is_linear_down_the_edges),
        cmocka_unit_test(stepping_along_a_long_span_stays_accurate),
        cmocka_unit_test(huge_triangle_covers_the_screen_once),
        cmocka_unit_test(tall_polygon_walks_only_screen_rows),
        cmocka_unit_test(broken_corners_draw_nothing),
        cmocka_unit_test(non_convex_face_is_drawn_as_its_triangles),
        cmocka_unit_test(face_not_convex_on_screen_falls_back_to_triangles),
        cmocka_unit_test(coverage_equals_the_edge_function_rule),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
