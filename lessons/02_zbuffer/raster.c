/* raster.c: lesson 02, the z-buffer (see raster.h and docs/02_zbuffer.md). */
#include "raster.h"

#include <math.h>

#include "guard_band.h"

/* What this lesson takes to be linear on the screen: d itself (the naive way).
 * A triangle cut at the guard band gets its new corners' d by the same rule. */
#define DEPTH_LINEARITY LINEAR_D

/* Before the first face: every pixel holds what any first fragment beats. */
void clear_depth(Target *t, LessonState *s)
{
    (void)s; /* none in this lesson (rasterizer.h) */
    size_t n = (size_t)t->width * (size_t)t->height;
    for (size_t i = 0; i < n; i++) {
        /* SOLUTION BEGIN: the value every pixel of the depth buffer starts
         * with: it must lose to any fragment in front of the camera. */
        t->depth[i] = INFINITY;
        /* SOLUTION STUB
        t->depth[i] = 0.0f;
        */
        /* SOLUTION END */
        t->face[i] = NO_FACE;
    }
}

/* The naive way: d taken to be linear on the screen, as if it were. It is
 * not: under perspective 1/d is (lesson 03). */
double interpolate_depth(Barycentric w, double d0, double d1, double d2)
{
    /* SOLUTION BEGIN: the view depth d at the pixel centre. Barycentric
     * weights reproduce exactly whatever is linear on the screen, and this
     * lesson takes d itself to be (lesson 03 says why it is not quite). */
    return w.w0 * d0 + w.w1 * d1 + w.w2 * d2;
    /* SOLUTION STUB
    (void)w; (void)d0; (void)d1; (void)d2;
    return 0.0;
    */
    /* SOLUTION END */
}

/* The z-buffer test: the fragment wins when it is nearer than what the pixel
 * holds. A tie keeps the face drawn first. inline: draw_triangle
 * runs it for every fragment, where a call would cost as much as the test. */
inline bool depth_test(Target *t, size_t i, int face, float d)
{
    float stored = t->depth[i];
    /* SOLUTION BEGIN: the z-buffer test: does the fragment win pixel i?
     * It must be nearer than what the pixel holds (in this buffer, which
     * way is nearer?), and a tie keeps the face drawn first. Report every
     * test with target_record, and keep the winner's depth and face. */
    bool passed = d < stored;
    target_record(t, i, face, d, stored, passed);
    if (passed) {
        t->depth[i] = d;
        t->face[i] = face;
    }
    return passed;
    /* SOLUTION STUB
    (void)face; (void)d; (void)stored;
    return false;
    */
    /* SOLUTION END */
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
            double d = interpolate_depth(w, a.d, b.d, c.d);
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
