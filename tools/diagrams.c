/* diagrams: the explanatory pictures of the lessons, drawn by code.
 *
 *   diagrams DIR
 *
 * writes these PNGs into DIR (which must exist):
 *   02_edge_functions.png    900 x 500  a 12 x 8 pixel grid, 40 pixels to a pixel:
 *                            triangle A with its edge functions' signs, its
 *                            neighbour B, every pixel centre in or out, and the
 *                            centres on the shared edge that the top-left rule
 *                            gives to A
 *   03_depth_along_a_row.png 820 x 520  d and 1/d of one grazing strip along a
 *                            screen row: d curved, 1/d straight, naive d dashed
 *   04_edge_walk.png         820 x 600  a convex polygon on a 12 x 9 grid, its left
 *                            and right edges crossing each row centre, and the
 *                            span of row 5
 *   05_clipping_cases.png    920 x 420  a triangle against the near plane, seen
 *                            from above, with 3, 2, 1 and 0 corners in front:
 *                            what is drawn and its corners (the test clips the
 *                            same triangles with lesson 05's clip_to_plane)
 *   06_depth_curve.png       960 x 580  window depth z_w against view depth d,
 *                            near 1, far 100, in the standard and the reversed
 *                            mapping (docs/conventions.md), and a zoom on d from
 *                            90 to 92 with the unorm16 codes stored there
 *   07_bias.png              940 x 520  a decal's fragments against its wall along a
 *                            row, facing the camera and grazing, with units only
 *                            and with factor and units: which win
 *   08_z_modes.png           940 x 590  the stages of a fragment in each --z-mode
 *                            of lesson 08: late, early, the pre-pass's two passes
 *   09_tile_bound.png        940 x 560  one row over two tiles of 8 pixels: the
 *                            buffer, each tile's farthest value, and a
 *                            triangle's plane whose nearest value skips one tile
 *   10_bins_blocks.png       940 x 600  a triangle over 2 x 2 tiles of 64 pixels:
 *                            its blocks of 8 x 8 inside every edge or crossed by
 *                            one, and one block's mask, a row of it one register
 * Exit status: 0 written, 1 could not write, 2 bad usage.
 *
 * Coverage is decided by the lessons' rule, exactly: corners snapped to 1/256
 * pixel, integer arithmetic, the top-left rule, here in its scanline form
 * (docs/04_scanline_inverse_z.md), which covers the same pixels as lesson
 * 02's edge functions. tests/tools/test_diagrams.c draws the same shapes with
 * build/bin/02_zbuffer and 04_scanline_inverse_z and reads the pictures back:
 * what it reads (grid positions, dot colours, the plot's frame and the 1/d
 * colour) is marked "read by the test" below; the depth curves it checks
 * against the mappings' formulas. */
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "harness/file.h"
#include "harness/font.h"
#include "harness/image_io.h"

#define PROGRAM "diagrams"

/* ---- Colours ---------------------------------------------------------------- */

static const Rgb BACKGROUND = {24, 28, 40};
static const Rgb GRID_LINE = {62, 68, 86};
static const Rgb TEXT = {230, 230, 230};
static const Rgb DIM_TEXT = {170, 174, 186};
static const Rgb LABEL_BOX = {10, 12, 18};
static const Rgb HOLLOW = {150, 154, 166};         /* a centre outside: a ring (read by the test) */
static const Rgb A_DOT = {255, 150, 50};           /* a centre in A (read by the test) */
static const Rgb A_CELL = {92, 62, 40};
static const Rgb B_DOT = {80, 170, 255};           /* a centre in B (read by the test) */
static const Rgb B_CELL = {38, 64, 100};
static const Rgb SHARED_MARK = {255, 235, 60};
static const Rgb D_COLOUR = {255, 150, 50};
static const Rgb INV_D_COLOUR = {90, 220, 255};    /* the 1/d line (read by the test) */
static const Rgb NAIVE_COLOUR = {200, 200, 200};
static const Rgb AXIS_COLOUR = {200, 200, 210};
static const Rgb POLY_CELL = {50, 60, 90};
static const Rgb IN_DOT = {235, 235, 245};         /* a centre in the polygon (read by the test) */
static const Rgb SPAN_CELL = {120, 100, 30};
static const Rgb SPAN_DOT = {255, 235, 60};        /* a centre in the span (read by the test) */
static const Rgb LEFT_COLOUR = {110, 230, 120};
static const Rgb RIGHT_COLOUR = {255, 110, 200};
static const Rgb TILE_LINE = {235, 235, 245};
static const Rgb LANE_COLOUR = {255, 235, 60}; /* a tile's farthest (09), a block's row (10) */

/* ---- Drawing ------------------------------------------------------------------ */

#define TEXT_SCALE 2      /* labels: the 5 x 7 font at twice its size */
#define MAX_LABEL 96      /* characters in one label line */

static void put(Image *im, int x, int y, Rgb c)
{
    if (x >= 0 && y >= 0 && x < im->width && y < im->height)
        image_set(im, x, y, c);
}

static void fill_rect(Image *im, int x0, int y0, int x1, int y1, Rgb c)
{
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++)
            put(im, x, y, c);
}

/* The text at scale times the font's size; (x, y) is its top-left pixel. */
static void text_at(Image *im, int x, int y, const char *text, int scale, Rgb c)
{
    if (scale == 1) {
        draw_text(im, x, y, text, c);
        return;
    }
    uint8_t pixels[FONT_LINE_HEIGHT * MAX_LABEL * FONT_ADVANCE * 3] = {0};
    Image glyphs = {MAX_LABEL * FONT_ADVANCE, FONT_LINE_HEIGHT, pixels};
    char line[MAX_LABEL + 1];
    snprintf(line, sizeof line, "%s", text);
    draw_text(&glyphs, 0, 0, line, (Rgb){255, 255, 255});
    for (int gy = 0; gy < glyphs.height; gy++)
        for (int gx = 0; gx < glyphs.width; gx++)
            if (image_get(&glyphs, gx, gy).r)
                fill_rect(im, x + gx * scale, y + gy * scale, x + (gx + 1) * scale,
                          y + (gy + 1) * scale, c);
}

static int scaled_width(const char *text, int scale) { return text_width(text) * scale; }
static int scaled_height(int scale) { return FONT_GLYPH_HEIGHT * scale; }

/* A label on a dark box, so that it reads over grid lines and edges. */
static void boxed_text(Image *im, int x, int y, const char *text, Rgb c)
{
    int pad = 3;
    fill_rect(im, x - pad, y - pad, x + scaled_width(text, TEXT_SCALE) + pad,
              y + scaled_height(TEXT_SCALE) + pad, LABEL_BOX);
    text_at(im, x, y, text, TEXT_SCALE, c);
}

/* The same, centred on (cx, cy). */
static void boxed_text_centred(Image *im, double cx, double cy, const char *text, Rgb c)
{
    boxed_text(im, (int)lround(cx - scaled_width(text, TEXT_SCALE) / 2.0),
               (int)lround(cy - scaled_height(TEXT_SCALE) / 2.0), text, c);
}

static double segment_distance(double px, double py, double ax, double ay, double bx, double by,
                               double *t_out)
{
    double dx = bx - ax;
    double dy = by - ay;
    double len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / len2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    if (t_out)
        *t_out = t;
    double qx = ax + t * dx - px, qy = ay + t * dy - py;
    return sqrt(qx * qx + qy * qy);
}

/* Every pixel whose centre lies within half_width of the segment (picture
 * coordinates, pixel (x, y) spanning [x, x + 1)); dash > 0 leaves gaps of that
 * length between dashes of that length. */
static void line(Image *im, double ax, double ay, double bx, double by, double half_width,
                 double dash, Rgb c)
{
    int x0 = (int)floor(fmin(ax, bx) - half_width), x1 = (int)ceil(fmax(ax, bx) + half_width);
    int y0 = (int)floor(fmin(ay, by) - half_width), y1 = (int)ceil(fmax(ay, by) + half_width);
    double len = hypot(bx - ax, by - ay);
    for (int y = y0; y <= y1; y++)
        for (int x = x0; x <= x1; x++) {
            double t;
            if (segment_distance(x + 0.5, y + 0.5, ax, ay, bx, by, &t) > half_width)
                continue;
            if (dash > 0 && fmod(t * len, 2 * dash) >= dash)
                continue;
            put(im, x, y, c);
        }
}

/* Pixels whose centres are between r_in and r_out from (cx, cy). */
static void ring(Image *im, double cx, double cy, double r_in, double r_out, Rgb c)
{
    for (int y = (int)floor(cy - r_out); y <= (int)ceil(cy + r_out); y++)
        for (int x = (int)floor(cx - r_out); x <= (int)ceil(cx + r_out); x++) {
            double r = hypot(x + 0.5 - cx, y + 0.5 - cy);
            if (r <= r_out && r >= r_in)
                put(im, x, y, c);
        }
}

static void disc(Image *im, double cx, double cy, double r, Rgb c) { ring(im, cx, cy, 0, r, c); }

/* A filled arrowhead with its tip at (x, y), pointing along (dx, dy). */
static void arrowhead(Image *im, double x, double y, double dx, double dy, double size, Rgb c)
{
    double len = hypot(dx, dy);
    dx /= len;
    dy /= len;
    double bx = x - dx * size, by = y - dy * size; /* the middle of its base */
    double p[3][2] = {{x, y}, {bx - dy * size * 0.5, by + dx * size * 0.5},
                      {bx + dy * size * 0.5, by - dx * size * 0.5}};
    for (int py = (int)floor(y - size) - 1; py <= (int)ceil(y + size) + 1; py++)
        for (int px = (int)floor(x - size) - 1; px <= (int)ceil(x + size) + 1; px++) {
            double qx = px + 0.5, qy = py + 0.5;
            int sign = 0;
            for (int k = 0; k < 3; k++) {
                const double *a = p[k], *b = p[(k + 1) % 3];
                double e = (b[0] - a[0]) * (qy - a[1]) - (b[1] - a[1]) * (qx - a[0]);
                sign += e >= 0 ? 1 : -1;
            }
            if (sign == 3 || sign == -3)
                put(im, px, py, c);
        }
}

