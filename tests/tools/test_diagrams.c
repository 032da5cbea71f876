/* test_diagrams.c: tools/diagrams draws the pictures of docs/02 to 04 at their
 * documented sizes, and they say what the lessons do:
 *   - each pixel centre of the edge-function grid is a dot in the colour of
 *     the triangle that build/bin/02_zbuffer gives the pixel (--id-out of the
 *     same two triangles), or hollow where it draws neither;
 *   - each pixel centre of the edge-walk grid is filled exactly where
 *     build/bin/04_scanline_inverse_z draws the same hexagon, in the span's
 *     colour on row 5;
 *   - in the depth plot the 1/d line is straight (within a pixel) and d is not.
 * Positions and colours are the ones tools/diagrams.c marks "read by the test". */
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
#include "test_support.h"

typedef struct { double x, y; } Point;

static const Rgb HOLLOW = {150, 154, 166};
static const Rgb A_DOT = {255, 150, 50};
static const Rgb B_DOT = {80, 170, 255};
static const Rgb INV_D_COLOUR = {90, 220, 255};
static const Rgb D_COLOUR = {255, 150, 50};
static const Rgb IN_DOT = {235, 235, 245};
static const Rgb SPAN_DOT = {255, 235, 60};

/* 02_edge_functions.png: a 12 x 8 grid, its top-left corner at (60, 56), 40 to a pixel. */
#define E02_LEFT 60
#define E02_TOP 56
#define E02_CELL 40
#define E02_COLS 12
#define E02_ROWS 8
static const Point TRIANGLE_A[3] = {{1.75, 1.0}, {10.75, 1.0}, {9.25, 6.0}};
static const Point TRIANGLE_B[3] = {{1.75, 1.0}, {9.25, 6.0}, {1.25, 7.0}};

/* 04_edge_walk.png: a 12 x 9 grid at (170, 90), 40 to a pixel; the span is row 5. */
#define E04_LEFT 170
#define E04_TOP 90
#define E04_CELL 40
#define E04_COLS 12
#define E04_ROWS 9
#define E04_SPAN_ROW 5
static const Point HEXAGON[6] = {{5.25, 0.75}, {9.5, 2.25}, {10.75, 6.0},
                                 {7.0, 8.25},  {2.25, 7.5}, {1.5, 3.0}};

/* 03_depth_along_a_row.png: the plot's frame. */
#define E03_PLOT_LEFT 100
#define E03_PLOT_RIGHT 700
#define E03_PLOT_TOP 100
#define E03_PLOT_BOTTOM 440

/* 06_depth_curve.png: the main plot's and the zoom's frames, the planes. */
#define E06_LEFT 90
#define E06_RIGHT 520
#define E06_TOP 140
#define E06_BOTTOM 480
#define E06_ZOOM_LEFT 680
#define E06_ZOOM_RIGHT 920
#define E06_NEAR 1.0
#define E06_FAR 100.0
static const Rgb STANDARD_COLOUR = {255, 150, 50};
static const Rgb REVERSED_COLOUR = {90, 220, 255};
static const Rgb CODE_COLOUR = {120, 230, 120};

