/* raster.c: lesson 03, perspective-correct depth (see raster.h and docs/03_perspective_z.md). */
#include "raster.h"

#include <math.h>

#include "guard_band.h"

/* What this lesson takes to be linear on the screen (lesson 02 took d).
 * A triangle cut at the guard band gets its new corners' d by the same rule. */
/* SOLUTION BEGIN: which quantity is linear on the screen under perspective
 * (common/guard_band.h names both choices)? The corners a cut makes must get
 * their depth by the rule the pixels use. */
#define DEPTH_LINEARITY LINEAR_INV_D
/* SOLUTION STUB
#define DEPTH_LINEARITY LINEAR_D // lesson 02's choice, for now
*/
/* SOLUTION END */

/* Before the first face: every pixel holds a value that the first fragment
 * to reach it always beats, whatever its depth; no face there yet. */
void clear_depth(Target *t, LessonState *s)
{
    (void)s; /* none in this lesson (rasterizer.h) */
    size_t n = (size_t)t->width * (size_t)t->height;
    for (size_t i = 0; i < n; i++) {
        t->depth[i] = INFINITY;
        t->face[i] = NO_FACE;
    }
}

/* Rounds a screen position to the nearest 1/256 of a pixel. From here on
 * every coverage decision is made in integers, so it is exact: two triangles
 * that share an edge see exactly the same edge. */
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
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

/* For a triangle walked clockwise on the screen (positive area), the inside
 * is to the right of each edge. A top edge is exactly horizontal with the
 * inside below it; a left edge has the inside to its right. Which way each
 * one runs on this y-down screen decides it. */
bool is_top_left(FixedPoint a, FixedPoint b)
{
    int64_t dx = b.x - a.x, dy = b.y - a.y;
    bool top = dy == 0 && dx > 0;
    bool left = dy < 0;
    return top || left;
}

/* Inside an edge by the fill rule: a centre on a shared edge goes to one. */
bool edge_covers(int64_t e, bool top_left)
{
    return e > 0 || (e == 0 && top_left);
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

/* Under perspective 1/d, not d, is linear on the screen: divide the plane
 * equation a x + b y + c z = e of a face by d, and 1/d comes out as an affine
 * function of x / d and y / d, which are affine in the screen position.
 * The corners' 1/d come in worked out (draw_triangle does it once per
 * triangle), so a pixel pays one division, not four.
 * Weights 0.5, 0.3, 0.2 on depths 2, 3, 4 give d = 2.5 (docs/03_perspective_z.md). */
double interpolate_depth(Barycentric w, double inv_d0, double inv_d1, double inv_d2)
{
    /* SOLUTION BEGIN: the depth d at the pixel centre. Barycentric weights
     * reproduce exactly what is linear on the screen: use them on that, then
     * turn the result back into a depth. */
    double inv_d = w.w0 * inv_d0 + w.w1 * inv_d1 + w.w2 * inv_d2;
    return 1 / inv_d;
    /* SOLUTION STUB
    return w.w0 * inv_d0 + w.w1 * inv_d1 + w.w2 * inv_d2; // lesson 02's blend, for now
    */
    /* SOLUTION END */
}

/* The z-buffer test: the fragment wins when it is nearer than what the pixel
 * holds, d < stored. A tie keeps the face drawn first. inline: draw_triangle
 * runs it for every fragment, where a call would cost as much as the test. */
inline bool depth_test(Target *t, size_t i, int face, float d)
{
    float stored = t->depth[i];
    bool passed = d < stored;
    target_record(t, i, face, d, stored, passed);
    if (passed) {
        t->depth[i] = d;
        t->face[i] = face;
    }
    return passed;
}

/* An edge function walked over the bounding box. E(a, b, p) is linear in p:
 * one pixel to the right adds -(b.y - a.y) * 256 to it, one row down adds
 * (b.x - a.x) * 256. So each pixel costs an addition per edge instead of two
 * multiplications, and the sums are exact: the very integers edge_function
 * gives at each pixel centre. */
typedef struct {
    int64_t row_start; /* E at the centre of the box's first pixel on this row */
    int64_t step_x;    /* added per pixel to the right */
    int64_t step_y;    /* added per row down */
    bool top_left;     /* a centre exactly on the edge is inside (edge_covers) */
} EdgeStepper;

static EdgeStepper edge_stepper(FixedPoint a, FixedPoint b, FixedPoint first_centre)
{
    EdgeStepper s = {edge_function(a, b, first_centre), -(b.y - a.y) * SUBPIXEL_ONE,
                     (b.x - a.x) * SUBPIXEL_ONE, is_top_left(a, b)};
    return s;
}

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
    /* SOLUTION BEGIN: what interpolate_depth blends, at each corner, worked
     * out once per triangle rather than once per pixel. */
    double inv_d0 = 1 / a.d, inv_d1 = 1 / b.d, inv_d2 = 1 / c.d; /* once, not per pixel */
    /* SOLUTION STUB
    double inv_d0 = a.d, inv_d1 = b.d, inv_d2 = c.d; // the corners' d, as lesson 02 blends it
    */
    /* SOLUTION END */

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
            double d = interpolate_depth(w, inv_d0, inv_d1, inv_d2);
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

const Rasterizer ZBUFFER = {.clear = clear_depth, .draw_face = draw_face, .stored_to_depth = NULL};