/* ---- The lessons' fill rule, in its scanline form ----------------------------- */

/* docs/04_scanline_inverse_z.md: a row y is drawn when its centre y + 0.5 is
 * in [top, bottom), a pixel x of it when its centre x + 0.5 is in
 * [left, right), the two edges' x on that row. It is the top-left rule of
 * lessons 02 and 03 said another way, and covers the same pixels; it is
 * written here afresh, not copied from a lesson, so that a student's handout
 * of a lesson (which holds tools/) does not hold that lesson's solution. */

#define SUBPIXEL_ONE 256 /* corners snapped to 1/256 of a pixel, as the lessons do */
#define SUBPIXEL_HALF (SUBPIXEL_ONE / 2)

typedef struct { int64_t x, y; } FixedPoint;
typedef struct { double x, y; } Point; /* screen pixels, y down */

static FixedPoint snap_to_fixed(Point p)
{
    return (FixedPoint){(int64_t)floor(p.x * SUBPIXEL_ONE + 0.5),
                        (int64_t)floor(p.y * SUBPIXEL_ONE + 0.5)};
}

static FixedPoint centre_of(int x, int y)
{
    return (FixedPoint){(int64_t)x * SUBPIXEL_ONE + SUBPIXEL_HALF,
                        (int64_t)y * SUBPIXEL_ONE + SUBPIXEL_HALF};
}

/* Is the centre of pixel (x, y) in the convex polygon, corners clockwise on
 * the screen? Going clockwise, an edge that runs down the screen is on the
 * right side, one that runs up on the left; each tests the rows whose centres
 * are in [its upper end, its lower end), exactly, in integers. */
static bool covers(const Point *corner, int n, int x, int y)
{
    FixedPoint c = centre_of(x, y);
    int64_t top = INT64_MAX, bottom = INT64_MIN;
    for (int k = 0; k < n; k++) {
        FixedPoint a = snap_to_fixed(corner[k]), b = snap_to_fixed(corner[(k + 1) % n]);
        top = a.y < top ? a.y : top;
        bottom = a.y > bottom ? a.y : bottom;
        if (a.y == b.y)
            continue; /* horizontal: [top, bottom) decides */
        FixedPoint upper = a.y < b.y ? a : b, lower = a.y < b.y ? b : a;
        if (c.y < upper.y || c.y >= lower.y)
            continue;
        /* The edge's x on this row is upper.x + (c.y - upper.y) * run / rise;
         * compared with c.x without dividing (rise > 0). */
        int64_t rise = lower.y - upper.y, run = lower.x - upper.x;
        int64_t centre_side = (c.x - upper.x) * rise, edge_side = (c.y - upper.y) * run;
        bool right_side = b.y > a.y;
        if (right_side ? centre_side >= edge_side : centre_side < edge_side)
            return false;
    }
    return top <= c.y && c.y < bottom;
}

/* Is the centre of pixel (x, y) exactly on the segment a-b, between its ends? */
static bool centre_on_edge(Point a, Point b, int x, int y)
{
    FixedPoint fa = snap_to_fixed(a), fb = snap_to_fixed(b), c = centre_of(x, y);
    FixedPoint along = {fb.x - fa.x, fb.y - fa.y}, to_c = {c.x - fa.x, c.y - fa.y};
    if (along.x * to_c.y != along.y * to_c.x)
        return false; /* not on the line */
    int64_t dot = to_c.x * along.x + to_c.y * along.y;
    return dot > 0 && dot < along.x * along.x + along.y * along.y;
}

/* ---- A magnified pixel grid ----------------------------------------------------- */

typedef struct {
    Image *im;
    int left, top;  /* picture position of the grid's top-left corner */
    int cell;       /* picture pixels per screen pixel */
    int cols, rows;
} Grid;

static double gx(const Grid *g, double x) { return g->left + x * g->cell; }
static double gy(const Grid *g, double y) { return g->top + y * g->cell; }

static void grid_cells_and_lines(const Grid *g, Rgb (*cell_colour)(int x, int y, const void *),
                                 const void *ctx)
{
    for (int y = 0; y < g->rows; y++)
        for (int x = 0; x < g->cols; x++)
            fill_rect(g->im, (int)gx(g, x), (int)gy(g, y), (int)gx(g, x + 1), (int)gy(g, y + 1),
                      cell_colour(x, y, ctx));
    for (int x = 0; x <= g->cols; x++)
        fill_rect(g->im, (int)gx(g, x), g->top, (int)gx(g, x) + 1, (int)gy(g, g->rows) + 1,
                  GRID_LINE);
    for (int y = 0; y <= g->rows; y++)
        fill_rect(g->im, g->left, (int)gy(g, y), (int)gx(g, g->cols) + 1, (int)gy(g, y) + 1,
                  GRID_LINE);
}

#define DOT_RADIUS 6.5
#define RING_WIDTH 2.0

/* Pixel (x, y)'s centre: a filled dot, or an empty ring when colour is NULL. */
static void centre_dot(const Grid *g, int x, int y, const Rgb *colour)
{
    double cx = gx(g, x + 0.5), cy = gy(g, y + 0.5);
    if (colour) {
        disc(g->im, cx, cy, DOT_RADIUS + 1.5, LABEL_BOX);
        disc(g->im, cx, cy, DOT_RADIUS, *colour);
    } else {
        disc(g->im, cx, cy, DOT_RADIUS, BACKGROUND); /* empty, even where an edge passes */
        ring(g->im, cx, cy, DOT_RADIUS - RING_WIDTH, DOT_RADIUS, HOLLOW);
    }
}

static void grid_edge(const Grid *g, Point a, Point b, Rgb c)
{
    line(g->im, gx(g, a.x), gy(g, a.y), gx(g, b.x), gy(g, b.y), 1.6, 0, c);
}

/* A legend line: a swatch drawn by the caller at (x, y + 7), then the text. */
static void legend_text(Image *im, int x, int y, const char *text)
{
    text_at(im, x + 34, y, text, TEXT_SCALE, TEXT);
}

/* ---- 02: edge functions and the top-left rule --------------------------------- */

#define E02_WIDTH 900
#define E02_HEIGHT 500
#define E02_COLS 12
#define E02_ROWS 8
#define E02_CELL 40   /* read by the test */
#define E02_LEFT 60   /* read by the test */
#define E02_TOP 56    /* read by the test */

/* The two triangles, clockwise on the screen (read by the test, which draws
 * them with lesson 02). They share the edge s0-s1, which runs through the
 * centres of pixels (2, 1), (5, 3) and (8, 5). */
static const Point S0 = {1.75, 1.0}, S1 = {9.25, 6.0};
static const Point A_THIRD = {10.75, 1.0}, B_THIRD = {1.25, 7.0};

typedef struct { Point a[3], b[3]; } TwoTriangles;

static Rgb e02_cell(int x, int y, const void *ctx)
{
    const TwoTriangles *t = ctx;
    return covers(t->a, 3, x, y) ? A_CELL : covers(t->b, 3, x, y) ? B_CELL : BACKGROUND;
}

/* A square outline, 3 pixels thick, around (cx, cy): a centre on the shared edge. */
static void square_mark(Image *im, double cx, double cy, double half)
{
    for (int w = 0; w < 3; w++) {
        double h = half + w;
        line(im, cx - h, cy - h, cx + h, cy - h, 0.5, 0, SHARED_MARK);
        line(im, cx - h, cy + h, cx + h, cy + h, 0.5, 0, SHARED_MARK);
        line(im, cx - h, cy - h, cx - h, cy + h, 0.5, 0, SHARED_MARK);
        line(im, cx + h, cy - h, cx + h, cy + h, 0.5, 0, SHARED_MARK);
    }
}

/* An arrow on edge a->b of triangle A, a fraction at along it: the direction of the walk. */
static void e02_edge_arrow(const Grid *g, Point a, Point b, double at)
{
    double x = gx(g, a.x + (b.x - a.x) * at), y = gy(g, a.y + (b.y - a.y) * at);
    arrowhead(g->im, x, y, b.x - a.x, b.y - a.y, 16, A_DOT);
}