static bool same(Rgb a, Rgb b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

/* Runs the tool into a fresh directory; returns the directory. */
static const char *draw_diagrams(const char *name)
{
    static char dir[512];
    snprintf(dir, sizeof dir, "%s", test_dir(name));
    const char *args[] = {dir, NULL};
    RunResult r = run_tool("diagrams", args);
    if (r.status != 0)
        fail_msg("diagrams %s: exit status %d: %s", dir, r.status, r.err);
    run_result_free(&r);
    return dir;
}

static void diagrams_are_written_at_their_documented_sizes(void **state)
{
    (void)state;
    const char *dir = draw_diagrams("diagrams_sizes");
    const struct { const char *file; int width, height; } expected[] = {
        {"02_edge_functions.png", 900, 500},
        {"03_depth_along_a_row.png", 820, 520},
        {"04_edge_walk.png", 820, 600},
        {"05_clipping_cases.png", 920, 420},
        {"06_depth_curve.png", 960, 580},
        {"07_bias.png", 940, 520},
        {"08_z_modes.png", 940, 590},
        {"09_tile_bound.png", 940, 560},
        {"10_bins_blocks.png", 940, 600},
    };
    for (size_t i = 0; i < sizeof expected / sizeof expected[0]; i++) {
        Image im = read_png(path_join(dir, expected[i].file));
        if (im.width != expected[i].width || im.height != expected[i].height)
            fail_msg("%s is %d x %d, the tool's header says %d x %d", expected[i].file, im.width,
                     im.height, expected[i].width, expected[i].height);
        image_free(&im);
    }
}

static void diagrams_without_a_directory_is_a_usage_error(void **state)
{
    (void)state;
    const char *none[] = {NULL};
    RunResult r = run_tool("diagrams", none);
    assert_int_equal(r.status, 2);
    assert_non_null(strstr(r.err, "diagrams: error: "));
    run_result_free(&r);
}

/* A face per polygon, screen points (x_s, y_s) of a width x height picture
 * placed on the plane z = 0 seen from (0, 0, 1) with fovy 90:
 * x = (x_s - width / 2) / s, y = (height / 2 - y_s) / s, s = height / 2. */
static void write_obj(const char *path, const Point *const *faces, const int *counts, int nfaces,
                      int width, int height)
{
    char text[4096];
    size_t n = 0;
    double s = height / 2.0;
    for (int f = 0; f < nfaces; f++)
        for (int k = 0; k < counts[f]; k++)
            n += (size_t)snprintf(text + n, sizeof text - n, "v %.17g %.17g 0\n",
                                  (faces[f][k].x - width / 2.0) / s,
                                  (height / 2.0 - faces[f][k].y) / s);
    int first = 1;
    for (int f = 0; f < nfaces; f++) {
        n += (size_t)snprintf(text + n, sizeof text - n, "f");
        for (int k = 0; k < counts[f]; k++)
            n += (size_t)snprintf(text + n, sizeof text - n, " %d", first + k);
        n += (size_t)snprintf(text + n, sizeof text - n, "\n");
        first += counts[f];
    }
    write_text(path, text);
}

/* Each pixel's face + 1 (0: none) as the lesson draws the OBJ. */
static Image lesson_ids(const char *lesson, const char *dir, const char *obj, int width,
                        int height)
{
    char w[16], h[16];
    snprintf(w, sizeof w, "%d", width);
    snprintf(h, sizeof h, "%d", height);
    Path out = in_dir(dir, "render.png"), ids = in_dir(dir, "ids.png");
    const char *args[] = {"--obj", obj, "--width", w, "--height", h, "--eye", "0,0,1",
                          "--target", "0,0,0", "--up", "0,1,0", "--fovy", "90", "--near", "0.5",
                          "--far", "2", "--out", out.path, "--id-out", ids.path, NULL};
    free(run_ok(lesson, args));
    return read_png(ids.path);
}

static int id_at(const Image *ids, int x, int y)
{
    Rgb c = image_get(ids, x, y);
    return (c.r << 16) | (c.g << 8) | c.b;
}

/* The dot of pixel (x, y) of a grid: "filled" in colour, or "hollow". */
static void expect_dot(const Image *im, const char *file, int left, int top, int cell, int x,
                       int y, const Rgb *colour)
{
    int cx = left + x * cell + cell / 2, cy = top + y * cell + cell / 2;
    Rgb centre = image_get(im, cx, cy), rim = image_get(im, cx + 5, cy);
    if (colour && !same(centre, *colour))
        fail_msg("%s: the centre of pixel (%d, %d), at (%d, %d) in the picture, is (%d, %d, %d); "
                 "the lesson covers it, so it should be a dot of (%d, %d, %d)", file, x, y, cx,
                 cy, centre.r, centre.g, centre.b, colour->r, colour->g, colour->b);
    if (!colour && (!same(rim, HOLLOW) || same(centre, HOLLOW) || same(centre, A_DOT) ||
                    same(centre, B_DOT) || same(centre, IN_DOT) || same(centre, SPAN_DOT)))
        fail_msg("%s: the centre of pixel (%d, %d), at (%d, %d) in the picture, should be a "
                 "hollow ring (the lesson draws nothing there): centre (%d, %d, %d), ring "
                 "(%d, %d, %d)", file, x, y, cx, cy, centre.r, centre.g, centre.b, rim.r, rim.g,
                 rim.b);
}

static void edge_function_grid_shows_what_lesson_02_draws(void **state)
{
    (void)state;
    const char *dir = draw_diagrams("diagrams_02");
    Path obj = in_dir(dir, "two_triangles.obj");
    const Point *faces[2] = {TRIANGLE_A, TRIANGLE_B};
    int counts[2] = {3, 3};
    write_obj(obj.path, faces, counts, 2, E02_COLS, E02_ROWS);
    Image ids = lesson_ids("02_zbuffer", dir, obj.path, E02_COLS, E02_ROWS);
    Image im = read_png(path_join(dir, "02_edge_functions.png"));
    int seen[3] = {0};
    for (int y = 0; y < E02_ROWS; y++)
        for (int x = 0; x < E02_COLS; x++) {
            int id = id_at(&ids, x, y);
            assert_in_range(id, 0, 2);
            seen[id]++;
            const Rgb *colour = id == 1 ? &A_DOT : id == 2 ? &B_DOT : NULL;
            expect_dot(&im, "02_edge_functions.png", E02_LEFT, E02_TOP, E02_CELL, x, y, colour);
        }
    /* The shared edge runs through the centre of pixel (5, 3): A's by the top-left rule. */
    assert_int_equal(id_at(&ids, 5, 3), 1);
    if (seen[0] == 0 || seen[1] == 0 || seen[2] == 0)
        fail_msg("the grid should show pixels of A, of B and of neither: %d, %d, %d", seen[1],
                 seen[2], seen[0]);
    image_free(&im);
    image_free(&ids);
}

static void edge_walk_grid_shows_what_lesson_04_draws(void **state)
{
    (void)state;
    const char *dir = draw_diagrams("diagrams_04");
    Path obj = in_dir(dir, "hexagon.obj");
    const Point *faces[1] = {HEXAGON};
    int counts[1] = {6};
    write_obj(obj.path, faces, counts, 1, E04_COLS, E04_ROWS);
    Image ids = lesson_ids("04_scanline_inverse_z", dir, obj.path, E04_COLS, E04_ROWS);
    Image im = read_png(path_join(dir, "04_edge_walk.png"));
    int span = 0;
    for (int y = 0; y < E04_ROWS; y++)
        for (int x = 0; x < E04_COLS; x++) {
            int id = id_at(&ids, x, y);
            assert_in_range(id, 0, 1);
            span += id == 1 && y == E04_SPAN_ROW;
            const Rgb *colour = id == 0 ? NULL : y == E04_SPAN_ROW ? &SPAN_DOT : &IN_DOT;
            expect_dot(&im, "04_edge_walk.png", E04_LEFT, E04_TOP, E04_CELL, x, y, colour);
        }
    assert_int_equal(span, 9); /* centres 2.5 .. 10.5 lie in [1.92, 10.58) */
    image_free(&im);
    image_free(&ids);
}

/* Per column inside the frame, the mean row of the pixels of colour c; NAN where none. */
static int curve_rows(const Image *im, Rgb c, double *rows)
{
    int n = 0;
    for (int x = E03_PLOT_LEFT + 3; x < E03_PLOT_RIGHT - 2; x++) {
        double sum = 0;
        int count = 0;
        for (int y = E03_PLOT_TOP; y < E03_PLOT_BOTTOM - 1; y++)
            if (same(image_get(im, x, y), c)) {
                sum += y;
                count++;
            }
        rows[x] = count ? sum / count : NAN;
        n += count > 0;
    }
    return n;
}

/* The largest distance, in rows, of the curve's columns from the straight
 * line that fits them best (least squares). */
static double largest_distance_from_a_line(const double *rows)
{
    double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (int x = E03_PLOT_LEFT + 3; x < E03_PLOT_RIGHT - 2; x++)
        if (!isnan(rows[x])) {
            n++;
            sx += x;
            sy += rows[x];
            sxx += (double)x * x;
            sxy += x * rows[x];
        }
    double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx), at0 = (sy - slope * sx) / n;
    double worst = 0;
    for (int x = E03_PLOT_LEFT + 3; x < E03_PLOT_RIGHT - 2; x++)
        if (!isnan(rows[x]))
            worst = fmax(worst, fabs(rows[x] - (at0 + slope * x)));
    return worst;
}

