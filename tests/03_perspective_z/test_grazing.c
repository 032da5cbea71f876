/* test_grazing.c: the scene grazing, where the naive rule misplaces the line
 * along which two surfaces cross. The line, and which strip must win on each
 * side of it, are worked out here from the planes and the camera; then
 * build/bin/03_perspective_z is run with each rule, with --compare-naive,
 * with --bug negated-w and with --depth-out, and its pictures are read back.
 *
 * The scene (common/harness/scene.c): the camera is at the origin looking down -Z,
 * so a point's view depth is d = -z, with fovy 45 at 800 x 600. With
 * f = 1 / tan(22.5 deg) = 1 + sqrt(2) the viewport puts a point at
 *     x_s = 400 + 300 f x / d,   y_s = 300 - 300 f y / d
 * (300 f = 400 f / aspect = 300 f). Write u = y_s - 300 for the rows below
 * the horizon.
 *   strip A, face 0: y = -0.5,                 x in [-1, 1],       d in [1.5, 100]
 *                    u = 150 f / d
 *   strip B, face 1: y = -0.5 + (4 - d) / 64,  x in [-0.75, 0.75], d in [2, 100]
 *                    = -(7/16 + d/64), so u = 131.25 f / d + 4.6875 f
 * So the pixel row with centre py = y + 0.5 sees A at d_A = 150 f / u and B
 * at d_B = 131.25 f / (u - 4.6875 f), whatever the column. They are equal at
 * d = 4, u = 37.5 f: the strips meet along the horizontal line at row
 * 300 + 37.5 f = 390.533. Above it (u < 37.5 f, farther) A is in front,
 * below it B is: at u = 30 f, d_A = 5 < d_B = 5.19; at u = 45 f, d_A = 3.33 >
 * d_B = 3.26.
 *
 * B's outline on the screen: its near edge (d = 2) at u = 70.3125 f, row
 * 469.751, its far edge (d = 100) at u = 6 f, row 314.485, its sides where
 * |x_s - 400| = 225 f / d_B. A covers all of it: on any row A's half-width
 * 300 f / d_A = 2 u exceeds B's 225 f / d_B = (12/7) (u - 4.6875 f), and A's
 * rows 303.6 .. 541.4 hold B's. The pixels tested are those whose centre is
 * at least 1 pixel inside B's outline (rows with py in [315.485, 468.751],
 * columns with |px - 400| <= 225 f / d_B - 1.5) and at least 2 pixels from
 * the line: 41070 pixels, 10106 above it and 30964 below it.
 *
 * The naive rule. Each strip is one quad whose near edge and far edge are
 * horizontal on the screen, each at one depth, so in both triangles of the
 * quad the naive d depends on the row alone, linearly from the near row to
 * the far row:
 *   A: d = 1.5 + 98.5 (100 f - u) / (98.5 f)     = 101.5 - u / f
 *   B: d = 2 + 98 (70.3125 f - u) / (64.3125 f)  = 2 + (32/21) (70.3125 - u / f)
 * They are equal at u / f = 160.5 / 11, row 300 + 14.591 f = 335.226, and
 * below that row the naive B is the nearer. So the naive rule shows B down
 * from row 335.226 instead of 390.533, 55 rows too high: it gets wrong the
 * tested pixels with centres between the two lines, 9226 of them (rows 335 to
 * 388). The nearest pixel centre to its line, row 335's at 335.5, is 0.27 of
 * a pixel away; snapping corners to 1/256 of a pixel moves it far less. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness/image_io.h"
#include "harness/shade.h"
#include "test_support.h"

#define PROGRAM "03_perspective_z"
#define STRIP_A 0
#define STRIP_B 1

#define TESTED_PIXELS 41070
#define TESTED_ABOVE 10106
#define TESTED_BELOW 30964
#define NAIVE_WRONG 9226

static const double F = 2.41421356237309504880; /* 1 / tan(22.5 deg) = 1 + sqrt(2) */

static double line_row(void) { return 300 + 37.5 * F; }
static double naive_line_row(void) { return 300 + 160.5 / 11 * F; }

/* True when pixel (x, y) is one of the tested pixels; *above tells its side. */
static bool tested_pixel(int x, int y, bool *above)
{
    double px = x + 0.5, py = y + 0.5, u = py - 300;
    if (py < 300 + 6 * F + 1 || py > 300 + 70.3125 * F - 1)
        return false;
    if (fabs(py - line_row()) < 2)
        return false;
    double d_b = 131.25 * F / (u - 4.6875 * F);
    if (fabs(px - 400) > 225 * F / d_b - 1.5)
        return false;
    *above = py < line_row();
    return true;
}