static void draw_edge_functions(Image *im)
{
    image_fill(im, BACKGROUND);
    Grid g = {im, E02_LEFT, E02_TOP, E02_CELL, E02_COLS, E02_ROWS};
    /* A = p0 p1 p2: e0 = E(p1, p2, p), e1 = E(p2, p0, p), e2 = E(p0, p1, p). */
    TwoTriangles t = {{S0, A_THIRD, S1}, {S0, S1, B_THIRD}};
    const Point *p = t.a;

    text_at(im, E02_LEFT, 14, "Which pixels a triangle covers: 12 x 8 pixels, 40 x enlarged",
            TEXT_SCALE, TEXT);
    grid_cells_and_lines(&g, e02_cell, &t);
    for (int k = 0; k < 3; k++)
        grid_edge(&g, t.b[k], t.b[(k + 1) % 3], B_DOT);
    for (int k = 0; k < 3; k++)
        grid_edge(&g, p[k], p[(k + 1) % 3], A_DOT);
    e02_edge_arrow(&g, p[1], p[2], 0.55); /* E0 */
    e02_edge_arrow(&g, p[2], p[0], 0.30); /* E1: the shared edge, between its centres */
    e02_edge_arrow(&g, p[0], p[1], 0.62); /* E2 */

    for (int y = 0; y < E02_ROWS; y++)
        for (int x = 0; x < E02_COLS; x++) {
            bool in_a = covers(t.a, 3, x, y), in_b = covers(t.b, 3, x, y);
            centre_dot(&g, x, y, in_a ? &A_DOT : in_b ? &B_DOT : NULL);
            if (centre_on_edge(S0, S1, x, y)) {
                double cx = gx(&g, x + 0.5), cy = gy(&g, y + 0.5);
                square_mark(im, cx, cy, 13);
                const char *who = in_a ? "A wins" : in_b ? "B wins" : "neither";
                /* Under it, on B's side, between the rows of dots. */
                boxed_text_centred(im, gx(&g, x - 0.5), gy(&g, y + 1), who, SHARED_MARK);
            }
        }

    /* The signs of A's edge functions, each beside its edge, on grid lines
     * (between the rows of dots). */
    boxed_text_centred(im, gx(&g, 7.0), gy(&g, 0), "E2 < 0", A_DOT);
    boxed_text_centred(im, gx(&g, 7.0), gy(&g, 2), "E2 > 0", A_DOT);
    boxed_text_centred(im, gx(&g, 8.7), gy(&g, 4), "E0 > 0", A_DOT);
    boxed_text_centred(im, gx(&g, 11.2), gy(&g, 3), "E0 < 0", A_DOT);
    boxed_text_centred(im, gx(&g, 6.0), gy(&g, 3), "E1 > 0", A_DOT);
    boxed_text_centred(im, gx(&g, 2.2), gy(&g, 3), "E1 < 0", A_DOT);
    boxed_text_centred(im, gx(&g, 1.1), gy(&g, 1), "p0", A_DOT);
    boxed_text_centred(im, gx(&g, 11.4), gy(&g, 1), "p1", A_DOT);
    boxed_text_centred(im, gx(&g, 9.9), gy(&g, 6), "p2", A_DOT);
    boxed_text_centred(im, gx(&g, 9.0), gy(&g, 3), "A", A_DOT);
    boxed_text_centred(im, gx(&g, 2.5), gy(&g, 6), "B", B_DOT);

    /* The legend, right of the grid and under it. */
    int lx = E02_LEFT + E02_COLS * E02_CELL + 24, ly = E02_TOP + 4;
    text_at(im, lx, ly, "A = p0 p1 p2, clockwise:", TEXT_SCALE, TEXT);
    text_at(im, lx, ly + 22, "E0 = E(p1, p2, p)", TEXT_SCALE, A_DOT);
    text_at(im, lx, ly + 44, "E1 = E(p2, p0, p)", TEXT_SCALE, A_DOT);
    text_at(im, lx, ly + 66, "E2 = E(p0, p1, p)", TEXT_SCALE, A_DOT);
    text_at(im, lx, ly + 96, "The arrows walk each", TEXT_SCALE, DIM_TEXT);
    text_at(im, lx, ly + 118, "edge; E > 0 on its", TEXT_SCALE, DIM_TEXT);
    text_at(im, lx, ly + 140, "right: the inside.", TEXT_SCALE, DIM_TEXT);
    text_at(im, lx, ly + 170, "Shared edge p2->p0:", TEXT_SCALE, TEXT);
    text_at(im, lx, ly + 192, "a left edge of A (in),", TEXT_SCALE, DIM_TEXT);
    text_at(im, lx, ly + 214, "a right edge of B (out)", TEXT_SCALE, DIM_TEXT);

    int y0 = E02_TOP + E02_ROWS * E02_CELL + 28;
    disc(im, E02_LEFT + 10, y0 + 7, DOT_RADIUS, A_DOT);
    legend_text(im, E02_LEFT, y0, "centre inside A: the pixel is A's");
    disc(im, E02_LEFT + 10, y0 + 31, DOT_RADIUS, B_DOT);
    legend_text(im, E02_LEFT, y0 + 24, "centre inside B: the pixel is B's");
    ring(im, E02_LEFT + 10, y0 + 55, DOT_RADIUS - RING_WIDTH, DOT_RADIUS, HOLLOW);
    legend_text(im, E02_LEFT, y0 + 48, "centre outside both: not drawn");
    square_mark(im, E02_LEFT + 10, y0 + 79, 10);
    legend_text(im, E02_LEFT, y0 + 72,
                "centre on the shared edge: the top-left rule picks one");
}

/* ---- 03: d and 1/d along a screen row ------------------------------------------ */

#define E03_WIDTH 820
#define E03_HEIGHT 520
#define E03_PLOT_LEFT 100   /* the plot's frame (read by the test) */
#define E03_PLOT_RIGHT 700
#define E03_PLOT_TOP 100
#define E03_PLOT_BOTTOM 440

/* grazing's camera (common/harness/scene.c) at 800 x 600, and its strip A stood on its
 * side: the wall x = -0.5 from d = 1.5 to 100. Along row 300 it lands at
 * x_s = 400 - k * 0.5 / d, k = 300 / tan(fovy / 2): the page's
 * "row 300 + 362.1 / d", turned from a column into a row. */
#define SCREEN_WIDTH 800.0
#define SCREEN_HEIGHT 600.0
#define FOVY_DEGREES 45.0
#define STRIP_X (-0.5)
#define STRIP_NEAR 1.5
#define STRIP_FAR 100.0
#define PI 3.14159265358979323846

/* The plot's ranges: screen x along the bottom, d on the left, 1/d on the right. */
#define X_MIN 150.0
#define X_MAX 400.0
#define X_TICK 50.0
#define D_MAX 100.0
#define D_TICK 20.0
#define INV_D_MAX 0.7
#define INV_D_TICK 0.1

static double screen_scale(void) { return SCREEN_HEIGHT / 2 / tan(FOVY_DEGREES * PI / 360); }
static double strip_screen_x(double d) { return SCREEN_WIDTH / 2 + screen_scale() * STRIP_X / d; }
static double strip_depth(double xs) { return screen_scale() * STRIP_X / (xs - SCREEN_WIDTH / 2); }

static double plot_x(double xs)
{
    return E03_PLOT_LEFT + (xs - X_MIN) / (X_MAX - X_MIN) * (E03_PLOT_RIGHT - E03_PLOT_LEFT);
}
static double plot_y(double v, double v_max)
{
    return E03_PLOT_BOTTOM - v / v_max * (E03_PLOT_BOTTOM - E03_PLOT_TOP);
}

/* One of the strip's curves, a short segment per picture column. */
static void plot_curve(Image *im, bool inverse, Rgb c)
{
    double x0 = strip_screen_x(STRIP_NEAR), x1 = strip_screen_x(STRIP_FAR);
    int columns = (int)ceil(plot_x(x1) - plot_x(x0));
    double px = 0, py = 0;
    for (int i = 0; i <= columns; i++) {
        double xs = x0 + (x1 - x0) * i / columns, d = strip_depth(xs);
        double qx = plot_x(xs), qy = inverse ? plot_y(1 / d, INV_D_MAX) : plot_y(d, D_MAX);
        if (i > 0)
            line(im, px, py, qx, qy, 1.6, 0, c);
        px = qx;
        py = qy;
    }
}

static void draw_depth_along_a_row(Image *im)
{
    image_fill(im, BACKGROUND);
    char text[MAX_LABEL];
    text_at(im, 20, 14, "One strip, d = 1.5 to 100, along a screen row", TEXT_SCALE, TEXT);
    text_at(im, 20, 36, "(grazing's strip A stood on its side: x = 400 - 362.1 / d)",
            TEXT_SCALE, DIM_TEXT);

    /* The legend, above the frame. */
    int ly = E03_PLOT_TOP - 36;
    line(im, 20, ly + 7, 56, ly + 7, 1.6, 0, D_COLOUR);
    text_at(im, 64, ly, "d: a curve", TEXT_SCALE, D_COLOUR);
    line(im, 200, ly + 7, 236, ly + 7, 1.6, 0, INV_D_COLOUR);
    text_at(im, 244, ly, "1/d: a straight line", TEXT_SCALE, INV_D_COLOUR);
    line(im, 510, ly + 7, 546, ly + 7, 1.1, 5, NAIVE_COLOUR);
    text_at(im, 554, ly, "naive d (lesson 02)", TEXT_SCALE, NAIVE_COLOUR);

    /* Frame, ticks and their labels. */
    line(im, E03_PLOT_LEFT, E03_PLOT_BOTTOM, E03_PLOT_RIGHT, E03_PLOT_BOTTOM, 0.5, 0, AXIS_COLOUR);
    line(im, E03_PLOT_LEFT, E03_PLOT_TOP, E03_PLOT_LEFT, E03_PLOT_BOTTOM, 0.5, 0, D_COLOUR);
    line(im, E03_PLOT_RIGHT, E03_PLOT_TOP, E03_PLOT_RIGHT, E03_PLOT_BOTTOM, 0.5, 0, INV_D_COLOUR);
    for (double xs = X_MIN; xs <= X_MAX + 1e-9; xs += X_TICK) {
        double x = plot_x(xs);
        line(im, x, E03_PLOT_BOTTOM, x, E03_PLOT_BOTTOM + 6, 0.5, 0, AXIS_COLOUR);
        snprintf(text, sizeof text, "%g", xs);
        text_at(im, (int)lround(x) - scaled_width(text, TEXT_SCALE) / 2, E03_PLOT_BOTTOM + 12,
                text, TEXT_SCALE, AXIS_COLOUR);
    }
    for (double d = 0; d <= D_MAX + 1e-9; d += D_TICK) {
        double y = plot_y(d, D_MAX);
        line(im, E03_PLOT_LEFT - 6, y, E03_PLOT_LEFT, y, 0.5, 0, D_COLOUR);
        snprintf(text, sizeof text, "%g", d);
        text_at(im, E03_PLOT_LEFT - 12 - scaled_width(text, TEXT_SCALE), (int)lround(y) - 7, text,
                TEXT_SCALE, D_COLOUR);
    }
    for (int k = 0; k * INV_D_TICK <= INV_D_MAX + 1e-9; k++) {
        double y = plot_y(k * INV_D_TICK, INV_D_MAX);
        line(im, E03_PLOT_RIGHT, y, E03_PLOT_RIGHT + 6, y, 0.5, 0, INV_D_COLOUR);
        snprintf(text, sizeof text, "%.1f", k * INV_D_TICK);
        text_at(im, E03_PLOT_RIGHT + 12, (int)lround(y) - 7, text, TEXT_SCALE, INV_D_COLOUR);
    }
    const char *x_title = "x on the screen (pixels)";
    text_at(im, (E03_PLOT_LEFT + E03_PLOT_RIGHT - scaled_width(x_title, TEXT_SCALE)) / 2,
            E03_PLOT_BOTTOM + 40, x_title, TEXT_SCALE, AXIS_COLOUR);
    text_at(im, E03_PLOT_LEFT - 60, (E03_PLOT_TOP + E03_PLOT_BOTTOM) / 2 - 7, "d", TEXT_SCALE,
            D_COLOUR);
    text_at(im, E03_PLOT_RIGHT + 60, (E03_PLOT_TOP + E03_PLOT_BOTTOM) / 2 - 7, "1/d", TEXT_SCALE,
            INV_D_COLOUR);

    /* The naive line first, so that the true curves are drawn over it. */
    double x0 = strip_screen_x(STRIP_NEAR), x1 = strip_screen_x(STRIP_FAR);
    line(im, plot_x(x0), plot_y(STRIP_NEAR, D_MAX), plot_x(x1), plot_y(STRIP_FAR, D_MAX), 1.1, 6,
         NAIVE_COLOUR);
    plot_curve(im, false, D_COLOUR);
    plot_curve(im, true, INV_D_COLOUR);
}