static void depth_plot_shows_inverse_depth_straight_and_depth_curved(void **state)
{
    (void)state;
    const char *dir = draw_diagrams("diagrams_03");
    Image im = read_png(path_join(dir, "03_depth_along_a_row.png"));
    double rows[E03_PLOT_RIGHT];
    int columns = curve_rows(&im, INV_D_COLOUR, rows);
    if (columns < 300)
        fail_msg("the 1/d line shows in %d columns of the plot, expected it across most of it",
                 columns);
    double off = largest_distance_from_a_line(rows);
    if (off > 1.0)
        fail_msg("the 1/d line strays %.2f pixels from a straight line (at most 1 allowed)", off);
    curve_rows(&im, D_COLOUR, rows);
    off = largest_distance_from_a_line(rows);
    if (off < 50.0)
        fail_msg("the d curve is within %.2f pixels of a straight line: it should bend", off);
    image_free(&im);
}

/* The mean row of the pixels of colour c in column x, rows top .. bottom; NAN if none. */
static double mean_row(const Image *im, Rgb c, int x, int top, int bottom)
{
    double sum = 0;
    int count = 0;
    for (int y = top; y <= bottom; y++)
        if (same(image_get(im, x, y), c))
            sum += y, count++;
    return count ? sum / count : NAN;
}