/* A picture of grazing at the default size, 800 x 600, read back. */
static Image read_grazing_png(const char *path)
{
    Image im = read_png(path);
    expect_count(800, im.width, "picture width");
    expect_count(600, im.height, "picture height");
    return im;
}

/* grazing at the default size, its --id-out, with the given extra flags. */
static Image render_id(const char *name, const char *flag, const char *value)
{
    const char *dir = test_dir(name);
    Path out = in_dir(dir, "id.png"), picture = in_dir(dir, "picture.png");
    const char *args[] = {"--scene", "grazing", "--id-out", out.path, "--out", picture.path,
                          flag,      value,     NULL};
    free(run_ok(PROGRAM, args));
    return read_grazing_png(out.path);
}

/* The test's own count of its pixels, so that a change of scene shows here
 * first: the numbers of the comment above. */
static void tested_pixels_are_as_derived(void **state)
{
    (void)state;
    long above = 0, below = 0, wrong = 0;
    for (int y = 0; y < 600; y++)
        for (int x = 0; x < 800; x++) {
            bool a;
            if (!tested_pixel(x, y, &a))
                continue;
            above += a;
            below += !a;
            double py = y + 0.5;
            wrong += py > naive_line_row() && py < line_row();
        }
    expect_count(TESTED_ABOVE, above, "tested pixels above the line");
    expect_count(TESTED_BELOW, below, "tested pixels below the line");
    expect_count(TESTED_PIXELS, above + below, "tested pixels");
    expect_count(NAIVE_WRONG, wrong, "tested pixels between the two lines");
}

/* Perspective (the default): every tested pixel shows the strip in front of
 * it, A above the line, B below. */
static void perspective_rule_puts_the_seam_on_the_line(void **state)
{
    (void)state;
    Image im = render_id("03_grazing_perspective", "--depth-interp", "perspective");
    for (int y = 0; y < 600; y++)
        for (int x = 0; x < 800; x++) {
            bool above;
            if (!tested_pixel(x, y, &above))
                continue;
            int32_t want = above ? STRIP_A : STRIP_B;
            if (face_at(&im, x, y) != want)
                fail_msg("pixel (%d,%d), %.2f rows %s the line where the strips meet (row "
                         "%.3f): face %d shows, strip %c is in front", x, y,
                         fabs(y + 0.5 - line_row()), above ? "above" : "below", line_row(),
                         face_at(&im, x, y), 'A' + want);
        }
    image_free(&im);
}

/* Naive: exactly the tested pixels between row 335.226 and the line are
 * wrong (strip B instead of A), NAIVE_WRONG of them; all others are right. */
static void naive_rule_puts_the_seam_55_rows_too_high(void **state)
{
    (void)state;
    Image im = render_id("03_grazing_naive", "--depth-interp", "naive");
    long wrong = 0;
    for (int y = 0; y < 600; y++)
        for (int x = 0; x < 800; x++) {
            bool above;
            if (!tested_pixel(x, y, &above))
                continue;
            double py = y + 0.5;
            bool between = py > naive_line_row() && py < line_row();
            int32_t right = above ? STRIP_A : STRIP_B;
            int32_t want = between ? STRIP_B : right;
            if (face_at(&im, x, y) != want)
                fail_msg("naive rule, pixel (%d,%d): face %d shows; by the naive depths of "
                         "the comment (seam at row %.3f) it should be strip %c", x, y,
                         face_at(&im, x, y), naive_line_row(), 'A' + want);
            wrong += face_at(&im, x, y) != right;
        }
    printf("  the naive rule shows the wrong strip at %ld of the %d tested pixels\n", wrong,
           TESTED_PIXELS);
    expect_count(NAIVE_WRONG, wrong, "pixels the naive rule gets wrong");
    image_free(&im);
}

/* --compare-naive marks (magenta) every tested pixel the naive rule gets
 * wrong and none it gets right, and the count it prints is the number of
 * marked pixels in its picture. */