/* ---- 04: edge walking and one span -------------------------------------------- */

#define E04_WIDTH 820
#define E04_HEIGHT 600
#define E04_COLS 12
#define E04_ROWS 9
#define E04_CELL 40   /* read by the test */
#define E04_LEFT 170  /* read by the test */
#define E04_TOP 90    /* read by the test */
#define E04_SPAN_ROW 5
#define E04_CORNERS 6

/* A convex hexagon, clockwise on the screen from its top corner (read by the
 * test, which draws it with lesson 04). */
static const Point HEXAGON[E04_CORNERS] = {{5.25, 0.75}, {9.5, 2.25}, {10.75, 6.0},
                                           {7.0, 8.25},  {2.25, 7.5}, {1.5, 3.0}};

static Rgb e04_cell(int x, int y, const void *ctx)
{
    (void)ctx;
    if (!covers(HEXAGON, E04_CORNERS, x, y))
        return BACKGROUND;
    return y == E04_SPAN_ROW ? SPAN_CELL : POLY_CELL;
}

static Point snapped(Point p)
{
    FixedPoint f = snap_to_fixed(p);
    return (Point){(double)f.x / SUBPIXEL_ONE, (double)f.y / SUBPIXEL_ONE};
}

/* Where the chain from corner `from` stepping by `step` (+1: the right side,
 * clockwise; -1: the left side) crosses height yc, which lies in [top, bottom). */
static double chain_x(int from, int step, double yc)
{
    for (int k = 0; k < E04_CORNERS; k++) {
        int i = (from + step * k + E04_CORNERS) % E04_CORNERS;
        int j = (i + step + E04_CORNERS) % E04_CORNERS;
        Point a = snapped(HEXAGON[i]), b = snapped(HEXAGON[j]);
        if (a.y <= yc && yc < b.y)
            return a.x + (yc - a.y) * (b.x - a.x) / (b.y - a.y);
    }
    return NAN;
}

static void draw_edge_walk(Image *im)
{
    image_fill(im, BACKGROUND);
    Grid g = {im, E04_LEFT, E04_TOP, E04_CELL, E04_COLS, E04_ROWS};
    char text[MAX_LABEL];
    int top = 0, bottom = 0;
    for (int k = 1; k < E04_CORNERS; k++) {
        top = HEXAGON[k].y < HEXAGON[top].y ? k : top;
        bottom = HEXAGON[k].y > HEXAGON[bottom].y ? k : bottom;
    }
    text_at(im, 20, 14, "Edge walking: a convex polygon, 12 x 9 pixels, 40 x enlarged",
            TEXT_SCALE, TEXT);

    grid_cells_and_lines(&g, e04_cell, NULL);
    for (int k = 0; k < E04_CORNERS; k++) {
        /* Clockwise from the top, the corners down to the bottom one are the right side. */
        int next = (k + 1) % E04_CORNERS;
        bool right = ((k - top + E04_CORNERS) % E04_CORNERS) <
                     ((bottom - top + E04_CORNERS) % E04_CORNERS);
        grid_edge(&g, HEXAGON[k], HEXAGON[next], right ? RIGHT_COLOUR : LEFT_COLOUR);
    }
    /* Each drawn row's two crossings, as ticks through the row centre that
     * stick out above and below the dots drawn over them. */
    for (int y = 0; y < E04_ROWS; y++) {
        double yc = y + 0.5;
        if (!(HEXAGON[top].y <= yc && yc < HEXAGON[bottom].y))
            continue; /* the row's centre is outside [top, bottom): no span */
        for (int side = -1; side <= 1; side += 2) {
            double x = gx(&g, chain_x(top, side, yc));
            Rgb c = side < 0 ? LEFT_COLOUR : RIGHT_COLOUR;
            line(im, x, gy(&g, yc) - 14, x, gy(&g, yc) + 14, 2.5, 0, LABEL_BOX);
            line(im, x, gy(&g, yc) - 13, x, gy(&g, yc) + 13, 1.5, 0, c);
        }
    }
    for (int y = 0; y < E04_ROWS; y++)
        for (int x = 0; x < E04_COLS; x++) {
            bool in = covers(HEXAGON, E04_CORNERS, x, y);
            centre_dot(&g, x, y, !in ? NULL : y == E04_SPAN_ROW ? &SPAN_DOT : &IN_DOT);
        }

    /* Row and column numbers, and each drawn row's two crossings in figures. */
    for (int x = 0; x < E04_COLS; x++) {
        snprintf(text, sizeof text, "%d", x);
        text_at(im, (int)gx(&g, x + 0.5) - scaled_width(text, TEXT_SCALE) / 2, E04_TOP - 26,
                text, TEXT_SCALE, DIM_TEXT);
    }
    text_at(im, E04_LEFT - 152, E04_TOP - 30, "left x", TEXT_SCALE, LEFT_COLOUR);
    text_at(im, E04_LEFT + E04_COLS * E04_CELL + 28, E04_TOP - 30, "right x", TEXT_SCALE,
            RIGHT_COLOUR);
    for (int y = 0; y < E04_ROWS; y++) {
        double yc = y + 0.5;
        snprintf(text, sizeof text, "y = %d", y);
        text_at(im, E04_LEFT - 72, (int)gy(&g, yc) - 7, text, TEXT_SCALE, DIM_TEXT);
        if (!(HEXAGON[top].y <= yc && yc < HEXAGON[bottom].y))
            continue; /* the row's centre is outside [top, bottom): no span */
        double xl = chain_x(top, -1, yc), xr = chain_x(top, +1, yc);
        snprintf(text, sizeof text, "%.2f", xl);
        text_at(im, E04_LEFT - 152, (int)gy(&g, yc) - 7, text, TEXT_SCALE, LEFT_COLOUR);
        snprintf(text, sizeof text, "%.2f", xr);
        text_at(im, E04_LEFT + E04_COLS * E04_CELL + 28, (int)gy(&g, yc) - 7, text, TEXT_SCALE,
                RIGHT_COLOUR);
    }
    boxed_text_centred(im, gx(&g, 3.0), gy(&g, 1), "left edge", LEFT_COLOUR);
    boxed_text_centred(im, gx(&g, 8.6), gy(&g, 1), "right edge", RIGHT_COLOUR);
    boxed_text_centred(im, gx(&g, 6.0), gy(&g, E04_SPAN_ROW + 1), "span y = 5", SPAN_DOT);
    boxed_text_centred(im, gx(&g, HEXAGON[top].x), gy(&g, 0), "top", TEXT);
    boxed_text_centred(im, gx(&g, HEXAGON[bottom].x), gy(&g, E04_ROWS), "bottom", TEXT);

    int y0 = E04_TOP + E04_ROWS * E04_CELL + 24, lx = 40;
    line(im, lx + 8, y0 - 3, lx + 8, y0 + 17, 1.5, 0, LEFT_COLOUR);
    line(im, lx + 20, y0 - 3, lx + 20, y0 + 17, 1.5, 0, RIGHT_COLOUR);
    legend_text(im, lx + 14, y0, "where the left and right edges cross the row centre");
    disc(im, lx + 10, y0 + 31, DOT_RADIUS, SPAN_DOT);
    legend_text(im, lx, y0 + 24, "the span of row 5: centres x + 0.5 in [left x, right x)");
    disc(im, lx + 10, y0 + 55, DOT_RADIUS, IN_DOT);
    legend_text(im, lx, y0 + 48, "centres in the other rows' spans");
    ring(im, lx + 10, y0 + 79, DOT_RADIUS - RING_WIDTH, DOT_RADIUS, HOLLOW);
    legend_text(im, lx, y0 + 72, "centres outside every span: not drawn");
}

/* ---- 05: a triangle against the near plane, in each of its four cases -------- */

#define E05_WIDTH 920
#define E05_HEIGHT 420
#define E05_PANELS 4
#define E05_PANEL_LEFT 20  /* panel k spans x from 20 + 225 k, 215 wide (read by the test) */
#define E05_PANEL_STEP 225
#define E05_PANEL_WIDTH 215
#define E05_PANEL_TOP 70   /* d = 4 at the top, d = 0 (the eye) at the bottom (read by the test) */
#define E05_PANEL_BOTTOM 330
#define E05_NEAR 1.0       /* the near plane, in view depth d (read by the test) */
#define E05_X_RANGE 2.2    /* x from -2.2 to 2.2 across a panel (read by the test) */
#define E05_D_RANGE 4.0

