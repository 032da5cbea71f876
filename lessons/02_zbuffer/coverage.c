/* coverage.c: lesson 02's fill rule, step by step (coverage.h,
 * docs/02_zbuffer.md): which pixels a triangle covers, decided exactly;
 * draw_triangle walks them, draw_face cuts a face into such triangles. */
#include "coverage.h"
#include "raster.h"

#include <math.h>

#include "guard_band.h"

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

static int64_t min2(int64_t a, int64_t b) { return a < b ? a : b; }
static int64_t max2(int64_t a, int64_t b) { return a > b ? a : b; }
static int clamp(int v, int lo, int hi) { return v < lo ? lo : v > hi ? hi : v; }

PixelBox bounding_box(FixedPoint a, FixedPoint b, FixedPoint c, int width, int height)
{
    PixelBox box = {first_pixel(min2(min2(a.x, b.x), c.x)), first_pixel(min2(min2(a.y, b.y), c.y)),
                    last_pixel(max2(max2(a.x, b.x), c.x)), last_pixel(max2(max2(a.y, b.y), c.y))};
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

/* The triangle's covered pixels, row by row, each depth-tested at the depth
 * the lesson's interpolate_depth blends from its corner_depth (raster.h). */
void draw_triangle(Target *t, ScreenVertex a, ScreenVertex b, ScreenVertex c, int face,
                   double far)
{
    FixedPoint p0 = snap_to_fixed(a), p1 = snap_to_fixed(b), p2 = snap_to_fixed(c);
    int64_t area = edge_function(p0, p1, p2); /* twice the signed area */
    if (area == 0)
        return; /* no area, no pixel centre strictly inside: nothing to draw */
    if (area < 0) {
        /* Counter-clockwise on the screen: both windings are drawn, so walk
         * it the other way round (swap corners 1 and 2). */
        FixedPoint tp = p1; p1 = p2; p2 = tp;
        ScreenVertex tv = b; b = c; c = tv;
        area = -area;
    }
    PixelBox box = bounding_box(p0, p1, p2, t->width, t->height);
    FixedPoint first = pixel_centre(box.x0, box.y0);
    EdgeStepper s0 = edge_stepper(p1, p2, first); /* edge opposite corner 0 */
    EdgeStepper s1 = edge_stepper(p2, p0, first); /* edge opposite corner 1 */
    EdgeStepper s2 = edge_stepper(p0, p1, first); /* edge opposite corner 2 */
    double inv_area = 1.0 / (double)area; /* for barycentric_weights: one division per triangle */
    double v0 = corner_depth(a), v1 = corner_depth(b), v2 = corner_depth(c); /* not per pixel */

    for (int y = box.y0; y <= box.y1; y++) {
        int64_t e0 = s0.row_start, e1 = s1.row_start, e2 = s2.row_start;
        bool entered = false;
        for (int x = box.x0; x <= box.x1; x++, e0 += s0.step_x, e1 += s1.step_x, e2 += s2.step_x) {
            bool inside = edge_covers(e0, s0.top_left) && edge_covers(e1, s1.top_left) &&
                          edge_covers(e2, s2.top_left);
            if (!inside) {
                if (entered)
                    break; /* a triangle is convex: once out of it, the row is done */
                continue;
            }
            entered = true;
            Barycentric w = barycentric_weights(e0, e1, e2, inv_area);
            double d = interpolate_depth(w, v0, v1, v2);
            if (d > far)
                continue; /* beyond the far plane: discarded before any test */
            depth_test(t, (size_t)y * (size_t)t->width + (size_t)x, face, (float)d);
        }
        s0.row_start += s0.step_y;
        s1.row_start += s1.step_y;
        s2.row_start += s2.step_y;
    }
}

/* A face is drawn as its triangles. One reaching far off the screen is first
 * cut down to the guard band (common/guard_band.h), where fixed point holds
 * it; what is left is a convex polygon, drawn as a fan. */
void draw_face(Target *t, LessonState *s, const ScreenFace *f, const DrawContext *ctx)
{
    (void)s;
    if (!screen_face_is_finite(f))
        return; /* a corner that is not a number: no picture is right, so none is drawn */
    for (int k = 0; k < f->n - 2; k++) {
        const Tri *tri = &f->tris[k];
        ScreenVertex corners[3] = {f->v[tri->c[0]], f->v[tri->c[1]], f->v[tri->c[2]]};
        ScreenVertex band[GUARD_BAND_MAX_OUT(3)];
        int n = guard_band_clip(corners, 3, t->width, t->height, DEPTH_LINEARITY, band);
        for (int j = 1; j + 1 < n; j++)
            draw_triangle(t, band[0], band[j], band[j + 1], f->face, ctx->far);
    }
}
