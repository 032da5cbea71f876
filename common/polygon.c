/* polygon.c: see polygon.h. */
#include "polygon.h"

#include <math.h>

#include "guard_band.h"

/* A polygon reaching past the guard band is clipped in a buffer on the stack
 * when it has at most this many corners; a bigger one is drawn as its triangles. */
#define CLIP_MAX_CORNERS 32

static int sign_of(int64_t v)
{
    return (v > 0) - (v < 0);
}

/* Convex on the screen, after snapping (rounded to nearest, as the
 * rasterizers snap): every turn has the same sign (or none), and y changes
 * direction at most twice going round, so the polygon is one loop with one
 * left side and one right side. Corners finite, |x|, |y| < 2^21 pixels. */
bool convex_on_screen(const ScreenVertex *v, int n, int subpixel_one, int *turn)
{
    int64_t x[3], y[3]; /* corners i, i + 1, i + 2, snapped */
    int sign = 0, y_turns = 0, last_dy = 0, first_dy = 0;
    for (int i = 0; i < n + 2; i++) {
        x[i % 3] = (int64_t)floor(v[i % n].x * subpixel_one + 0.5);
        y[i % 3] = (int64_t)floor(v[i % n].y * subpixel_one + 0.5);
        if (i < 1)
            continue;
        int dy = sign_of(y[i % 3] - y[(i - 1) % 3]); /* edge i - 1 -> i */
        if (i <= n) {
            if (dy != 0 && first_dy == 0)
                first_dy = dy;
            if (dy != 0 && last_dy != 0 && dy != last_dy)
                y_turns++;
            if (dy != 0)
                last_dy = dy;
        }
        if (i < 2)
            continue;
        const int a = (i - 2) % 3, b = (i - 1) % 3, c = i % 3;
        int s = sign_of((x[b] - x[a]) * (y[c] - y[b]) - (y[b] - y[a]) * (x[c] - x[b]));
        if (s != 0 && sign != 0 && s != sign)
            return false;
        if (s != 0)
            sign = s;
    }
    /* Close the loop: the last edge that moves in y against the first. */
    if (first_dy != 0 && last_dy != 0 && first_dy != last_dy)
        y_turns++;
    *turn = sign;
    return y_turns <= 2;
}

/* Draws polygon v[0 .. n-1], clipped to the guard band first when it reaches
 * beyond it. False when it was not drawn (not convex on the screen, or too
 * many corners to clip here): then its triangles are drawn instead. New
 * corners get their depth with 1/d taken as linear on the screen. */
static bool draw_clipped_polygon(const Primitive *p, const ScreenVertex *v, int n,
                                 const DrawContext *ctx, DrawPolygonFn draw_polygon)
{
    if (guard_band_contains(v, n, ctx->width, ctx->height))
        return draw_polygon(p, v, n, ctx->far);
    if (n > CLIP_MAX_CORNERS)
        return false;
    ScreenVertex clipped[GUARD_BAND_MAX_OUT(CLIP_MAX_CORNERS)];
    int m = guard_band_clip(v, n, ctx->width, ctx->height, LINEAR_INV_D, clipped);
    if (m < 3 || draw_polygon(p, clipped, m, ctx->far))
        return true;
    /* Cut far off the screen and snapped, a polygon can come out a hair from
     * convex: draw it as a fan of triangles, as lessons 02 and 03 do. */
    for (int j = 1; j + 1 < m; j++) {
        ScreenVertex tri[3] = {clipped[0], clipped[j], clipped[j + 1]};
        draw_polygon(p, tri, 3, ctx->far);
    }
    return true;
}

/* A face with a corner that is not a finite number in front of the camera
 * draws nothing. */
void draw_face_as_polygons(const Primitive *p, const ScreenFace *f, const DrawContext *ctx,
                           DrawPolygonFn draw_polygon)
{
    for (int i = 0; i < f->n; i++)
        if (!(isfinite(f->v[i].x) && isfinite(f->v[i].y) && isfinite(f->v[i].d) && f->v[i].d > 0))
            return; /* the pipeline drops such faces; draw nothing if one gets here */
    if (f->convex && draw_clipped_polygon(p, f->v, f->n, ctx, draw_polygon))
        return;
    /* A non-convex face: its ear-clipped triangles, each one a convex polygon. */
    for (int k = 0; k < f->n - 2; k++) {
        ScreenVertex tri[3];
        for (int j = 0; j < 3; j++)
            tri[j] = f->v[f->tris[k].c[j]];
        draw_clipped_polygon(p, tri, 3, ctx, draw_polygon);
    }
}