static const Rgb BEHIND = {44, 36, 46};
static const Rgb NEAR_COLOUR = {255, 235, 60};
static const Rgb KEPT_CELL = {50, 90, 140};
static const Rgb KEPT_EDGE = {90, 200, 255};
static const Rgb CUT_EDGE = {150, 154, 166};
static const Rgb CORNER_COLOUR = {255, 120, 200}; /* a corner of what is kept (read by the test) */

/* Each panel's triangle, (x, d) in view space: 3, 2, 1 and 0 corners in front
 * of the near plane (read by the test, which clips them with lesson 05). */
static const Point E05_TRIANGLE[E05_PANELS][3] = {
    {{-1.2, 1.8}, {1.3, 2.3}, {0.1, 3.6}},
    {{-1.4, 0.4}, {1.3, 1.8}, {-0.2, 3.4}},
    {{-1.4, 0.3}, {1.5, 0.5}, {0.2, 3.0}},
    {{-1.2, 0.2}, {1.3, 0.6}, {0.1, 0.85}},
};
static const char *const E05_CAPTION[E05_PANELS][2] = {
    {"3 in front:", "kept, 3 corners"}, {"2 in front:", "4 corners"},
    {"1 in front:", "3 corners"},       {"0 in front:", "nothing drawn"},
};

static double e05_x(int panel, double x)
{
    return E05_PANEL_LEFT + E05_PANEL_STEP * panel + (x / E05_X_RANGE + 1) / 2 * E05_PANEL_WIDTH;
}
static double e05_y(double d)
{
    return E05_PANEL_BOTTOM - d / E05_D_RANGE * (E05_PANEL_BOTTOM - E05_PANEL_TOP);
}

/* The part of polygon p (n corners) with d >= near: one pass of
 * Sutherland-Hodgman, each crossing found from the corner in front. */
static int keep_in_front(const Point *p, int n, Point *out)
{
    int m = 0;
    for (int i = 0; i < n; i++) {
        Point a = p[i], b = p[(i + 1) % n];
        bool a_in = a.y >= E05_NEAR, b_in = b.y >= E05_NEAR;
        if (a_in)
            out[m++] = a;
        if (a_in != b_in) {
            Point in = a_in ? a : b, away = a_in ? b : a;
            double t = (in.y - E05_NEAR) / (in.y - away.y);
            out[m++] = (Point){in.x + t * (away.x - in.x), E05_NEAR};
        }
    }
    return m;
}

/* Fills polygon q (picture coordinates): every pixel whose centre is inside. */
static void fill_polygon(Image *im, const Point *q, int n, Rgb c)
{
    for (int y = 0; y < im->height; y++)
        for (int x = 0; x < im->width; x++) {
            bool inside = n >= 3;
            for (int i = 0; i < n && inside; i++) {
                Point a = q[i], b = q[(i + 1) % n];
                double cross = (b.x - a.x) * (y + 0.5 - a.y) - (b.y - a.y) * (x + 0.5 - a.x);
                inside = cross <= 0; /* the corners go counterclockwise in the picture */
            }
            if (inside)
                put(im, x, y, c);
        }
}

static void draw_clipping_cases(Image *im)
{
    image_fill(im, BACKGROUND);
    text_at(im, 20, 14, "A triangle against the near plane, seen from above (x across, d up)",
            TEXT_SCALE, TEXT);
    line(im, 20, 45, 56, 45, 1.6, 6, NEAR_COLOUR);
    text_at(im, 64, 38, "near plane d = 1", TEXT_SCALE, NEAR_COLOUR);
    line(im, 270, 45, 306, 45, 1.0, 0, CUT_EDGE);
    text_at(im, 314, 38, "the triangle", TEXT_SCALE, CUT_EDGE);
    fill_rect(im, 480, 38, 516, 52, KEPT_CELL);
    text_at(im, 524, 38, "what is drawn", TEXT_SCALE, KEPT_EDGE);
    disc(im, 716, 45, 5, CORNER_COLOUR);
    text_at(im, 728, 38, "its corners", TEXT_SCALE, CORNER_COLOUR);
    for (int k = 0; k < E05_PANELS; k++) {
        int left = E05_PANEL_LEFT + E05_PANEL_STEP * k, right = left + E05_PANEL_WIDTH;
        fill_rect(im, left, (int)e05_y(E05_NEAR), right, E05_PANEL_BOTTOM, BEHIND);
        Point kept[4], q[4], t[3];
        int m = keep_in_front(E05_TRIANGLE[k], 3, kept);
        for (int i = 0; i < m; i++)
            q[i] = (Point){e05_x(k, kept[i].x), e05_y(kept[i].y)};
        if (m >= 3) /* counterclockwise in the picture, as fill_polygon takes it */
            fill_polygon(im, q, m, KEPT_CELL);
        for (int i = 0; i < 3; i++)
            t[i] = (Point){e05_x(k, E05_TRIANGLE[k][i].x), e05_y(E05_TRIANGLE[k][i].y)};
        for (int i = 0; i < 3; i++)
            line(im, t[i].x, t[i].y, t[(i + 1) % 3].x, t[(i + 1) % 3].y, 1.0, 0, CUT_EDGE);
        for (int i = 0; i < m; i++)
            line(im, q[i].x, q[i].y, q[(i + 1) % m].x, q[(i + 1) % m].y, 1.4, 0, KEPT_EDGE);
        line(im, left, e05_y(E05_NEAR), right, e05_y(E05_NEAR), 1.6, 6, NEAR_COLOUR);
        for (int i = 0; i < m; i++)
            disc(im, q[i].x, q[i].y, 5, CORNER_COLOUR);
        disc(im, (left + right) / 2.0, E05_PANEL_BOTTOM - 4, 4, TEXT); /* the eye */
        text_at(im, left + 8, E05_PANEL_BOTTOM + 14, E05_CAPTION[k][0], TEXT_SCALE, TEXT);
        text_at(im, left + 8, E05_PANEL_BOTTOM + 38, E05_CAPTION[k][1], TEXT_SCALE, KEPT_EDGE);
    }
}

/* ---- 06: window depth against view depth ------------------------------------ */

#define E06_WIDTH 960
#define E06_HEIGHT 580
#define E06_LEFT 90 /* the main plot's frame (read by the test) */
#define E06_RIGHT 520
#define E06_TOP 140
#define E06_BOTTOM 480
#define E06_ZOOM_LEFT 680 /* the zoom's frame (read by the test) */
#define E06_ZOOM_RIGHT 920
#define E06_NEAR 1.0 /* the planes of both plots (read by the test) */
#define E06_FAR 100.0
#define E06_ZOOM_D0 90.0 /* the zoom: d from 90 to 92, z_w over the codes there */
#define E06_ZOOM_D1 92.0
#define E06_UNORM16 65535.0

static const Rgb STANDARD_COLOUR = {255, 150, 50}; /* read by the test */
static const Rgb REVERSED_COLOUR = {90, 220, 255}; /* read by the test */
static const Rgb CODE_COLOUR = {120, 230, 120};    /* unorm16's steps (read by the test) */

/* docs/conventions.md's mappings: z_w = f/(f-n) (1 - n/d) and n/(f-n) (f/d - 1). */
static double standard_z(double d) { return E06_FAR / (E06_FAR - E06_NEAR) * (1 - E06_NEAR / d); }
static double reversed_z(double d) { return E06_NEAR / (E06_FAR - E06_NEAR) * (E06_FAR / d - 1); }

static double e06_x(double d) { return E06_LEFT + d / E06_FAR * (E06_RIGHT - E06_LEFT); }
static double e06_y(double z) { return E06_BOTTOM - z * (E06_BOTTOM - E06_TOP); }

/* The zoom's range of z_w: the standard mapping's over d in [90, 92], to whole codes. */
static double zoom_z0(void) { return floor(standard_z(E06_ZOOM_D0) * E06_UNORM16) / E06_UNORM16; }
static double zoom_z1(void) { return ceil(standard_z(E06_ZOOM_D1) * E06_UNORM16) / E06_UNORM16; }
static double zoom_x(double d)
{
    return E06_ZOOM_LEFT + (d - E06_ZOOM_D0) / (E06_ZOOM_D1 - E06_ZOOM_D0) *
                               (E06_ZOOM_RIGHT - E06_ZOOM_LEFT);
}
static double zoom_y(double z)
{
    return E06_BOTTOM - (z - zoom_z0()) / (zoom_z1() - zoom_z0()) * (E06_BOTTOM - E06_TOP);
}

static void frame(Image *im, int left, int top, int right, int bottom)
{
    line(im, left, bottom, right, bottom, 0.5, 0, AXIS_COLOUR);
    line(im, left, top, left, bottom, 0.5, 0, AXIS_COLOUR);
}