static void compare_naive_marks_the_pixels_the_naive_rule_gets_wrong(void **state)
{
    (void)state;
    const char *dir = test_dir("03_grazing_compare");
    char out[4096], cmp[4096];
    snprintf(out, sizeof out, "%s", path_join(dir, "right.png"));
    snprintf(cmp, sizeof cmp, "%s", path_join(dir, "sub/compare.png"));
    const char *args[] = {"--out", out, "--compare-naive", cmp, NULL};
    char *summary = run_ok(PROGRAM, args);
    Image im = read_grazing_png(cmp);
    long marked = 0;
    for (int y = 0; y < 600; y++)
        for (int x = 0; x < 800; x++) {
            Rgb c = image_get(&im, x, y);
            bool is_marked = c.r == 255 && c.g == 0 && c.b == 255;
            marked += is_marked;
            bool above;
            if (!tested_pixel(x, y, &above))
                continue;
            double py = y + 0.5;
            bool naive_wrong = py > naive_line_row() && py < line_row();
            if (is_marked != naive_wrong)
                fail_msg("--compare-naive: pixel (%d,%d) is %smarked, but the naive rule gets "
                         "it %s", x, y, is_marked ? "" : "not ", naive_wrong ? "wrong" : "right");
        }
    char line[128];
    snprintf(line, sizeof line, "  the naive rule shows another face at %ld pixels\n", marked);
    if (!strstr(summary, line))
        fail_msg("the summary should say\n%sit says\n%s", line, summary);
    expect_at_least(NAIVE_WRONG, marked, "marked pixels");
    free(summary);
    image_free(&im);
}

/* --bug negated-w: the buffer holds -d, so the farther strip wins every
 * tested pixel: B above the line, A below. */
static void negated_w_shows_the_farther_strip_everywhere(void **state)
{
    (void)state;
    Image im = render_id("03_grazing_bug", "--bug", "negated-w");
    for (int y = 0; y < 600; y++)
        for (int x = 0; x < 800; x++) {
            bool above;
            if (!tested_pixel(x, y, &above))
                continue;
            int32_t farther = above ? STRIP_B : STRIP_A;
            if (face_at(&im, x, y) != farther)
                fail_msg("--bug negated-w, pixel (%d,%d): face %d shows; with -d stored the "
                         "farther strip %c should", x, y, face_at(&im, x, y), 'A' + farther);
        }
    image_free(&im);
}

/* --depth-out against the ray-plane intersection. With --fovy 90 (f = 1) every
 * corner of grazing lands exactly on the 1/256-pixel grid (rows 400, 301.5,
 * 370.3125, 306; columns 400 +- 200, 3, 112.5, 2.25), so snapping moves
 * nothing and the depths are exact up to rounding. The row with centre py sees
 * A at d = 150 / u and B at d = 131.25 / (u - 4.6875), u = py - 300; they meet
 * at row 337.5. */
static void depth_out_is_where_the_ray_meets_the_plane(void **state)
{
    (void)state;
    const char *dir = test_dir("03_grazing_depth");
    char pfm[4096], png[4096];
    snprintf(pfm, sizeof pfm, "%s", path_join(dir, "depth.pfm"));
    snprintf(png, sizeof png, "%s", path_join(dir, "pic.png"));
    const char *args[] = {"--fovy", "90", "--depth-out", pfm, "--out", png, NULL};
    free(run_ok(PROGRAM, args));
    float *depth;
    int w, h;
    Error err;
    if (!read_pfm(&depth, &w, &h, pfm, &err))
        fail_msg("%s", err.msg);
    expect_count(800, w, "depth picture width");
    expect_count(600, h, "depth picture height");
    /* Pixels on A above the line, on B below it (inside B's outline: B's
     * half-width there is 225 / d), and on A beside and in front of B. */
    const struct { int x, y; char strip; } at[7] = {
        {400, 302, 'A'}, {410, 310, 'A'}, {400, 320, 'A'}, {380, 335, 'A'},
        {400, 360, 'B'}, {450, 365, 'B'}, {300, 380, 'A'}};
    for (int k = 0; k < 7; k++) {
        double u = at[k].y + 0.5 - 300;
        double want = at[k].strip == 'A' ? 150 / u : 131.25 / (u - 4.6875);
        double got = depth[at[k].y * 800 + at[k].x];
        observe_near(got, want, 1e-5 * want);
        if (!(fabs(got - want) <= 1e-5 * want))
            fail_msg("--depth-out at pixel (%d,%d): %.9g; the ray meets strip %c at d = %.9g "
                     "(relative error %.2g, allowed 1e-5)", at[k].x, at[k].y, got, at[k].strip,
                     want, fabs(got - want) / want);
    }
    assert_true(isinf(depth[10 * 800 + 10]) && depth[10 * 800 + 10] > 0); /* the sky */
    free(depth);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(tested_pixels_are_as_derived),
        cmocka_unit_test(perspective_rule_puts_the_seam_on_the_line),
        cmocka_unit_test(naive_rule_puts_the_seam_55_rows_too_high),
        cmocka_unit_test(compare_naive_marks_the_pixels_the_naive_rule_gets_wrong),
        cmocka_unit_test(negated_w_shows_the_farther_strip_everywhere),
        cmocka_unit_test(depth_out_is_where_the_ray_meets_the_plane),
    };
    return cmocka_run_group_tests_name("03_perspective_z grazing", tests, NULL, NULL);
}