/* The curves follow docs/conventions.md's mappings, computed here from the
 * page's formulas: z_w = f/(f-n) (1 - n/d) and n/(f-n) (f/d - 1), n = 1,
 * f = 100; the zoom steps once per unorm16 code between d = 90 and 92. */
static void depth_curve_follows_both_mappings_and_steps_per_code(void **state)
{
    (void)state;
    const char *dir = draw_diagrams("diagrams_06");
    Image im = read_png(path_join(dir, "06_depth_curve.png"));
    double n = E06_NEAR, f = E06_FAR, worst = 0;
    int checked = 0;
    for (int x = E06_LEFT + 10; x < E06_RIGHT - 4; x++) {
        double d = (x + 0.5 - E06_LEFT) / (E06_RIGHT - E06_LEFT) * f;
        if (d < 4)
            continue; /* where the two curves cross */
        double zs = f / (f - n) * (1 - n / d), zr = n / (f - n) * (f / d - 1);
        double ys = mean_row(&im, STANDARD_COLOUR, x, E06_TOP - 4, E06_BOTTOM);
        double yr = mean_row(&im, REVERSED_COLOUR, x, E06_TOP - 4, E06_BOTTOM);
        double want_s = E06_BOTTOM - zs * (E06_BOTTOM - E06_TOP);
        double want_r = E06_BOTTOM - zr * (E06_BOTTOM - E06_TOP);
        if (isnan(ys) || isnan(yr))
            fail_msg("column %d (d = %.2f): a curve is missing", x, d);
        worst = fmax(worst, fmax(fabs(ys + 0.5 - want_s), fabs(yr + 0.5 - want_r)));
        checked++;
    }
    if (worst > 2.0)
        fail_msg("the curves stray %.2f rows from the mappings' formulas (at most 2)", worst);
    if (checked < 300)
        fail_msg("only %d columns checked", checked);

    /* The zoom: the level of each column's step (a column where the code
     * colour runs taller than a step's line is a rise: skipped), counted
     * where it changes; the codes from the formula. */
    int steps = 0, codes = 0;
    double last_row = NAN, last_code = NAN;
    for (int x = E06_ZOOM_LEFT + 2; x < E06_ZOOM_RIGHT - 2; x++) {
        int top = -1, bottom = -1;
        for (int y = E06_TOP - 4; y <= E06_BOTTOM; y++)
            if (same(image_get(&im, x, y), CODE_COLOUR))
                bottom = y, top = top < 0 ? y : top;
        double row = top >= 0 && bottom - top <= 4 ? (top + bottom) / 2.0 : NAN;
        if (!isnan(row) && (isnan(last_row) || fabs(row - last_row) > 2))
            steps++;
        if (!isnan(row))
            last_row = row;
        double d = 90 + 2.0 * (x + 0.5 - E06_ZOOM_LEFT) / (E06_ZOOM_RIGHT - E06_ZOOM_LEFT);
        double code = nearbyint(f / (f - n) * (1 - n / d) * 65535.0);
        codes += code != last_code;
        last_code = code;
    }
    if (abs(steps - codes) > 1)
        fail_msg("the zoom shows %d steps; unorm16 has %d codes between d = 90 and 92", steps,
                 codes);
    image_free(&im);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(diagrams_are_written_at_their_documented_sizes),
        cmocka_unit_test(diagrams_without_a_directory_is_a_usage_error),
        cmocka_unit_test(edge_function_grid_shows_what_lesson_02_draws),
        cmocka_unit_test(edge_walk_grid_shows_what_lesson_04_draws),
        cmocka_unit_test(depth_plot_shows_inverse_depth_straight_and_depth_curved),
        cmocka_unit_test(depth_curve_follows_both_mappings_and_steps_per_code),
    };
    return cmocka_run_group_tests_name("tools: diagrams", tests, NULL, NULL);
}