static void draw_depth_curve(Image *im)
{
    image_fill(im, BACKGROUND);
    char text[MAX_LABEL];
    text_at(im, 20, 14, "Window depth z_w against view depth d (near 1, far 100)", TEXT_SCALE,
            TEXT);
    line(im, 20, 53, 56, 53, 1.6, 0, STANDARD_COLOUR);
    text_at(im, 64, 46, "standard: half the codes by d = 2", TEXT_SCALE, STANDARD_COLOUR);
    line(im, 20, 77, 56, 77, 1.6, 0, REVERSED_COLOUR);
    text_at(im, 64, 70, "reversed: 1 at near, 0 at far", TEXT_SCALE, REVERSED_COLOUR);
    line(im, 20, 101, 56, 101, 1.1, 5, NAIVE_COLOUR);
    text_at(im, 64, 94, "(d - n) / (f - n): linear, for comparison", TEXT_SCALE, NAIVE_COLOUR);

    /* The main plot: d from 0 to 100 along the bottom, z_w from 0 to 1. */
    frame(im, E06_LEFT, E06_TOP, E06_RIGHT, E06_BOTTOM);
    for (int d = 0; d <= 100; d += 20) {
        double x = e06_x(d);
        line(im, x, E06_BOTTOM, x, E06_BOTTOM + 6, 0.5, 0, AXIS_COLOUR);
        snprintf(text, sizeof text, "%d", d);
        text_at(im, (int)lround(x) - scaled_width(text, TEXT_SCALE) / 2, E06_BOTTOM + 12, text,
                TEXT_SCALE, AXIS_COLOUR);
    }
    for (int k = 0; k <= 4; k++) {
        double y = e06_y(k / 4.0);
        line(im, E06_LEFT - 6, y, E06_LEFT, y, 0.5, 0, AXIS_COLOUR);
        snprintf(text, sizeof text, "%.2f", k / 4.0);
        text_at(im, E06_LEFT - 12 - scaled_width(text, TEXT_SCALE), (int)lround(y) - 7, text,
                TEXT_SCALE, AXIS_COLOUR);
    }
    text_at(im, (E06_LEFT + E06_RIGHT) / 2 - 60, E06_BOTTOM + 40, "view depth d", TEXT_SCALE,
            AXIS_COLOUR);
    text_at(im, E06_LEFT - 80, (E06_TOP + E06_BOTTOM) / 2 - 30, "z_w", TEXT_SCALE, AXIS_COLOUR);
    line(im, e06_x(E06_NEAR), e06_y(0), e06_x(E06_FAR), e06_y(1), 1.1, 6, NAIVE_COLOUR);
    /* Where the zoom looks, on the standard curve (under it). */
    line(im, e06_x(E06_ZOOM_D0), e06_y(standard_z(E06_ZOOM_D0)) - 14, e06_x(E06_ZOOM_D0),
         e06_y(standard_z(E06_ZOOM_D0)) + 14, 0.5, 0, CODE_COLOUR);
    line(im, e06_x(E06_ZOOM_D1), e06_y(standard_z(E06_ZOOM_D1)) - 14, e06_x(E06_ZOOM_D1),
         e06_y(standard_z(E06_ZOOM_D1)) + 14, 0.5, 0, CODE_COLOUR);

    double px = 0, ps = 0, pr = 0;
    for (int i = 0; i <= 800; i++) { /* d from near to far, finely where the curves bend */
        double d = E06_NEAR * pow(E06_FAR / E06_NEAR, i / 800.0);
        double x = e06_x(d), ys = e06_y(standard_z(d)), yr = e06_y(reversed_z(d));
        if (i > 0)
            line(im, px, ps, x, ys, 1.6, 0, STANDARD_COLOUR),
                line(im, px, pr, x, yr, 1.6, 0, REVERSED_COLOUR);
        px = x, ps = ys, pr = yr;
    }
    /* The zoom: d from 90 to 92, the standard curve and what unorm16 stores. */
    frame(im, E06_ZOOM_LEFT, E06_TOP, E06_ZOOM_RIGHT, E06_BOTTOM);
    text_at(im, E06_ZOOM_LEFT - 40, 70, "zoom: d from 90 to 92,", TEXT_SCALE, CODE_COLOUR);
    text_at(im, E06_ZOOM_LEFT - 40, 94, "the codes unorm16 stores", TEXT_SCALE, CODE_COLOUR);
    for (double d = E06_ZOOM_D0; d <= E06_ZOOM_D1 + 1e-9; d += 1) {
        double x = zoom_x(d);
        line(im, x, E06_BOTTOM, x, E06_BOTTOM + 6, 0.5, 0, AXIS_COLOUR);
        snprintf(text, sizeof text, "%g", d);
        text_at(im, (int)lround(x) - scaled_width(text, TEXT_SCALE) / 2, E06_BOTTOM + 12, text,
                TEXT_SCALE, AXIS_COLOUR);
    }
    for (int k = 0; k < 2; k++) { /* z_w at the zoom's bottom and top */
        double z = k ? zoom_z1() : zoom_z0(), y = zoom_y(z);
        line(im, E06_ZOOM_LEFT - 6, y, E06_ZOOM_LEFT, y, 0.5, 0, AXIS_COLOUR);
        snprintf(text, sizeof text, "%.5f", z);
        text_at(im, E06_ZOOM_LEFT - 12 - scaled_width(text, TEXT_SCALE), (int)lround(y) - 7, text,
                TEXT_SCALE, AXIS_COLOUR);
    }
    long codes = lround(nearbyint(standard_z(E06_ZOOM_D1) * E06_UNORM16) -
                        nearbyint(standard_z(E06_ZOOM_D0) * E06_UNORM16)) + 1; /* stored there */
    snprintf(text, sizeof text, "%ld codes", codes);
    text_at(im, E06_ZOOM_LEFT + 60, E06_BOTTOM + 40, text, TEXT_SCALE, CODE_COLOUR);
    double qx = 0, qy = 0, sy = 0;
    int columns = E06_ZOOM_RIGHT - E06_ZOOM_LEFT;
    for (int i = 0; i <= columns; i++) {
        double d = E06_ZOOM_D0 + (E06_ZOOM_D1 - E06_ZOOM_D0) * i / columns, x = zoom_x(d);
        double stored = nearbyint(standard_z(d) * E06_UNORM16) / E06_UNORM16;
        double y = zoom_y(standard_z(d)), ys = zoom_y(stored);
        if (i > 0) {
            line(im, qx, sy, x, sy, 1.6, 0, CODE_COLOUR); /* a step, then its rise */
            if (ys != sy)
                line(im, x, sy, x, ys, 0.8, 0, CODE_COLOUR);
            line(im, qx, qy, x, y, 1.0, 0, STANDARD_COLOUR);
        }
        qx = x, qy = y, sy = ys;
    }
}

/* ---- 07: what a slope-scaled bias does on a grazing face ---------------------- */

#define E07_WIDTH 940
#define E07_HEIGHT 520
#define E07_PANEL_LEFT 40
#define E07_PANEL_STEP 300
#define E07_PANEL_WIDTH 270
#define E07_TOP 120
#define E07_BOTTOM 400
#define E07_R 1.0 /* one step of the format: the units' size, in the picture's depth units */

static const Rgb WALL_COLOUR = {170, 174, 186};
static const Rgb DECAL_COLOUR = {255, 150, 50};

/* The decal's z_w at pixel k of a face whose depth changes by m per pixel:
 * the wall's, off by up to half a pixel's change (its plane set up from
 * rounded numbers, as lesson 07's page explains), in depth units. */
static double decal_error(int k, double m)
{
    static const double E[8] = {0.42, -0.31, 0.18, -0.47, 0.35, -0.12, 0.49, -0.38};
    return E[k] * m + (k % 2 ? -0.4 : 0.4) * E07_R;
}

/* One panel: the wall's line, the decal's fragments moved by o toward the
 * camera (down), filled where they win (nearer than the wall), hollow where
 * they lose. */
static void bias_panel(Image *im, int panel, double m, double o, const char *title,
                       const char *how)
{
    int left = E07_PANEL_LEFT + E07_PANEL_STEP * panel;
    double scale = (E07_BOTTOM - E07_TOP) / 34.0; /* depth units to picture pixels */
    double mid = (E07_TOP + E07_BOTTOM) / 2.0 - 20;
    double x0 = left + 15, dx = (E07_PANEL_WIDTH - 30) / 7.0;
    double wall0 = mid - 3.5 * m * scale; /* the wall's z_w at pixel 0, farther up */
    line(im, x0, wall0, x0 + 7 * dx, wall0 + 7 * m * scale, 1.4, 0, WALL_COLOUR);
    for (int k = 0; k < 8; k++) {
        double wall = wall0 + k * m * scale;
        double y = wall + (o - decal_error(k, m)) * scale; /* o pulls it nearer: down */
        bool wins = y > wall + 0.5;
        if (wins)
            disc(im, x0 + k * dx, y, 6, DECAL_COLOUR);
        else
            ring(im, x0 + k * dx, y, 4, 6, DECAL_COLOUR);
    }
    text_at(im, left, E07_BOTTOM + 16, title, TEXT_SCALE, TEXT);
    text_at(im, left, E07_BOTTOM + 40, how, TEXT_SCALE, DECAL_COLOUR);
}

static void draw_bias(Image *im)
{
    image_fill(im, BACKGROUND);
    text_at(im, 20, 14, "A decal on a wall, 8 pixels along a row (z_w: farther up)", TEXT_SCALE,
            TEXT);
    line(im, 20, 51, 56, 51, 1.4, 0, WALL_COLOUR);
    text_at(im, 64, 44, "the wall", TEXT_SCALE, WALL_COLOUR);
    disc(im, 200, 51, 6, DECAL_COLOUR);
    text_at(im, 214, 44, "decal fragment that wins", TEXT_SCALE, DECAL_COLOUR);
    ring(im, 560, 51, 4, 6, DECAL_COLOUR);
    text_at(im, 574, 44, "one that loses", TEXT_SCALE, DECAL_COLOUR);
    text_at(im, 20, 74, "its error: up to m/2 (m: the change of depth per pixel), and under r",
            TEXT_SCALE, DIM_TEXT);
    bias_panel(im, 0, 0.2, E07_R, "facing the camera", "units: o = r, wins");
    bias_panel(im, 1, 3.0, E07_R, "grazing, units only", "o = r: fights");
    bias_panel(im, 2, 3.0, 3.0 + E07_R, "grazing, factor too", "o = m + r: wins");
}

/* ---- 08: where the depth test runs, in each --z-mode -------------------------- */

#define E08_WIDTH 940
#define E08_HEIGHT 590
#define E08_BOX_W 150
#define E08_BOX_H 40

static const Rgb STAGE_CELL = {48, 56, 78};
static const Rgb TEST_CELL = {92, 62, 40};
static const Rgb SHADE_CELL = {38, 90, 64};
static const Rgb FAIL_COLOUR = {255, 110, 110};

