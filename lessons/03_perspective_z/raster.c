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

/* Before the first face: every pixel holds what any first fragment beats. */
void clear_depth(Target *t, LessonState *s)
{
    (void)s; /* none in this lesson (rasterizer.h) */
    size_t n = (size_t)t->width * (size_t)t->height;
    for (size_t i = 0; i < n; i++) {
        t->depth[i] = INFINITY;
        t->face[i] = NO_FACE;
    }
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
