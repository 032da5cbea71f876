/* coverage.c: lesson 02's fill rule, step by step (coverage.h,
 * docs/02_zbuffer.md): which pixels a triangle covers, decided exactly. */
#include "coverage.h"

#include <math.h>

/* Rounds a screen position to the nearest 1/256 of a pixel. From here on every
 * decision is in integers, exact: triangles sharing an edge see the same edge. */
FixedPoint snap_to_fixed(ScreenVertex v)
{
    FixedPoint p = {(int64_t)floor(v.x * SUBPIXEL_ONE + 0.5),
                    (int64_t)floor(v.y * SUBPIXEL_ONE + 0.5)};
    return p;
}

/* Pixel (x, y) is sampled at its centre (x + 0.5, y + 0.5). */
FixedPoint pixel_centre(int x, int y)
{
    FixedPoint p = {(int64_t)x * SUBPIXEL_ONE + SUBPIXEL_HALF,
                    (int64_t)y * SUBPIXEL_ONE + SUBPIXEL_HALF};
    return p;
}

/* The edge function E(a, b, p): twice the signed area of triangle a, b, p,
 * exact in fixed point. On this y-down screen it is
 * positive when p lies to the right of a->b as one walks from a to b,
 * seen on the screen, zero on the line through a and b. */
int64_t edge_function(FixedPoint a, FixedPoint b, FixedPoint p)
{
    /* SOLUTION BEGIN: the edge function E(a, b, p): twice the signed area
     * of the triangle a, b, p, positive when p lies to the right of a->b on
     * this y-down screen, zero on the line. */
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
    /* SOLUTION STUB
    (void)a; (void)b; (void)p;
    return 0;
    */
    /* SOLUTION END */
}

/* For a triangle walked clockwise on the screen (positive area), the inside
 * is to the right of each edge. A top edge is exactly horizontal with the
 * inside below it; a left edge has the inside to its right. Which way each
 * one runs on this y-down screen decides it. */
bool is_top_left(FixedPoint a, FixedPoint b)
{
    /* SOLUTION BEGIN: the top-left rule: of a triangle walked clockwise on
     * the screen, is a->b a top edge (exactly horizontal, the inside below
     * it) or a left edge (the inside to its right)? */
    int64_t dx = b.x - a.x, dy = b.y - a.y;
    bool top = dy == 0 && dx > 0;
    bool left = dy < 0;
    return top || left;
    /* SOLUTION STUB
    (void)a; (void)b;
    return false;
    */
    /* SOLUTION END */
}

/* Inside an edge by the fill rule: a centre on a shared edge goes to one. */
bool edge_covers(int64_t e, bool top_left)
{
    /* SOLUTION BEGIN: is a pixel centre whose edge function is e inside
     * this edge? e tells which side of the edge the centre is on; a centre
     * exactly on the edge is where the top-left rule (is_top_left) has its
     * say. */
    return e > 0 || (e == 0 && top_left);
    /* SOLUTION STUB
    (void)e; (void)top_left;
    return false;
    */
    /* SOLUTION END */
}

/* The pixels whose centres can lie in the triangle, clamped to the screen.
 * Pixel x has its centre in [lo, hi] when x * 256 + 128 >= lo, i.e.
 * x >= ceil((lo - 128) / 256), and x * 256 + 128 <= hi, i.e.
 * x <= floor((hi - 128) / 256). */
static int first_pixel(int64_t lo)
{
    int64_t n = lo - SUBPIXEL_HALF;
    return (int)(n >= 0 ? (n + SUBPIXEL_ONE - 1) / SUBPIXEL_ONE : -((-n) / SUBPIXEL_ONE));
}

static int last_pixel(int64_t hi)
{
    int64_t n = hi - SUBPIXEL_HALF;
    return (int)(n >= 0 ? n / SUBPIXEL_ONE : -((-n + SUBPIXEL_ONE - 1) / SUBPIXEL_ONE));
}

static int64_t min3(int64_t a, int64_t b, int64_t c)
{
    int64_t m = a < b ? a : b;
    return m < c ? m : c;
}

static int64_t max3(int64_t a, int64_t b, int64_t c)
{
    int64_t m = a > b ? a : b;
    return m > c ? m : c;
}

static int clamp(int v, int lo, int hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

PixelBox bounding_box(FixedPoint a, FixedPoint b, FixedPoint c, int width, int height)
{
    PixelBox box = {first_pixel(min3(a.x, b.x, c.x)), first_pixel(min3(a.y, b.y, c.y)),
                    last_pixel(max3(a.x, b.x, c.x)), last_pixel(max3(a.y, b.y, c.y))};
    /* Clamping keeps an empty box empty: x0 > width - 1 stays above x1 <= width - 1. */
    box.x0 = clamp(box.x0, 0, width);
    box.y0 = clamp(box.y0, 0, height);
    box.x1 = clamp(box.x1, -1, width - 1);
    box.y1 = clamp(box.y1, -1, height - 1);
    return box;
}

/* w_i = E_i / area, where E_i is the edge function of the edge opposite
 * corner i: the share of the triangle's area that lies across from corner i.
 * inv_area = 1 / area is worked out once per triangle: a multiplication per
 * weight costs far less than a division. */
Barycentric barycentric_weights(int64_t e0, int64_t e1, int64_t e2, double inv_area)
{
    Barycentric w = {(double)e0 * inv_area, (double)e1 * inv_area, (double)e2 * inv_area};
    return w;
}

EdgeStepper edge_stepper(FixedPoint a, FixedPoint b, FixedPoint first_centre)
{
    EdgeStepper s = {edge_function(a, b, first_centre), -(b.y - a.y) * SUBPIXEL_ONE,
                     (b.x - a.x) * SUBPIXEL_ONE, is_top_left(a, b)};
    return s;
}