/* A stage: a box at (x, y) of colour cell, its name centred. */
static void stage(Image *im, int x, int y, const char *name, Rgb cell)
{
    fill_rect(im, x, y, x + E08_BOX_W, y + E08_BOX_H, cell);
    text_at(im, x + (E08_BOX_W - scaled_width(name, TEXT_SCALE)) / 2,
            y + (E08_BOX_H - scaled_height(TEXT_SCALE)) / 2, name, TEXT_SCALE, TEXT);
}

/* An arrow from the right side of one box to the left side of the next. */
static void arrow_right(Image *im, int x0, int x1, int y)
{
    line(im, x0, y, x1 - 8, y, 1.2, 0, AXIS_COLOUR);
    arrowhead(im, x1, y, 1, 0, 9, AXIS_COLOUR);
}

/* Stages in a row from (x, y), 40 pixels apart; the first box of kind test,
 * shade or neither is coloured as such. */
static void stages(Image *im, int x, int y, const char *const *names, const Rgb *cells, int n)
{
    for (int k = 0; k < n; k++) {
        int bx = x + k * (E08_BOX_W + 40);
        stage(im, bx, y, names[k], cells[k]);
        if (k > 0)
            arrow_right(im, bx - 40, bx, y + E08_BOX_H / 2);
    }
}

/* Where a failed depth test ends a fragment: an arrow down to a note. */
static void fails_here(Image *im, int x, int y, const char *note)
{
    int cx = x + E08_BOX_W / 2;
    line(im, cx, y + E08_BOX_H, cx, y + E08_BOX_H + 22, 1.2, 0, FAIL_COLOUR);
    arrowhead(im, cx, y + E08_BOX_H + 30, 0, 1, 9, FAIL_COLOUR);
    text_at(im, cx - 60, y + E08_BOX_H + 36, note, TEXT_SCALE, FAIL_COLOUR);
}

static void draw_z_modes(Image *im)
{
    image_fill(im, BACKGROUND);
    text_at(im, 20, 14, "Where the depth test runs, for each fragment (--z-mode)", TEXT_SCALE, TEXT);
    int step = E08_BOX_W + 40, x = 160;
    const Rgb plain = STAGE_CELL, test = TEST_CELL, shade = SHADE_CELL;

    text_at(im, 20, 72, "late", TEXT_SCALE, TEXT);
    const char *late[] = {"rasterize", "shade", "depth test", "write"};
    stages(im, x, 60, late, (const Rgb[]){plain, shade, test, plain}, 4);
    fails_here(im, x + 2 * step, 60, "failed: shaded for nothing");

    text_at(im, 20, 212, "early", TEXT_SCALE, TEXT);
    const char *early[] = {"rasterize", "depth test", "shade", "write"};
    stages(im, x, 200, early, (const Rgb[]){plain, test, shade, plain}, 4);
    fails_here(im, x + step, 200, "failed: never shaded");
    text_at(im, x + 2 * step, 250, "a cutout: as late", TEXT_SCALE, DIM_TEXT);

    text_at(im, 20, 352, "prepass", TEXT_SCALE, TEXT);
    text_at(im, 20, 374, "pass 1", TEXT_SCALE, DIM_TEXT);
    const char *pass1[] = {"rasterize", "depth test", "write depth"};
    stages(im, x, 340, pass1, (const Rgb[]){plain, test, plain}, 3);
    text_at(im, 20, 446, "pass 2", TEXT_SCALE, DIM_TEXT);
    const char *pass2[] = {"rasterize", "equal test", "shade", "write"};
    stages(im, x, 430, pass2, (const Rgb[]){plain, test, shade, plain}, 4);
    fails_here(im, x + step, 430, "not the nearest: never shaded");

    fill_rect(im, 20, 558, 40, 572, TEST_CELL);
    text_at(im, 48, 558, "depth test", TEXT_SCALE, TEXT);
    fill_rect(im, 210, 558, 230, 572, SHADE_CELL);
    text_at(im, 238, 558, "the shader (a cutout discards there)", TEXT_SCALE, TEXT);
}

/* ---- 09: a tile's farthest depth against a triangle's nearest ----------------- */

#define E09_WIDTH 940
#define E09_HEIGHT 560
#define E09_LEFT 110
#define E09_CELL 44   /* picture pixels per screen pixel across */
#define E09_TOP 110   /* z_w = 1 (the far plane) */
#define E09_BOTTOM 430 /* z_w = 0 (near) */

/* Two tiles of 8 pixels along one row: what the buffer holds at each pixel
 * (z_w, farther up), and the triangle's plane over them, z = a + g x. */
static const double E09_STORED[16] = {0.30, 0.28, 0.27, 0.29, 0.31, 0.30, 0.28, 0.27,
                                      0.35, 0.38, 1.00, 0.62, 0.40, 0.66, 0.70, 0.45};
#define E09_PLANE_A 0.62
#define E09_PLANE_G (-0.012)

static double e09_y(double z) { return E09_BOTTOM - z * (E09_BOTTOM - E09_TOP); }
static double e09_plane(double x) { return E09_PLANE_A + E09_PLANE_G * x; }

static void draw_tile_bound(Image *im)
{
    image_fill(im, BACKGROUND);
    text_at(im, 20, 14, "Two tiles of 8 pixels along a row: skip a tile when no fragment can pass",
            TEXT_SCALE, TEXT);
    line(im, 20, 51, 56, 51, 1.6, 0, A_DOT);
    text_at(im, 64, 44, "the triangle's plane; its nearest over a tile", TEXT_SCALE, A_DOT);
    fill_rect(im, 20, 68, 56, 80, GRID_LINE);
    text_at(im, 64, 68, "stored z_w", TEXT_SCALE, DIM_TEXT);
    line(im, 250, 75, 286, 75, 1.6, 6, LANE_COLOUR);
    text_at(im, 294, 68, "the tile's farthest (far[k])", TEXT_SCALE, LANE_COLOUR);
    disc(im, 684, 75, 5, LEFT_COLOUR);
    text_at(im, 696, 68, "fragment passes", TEXT_SCALE, LEFT_COLOUR);

    for (int x = 0; x < 16; x++) { /* the buffer, pixel by pixel */
        double z = E09_STORED[x];
        fill_rect(im, E09_LEFT + x * E09_CELL + 3, (int)e09_y(z), E09_LEFT + (x + 1) * E09_CELL - 3,
                  E09_BOTTOM, z >= 1 ? STAGE_CELL : GRID_LINE);
    }
    line(im, E09_LEFT, E09_BOTTOM, E09_LEFT + 16 * E09_CELL, E09_BOTTOM, 0.5, 0, AXIS_COLOUR);
    line(im, E09_LEFT, E09_TOP, E09_LEFT, E09_BOTTOM, 0.5, 0, AXIS_COLOUR);
    text_at(im, 24, E09_TOP - 7, "far 1", TEXT_SCALE, AXIS_COLOUR);
    text_at(im, 24, E09_BOTTOM - 7, "near 0", TEXT_SCALE, AXIS_COLOUR);
    text_at(im, 20, (E09_TOP + E09_BOTTOM) / 2 - 7, "z_w", TEXT_SCALE, AXIS_COLOUR);
    for (int k = 0; k < 2; k++) {
        int x0 = E09_LEFT + k * 8 * E09_CELL, x1 = x0 + 8 * E09_CELL;
        double far = 0;
        for (int x = 0; x < 8; x++)
            far = fmax(far, E09_STORED[k * 8 + x]);
        double nearest = fmin(e09_plane(k * 8 + 0.5), e09_plane(k * 8 + 7.5));
        line(im, x0, e09_y(far), x1, e09_y(far), 1.6, 6, LANE_COLOUR);
        line(im, x0 + 0.5 * E09_CELL, e09_y(e09_plane(k * 8 + 0.5)), x0 + 7.5 * E09_CELL,
             e09_y(e09_plane(k * 8 + 7.5)), 1.6, 0, A_DOT);
        double nx = e09_plane(k * 8 + 0.5) <= e09_plane(k * 8 + 7.5) ? k * 8 + 0.5 : k * 8 + 7.5;
        disc(im, E09_LEFT + nx * E09_CELL, e09_y(nearest), 6, A_DOT);
        bool skip = nearest > far; /* the standard mapping: larger is farther */
        for (int x = 0; x < 8 && !skip; x++) {
            double px = k * 8 + x + 0.5;
            if (e09_plane(px) < E09_STORED[k * 8 + x])
                disc(im, E09_LEFT + px * E09_CELL, e09_y(e09_plane(px)), 5, LEFT_COLOUR);
        }
        line(im, x1, E09_TOP - 10, x1, E09_BOTTOM + 10, 0.8, 0, TILE_LINE);
        text_at(im, x0 + 12, E09_BOTTOM + 18, k == 0 ? "tile 1: nearest > farthest" :
                                                       "tile 2: nearest < farthest",
                TEXT_SCALE, TEXT);
        text_at(im, x0 + 12, E09_BOTTOM + 42, k == 0 ? "skipped, nothing tested" :
                                                       "tested pixel by pixel",
                TEXT_SCALE, k == 0 ? A_DOT : LEFT_COLOUR);
    }
    text_at(im, E09_LEFT + 8 * E09_CELL + 12, E09_TOP + 20, "a pixel still cleared: 1",
            TEXT_SCALE, DIM_TEXT);
}

/* ---- 10: bins, blocks and a block's rows ------------------------------------- */

#define E10_WIDTH 940
#define E10_HEIGHT 600
#define E10_PIXELS 128 /* 2 x 2 tiles of 64 x 64 pixels, 8 x 8 blocks of 8 x 8 */
#define E10_SCALE 3    /* picture pixels per screen pixel */
#define E10_LEFT 40
#define E10_TOP 90
#define E10_ZOOM_LEFT 560
#define E10_ZOOM_CELL 40

static const Rgb CROSSED_CELL = {120, 84, 40};
static const Rgb WHOLE_CELL = {50, 90, 140};

