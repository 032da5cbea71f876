/* naive.c: lesson 02's depth rule, drawn with lesson 03's own coverage
 * functions (see naive.h). Every pixel's edge functions are worked out
 * afresh rather than stepped: the same integers, so the same pixels. */
#include "naive.h"

#include "guard_band.h"

double interpolate_depth_naive(Barycentric w, double d0, double d1, double d2)
{
    return w.w0 * d0 + w.w1 * d1 + w.w2 * d2;
}

static void draw_triangle_naive(Target *t, ScreenVertex a, ScreenVertex b, ScreenVertex c,
                                int face, double far)
{
    FixedPoint p0 = snap_to_fixed(a), p1 = snap_to_fixed(b), p2 = snap_to_fixed(c);
    int64_t area = edge_function(p0, p1, p2);
    if (area == 0)
        return;
    if (area < 0) { /* walk it clockwise, as draw_triangle does */
        FixedPoint tp = p1; p1 = p2; p2 = tp;
        ScreenVertex tv = b; b = c; c = tv;
        area = -area;
    }
    PixelBox box = bounding_box(p0, p1, p2, t->width, t->height);
    bool tl0 = is_top_left(p1, p2), tl1 = is_top_left(p2, p0), tl2 = is_top_left(p0, p1);
    double inv_area = 1.0 / (double)area;
    for (int y = box.y0; y <= box.y1; y++)
        for (int x = box.x0; x <= box.x1; x++) {
            FixedPoint p = pixel_centre(x, y);
            int64_t e0 = edge_function(p1, p2, p), e1 = edge_function(p2, p0, p),
                    e2 = edge_function(p0, p1, p);
            if (!(edge_covers(e0, tl0) && edge_covers(e1, tl1) && edge_covers(e2, tl2)))
                continue;
            Barycentric w = barycentric_weights(e0, e1, e2, inv_area);
            double d = interpolate_depth_naive(w, a.d, b.d, c.d);
            if (d > far)
                continue;
            depth_test(t, (size_t)y * (size_t)t->width + (size_t)x, face, (float)d);
        }
}

/* As draw_face, with the guard band cutting by d, the naive rule's own idea
 * of what is linear on the screen. */
static void draw_face_naive(Target *t, LessonState *s, const ScreenFace *f, const DrawContext *ctx)
{
    (void)s;
    if (!screen_face_is_finite(f))
        return;
    for (int k = 0; k < f->n - 2; k++) {
        const Tri *tri = &f->tris[k];
        ScreenVertex corners[3] = {f->v[tri->c[0]], f->v[tri->c[1]], f->v[tri->c[2]]};
        ScreenVertex band[GUARD_BAND_MAX_OUT(3)];
        int n = guard_band_clip(corners, 3, t->width, t->height, LINEAR_D, band);
        for (int j = 1; j + 1 < n; j++)
            draw_triangle_naive(t, band[0], band[j], band[j + 1], f->face, ctx->far);
    }
}

const Rasterizer ZBUFFER_NAIVE = {.clear = clear_depth, .draw_face = draw_face_naive,
                                  .stored_to_depth = NULL};