/* A triangle on the 128 x 128 screen, and whether pixel (x, y)'s centre is
 * in it (no centre lies on one of its edges: no fill rule is needed). */
static const Point E10_TRIANGLE[3] = {{10.3, 20.6}, {121.7, 44.2}, {38.4, 119.1}};
static bool e10_inside(int x, int y)
{
    double px = x + 0.5, py = y + 0.5;
    int sign = 0;
    for (int k = 0; k < 3; k++) {
        Point a = E10_TRIANGLE[k], b = E10_TRIANGLE[(k + 1) % 3];
        double e = (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
        int s = (e > 0) - (e < 0);
        if (s != 0 && sign != 0 && s != sign)
            return false;
        sign = s ? s : sign;
    }
    return true;
}

/* How many of block (bx, by)'s 64 pixel centres lie in the triangle. */
static int block_pixels_in(int bx, int by)
{
    int in = 0;
    for (int y = 0; y < 8; y++)
        for (int x = 0; x < 8; x++)
            in += e10_inside(bx * 8 + x, by * 8 + y);
    return in;
}

static void draw_bins_and_blocks(Image *im)
{
    image_fill(im, BACKGROUND);
    text_at(im, 20, 14, "One triangle in lesson 10: tiles, blocks, and a block's rows", TEXT_SCALE,
            TEXT);
    int side = E10_PIXELS * E10_SCALE, block = 8 * E10_SCALE, zx = 0, zy = 0, half = 64;
    for (int by = 0; by < E10_PIXELS / 8; by++)
        for (int bx = 0; bx < E10_PIXELS / 8; bx++) {
            int in = block_pixels_in(bx, by);
            int x0 = E10_LEFT + bx * block, y0 = E10_TOP + by * block;
            if (in > 0)
                fill_rect(im, x0, y0, x0 + block - 1, y0 + block - 1,
                          in == 64 ? WHOLE_CELL : CROSSED_CELL);
            if (in > 0 && in < 64 && abs(in - 32) < half)
                zx = bx, zy = by, half = abs(in - 32); /* the zoom: the block most nearly half in */
        }
    for (int k = 0; k <= E10_PIXELS / 8; k++) { /* block lines, then tile lines */
        line(im, E10_LEFT + k * block, E10_TOP, E10_LEFT + k * block, E10_TOP + side, 0.4, 0,
             GRID_LINE);
        line(im, E10_LEFT, E10_TOP + k * block, E10_LEFT + side, E10_TOP + k * block, 0.4, 0,
             GRID_LINE);
    }
    for (int k = 0; k <= 2; k++) {
        line(im, E10_LEFT + k * side / 2, E10_TOP, E10_LEFT + k * side / 2, E10_TOP + side, 1.5, 0,
             TILE_LINE);
        line(im, E10_LEFT, E10_TOP + k * side / 2, E10_LEFT + side, E10_TOP + k * side / 2, 1.5, 0,
             TILE_LINE);
    }
    for (int k = 0; k < 3; k++) {
        Point a = E10_TRIANGLE[k], b = E10_TRIANGLE[(k + 1) % 3];
        line(im, E10_LEFT + a.x * E10_SCALE, E10_TOP + a.y * E10_SCALE, E10_LEFT + b.x * E10_SCALE,
             E10_TOP + b.y * E10_SCALE, 1.2, 0, A_DOT);
    }
    int qx = E10_LEFT + zx * block, qy = E10_TOP + zy * block;
    line(im, qx, qy, qx + block, qy, 1.5, 0, LANE_COLOUR);
    line(im, qx, qy + block, qx + block, qy + block, 1.5, 0, LANE_COLOUR);
    line(im, qx, qy, qx, qy + block, 1.5, 0, LANE_COLOUR);
    line(im, qx + block, qy, qx + block, qy + block, 1.5, 0, LANE_COLOUR);
    line(im, qx + block, qy + block / 2, E10_ZOOM_LEFT - 10, E10_TOP + 4 * E10_ZOOM_CELL, 0.8, 4,
         LANE_COLOUR);

    /* The block, pixel by pixel: its mask, and row 3 as one register of 8 lanes. */
    for (int y = 0; y < 8; y++)
        for (int x = 0; x < 8; x++) {
            int x0 = E10_ZOOM_LEFT + x * E10_ZOOM_CELL, y0 = E10_TOP + y * E10_ZOOM_CELL;
            bool in = e10_inside(zx * 8 + x, zy * 8 + y);
            fill_rect(im, x0 + 1, y0 + 1, x0 + E10_ZOOM_CELL - 1, y0 + E10_ZOOM_CELL - 1,
                      in ? WHOLE_CELL : STAGE_CELL);
            char bit[4];
            snprintf(bit, sizeof bit, "%d", in);
            text_at(im, x0 + 15, y0 + 13, bit, TEXT_SCALE, in ? TEXT : DIM_TEXT);
        }
    int ry = E10_TOP + 3 * E10_ZOOM_CELL;
    line(im, E10_ZOOM_LEFT, ry, E10_ZOOM_LEFT + 8 * E10_ZOOM_CELL, ry, 1.5, 0, LANE_COLOUR);
    line(im, E10_ZOOM_LEFT, ry + E10_ZOOM_CELL, E10_ZOOM_LEFT + 8 * E10_ZOOM_CELL,
         ry + E10_ZOOM_CELL, 1.5, 0, LANE_COLOUR);
    text_at(im, E10_ZOOM_LEFT, E10_TOP - 26, "the yellow block: its mask", TEXT_SCALE, LANE_COLOUR);
    text_at(im, E10_ZOOM_LEFT, E10_TOP + 8 * E10_ZOOM_CELL + 12, "row 3: 8 lanes, one AVX2", TEXT_SCALE,
            LANE_COLOUR);
    text_at(im, E10_ZOOM_LEFT, E10_TOP + 8 * E10_ZOOM_CELL + 34, "register; bit 8 j + i", TEXT_SCALE,
            LANE_COLOUR);

    int ly = E10_TOP + side + 20;
    line(im, 40, ly + 7, 76, ly + 7, 1.5, 0, TILE_LINE);
    text_at(im, 84, ly, "tiles, 64 x 64: the triangle goes in all four bins", TEXT_SCALE, TEXT);
    fill_rect(im, 40, ly + 26, 76, ly + 40, WHOLE_CELL);
    text_at(im, 84, ly + 26, "blocks inside every edge: all 64 pixels at once", TEXT_SCALE, TEXT);
    fill_rect(im, 40, ly + 52, 76, ly + 66, CROSSED_CELL);
    text_at(im, 84, ly + 52, "blocks an edge crosses: that edge per pixel", TEXT_SCALE, TEXT);
}

/* ---- Writing them ---------------------------------------------------------------- */

typedef struct {
    const char *file;
    int width, height;
    void (*draw)(Image *im);
} Diagram;

static const Diagram DIAGRAMS[] = {
    {"02_edge_functions.png", E02_WIDTH, E02_HEIGHT, draw_edge_functions},
    {"03_depth_along_a_row.png", E03_WIDTH, E03_HEIGHT, draw_depth_along_a_row},
    {"04_edge_walk.png", E04_WIDTH, E04_HEIGHT, draw_edge_walk},
    {"05_clipping_cases.png", E05_WIDTH, E05_HEIGHT, draw_clipping_cases},
    {"06_depth_curve.png", E06_WIDTH, E06_HEIGHT, draw_depth_curve},
    {"07_bias.png", E07_WIDTH, E07_HEIGHT, draw_bias},
    {"08_z_modes.png", E08_WIDTH, E08_HEIGHT, draw_z_modes},
    {"09_tile_bound.png", E09_WIDTH, E09_HEIGHT, draw_tile_bound},
    {"10_bins_blocks.png", E10_WIDTH, E10_HEIGHT, draw_bins_and_blocks},
};

int main(int argc, char **argv)
{
    signals_begin(PROGRAM); /* a signal from now on prints one line */
    if (argc == 2 && strcmp(argv[1], "--help") == 0) {
        printf("usage: " PROGRAM " DIR\n"
               "Writes the lessons' diagrams into DIR: 02_edge_functions.png,\n"
               "03_depth_along_a_row.png, 04_edge_walk.png, 05_clipping_cases.png,\n"
               "06_depth_curve.png, 07_bias.png, 08_z_modes.png, 09_tile_bound.png and\n"
               "10_bins_blocks.png.\n");
        return EXIT_OK;
    }
    if (argc != 2 || argv[1][0] == '\0' || argv[1][0] == '-') {
        fprintf(stderr, PROGRAM ": error: expected one argument, the directory to write "
                        "into (usage: " PROGRAM " DIR)\n");
        return EXIT_USAGE;
    }
    /* The diagrams are one output set: all are published, or none (a
     * failure or a signal at the fifth leaves no four new ones behind). */
    output_set_begin();
    Error err;
    for (size_t i = 0; i < sizeof DIAGRAMS / sizeof DIAGRAMS[0]; i++) {
        const Diagram *dg = &DIAGRAMS[i];
        char path[4096];
        int n = snprintf(path, sizeof path, "%s/%s", argv[1], dg->file);
        if (n < 0 || (size_t)n >= sizeof path) {
            output_set_abort();
            fprintf(stderr, PROGRAM ": error: the directory name is too long\n");
            return EXIT_USAGE;
        }
        Image im;
        if (!image_init(&im, dg->width, dg->height, &err)) {
            output_set_abort();
            return error_report(PROGRAM, &err, EXIT_RUN_FAILED);
        }
        dg->draw(&im);
        bool ok = image_write_png(&im, path, &err);
        image_free(&im);
        if (!ok) {
            output_set_abort();
            return error_report(PROGRAM, &err, EXIT_RUN_FAILED);
        }
    }
    return output_set_publish(&err) ? EXIT_OK : error_report(PROGRAM, &err, EXIT_RUN_FAILED);
}
