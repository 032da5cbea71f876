/* hierarchical_z.c: lesson 09's tile buffer, step by step
 * (hierarchical_z.h, docs/09_hierarchical_z.md). */
#include "hierarchical_z.h"

#include <math.h>
#include <stdlib.h>

#include "scanline.h"

/* Farther: larger in the standard mapping, smaller in the reversed one. */
static bool farther(const DepthSetup *s, float a, float b)
{
    return s->mapping == REVERSED ? a < b : a > b;
}

/* One tile buffer for the target, t->hiz; every tile is read at the clear. */
bool hiz_begin(HierarchicalZ *h, Target *t, int tile, Error *err)
{
    h->tile = tile;
    h->tiles_x = (t->width + tile - 1) / tile;
    h->tiles_y = (t->height + tile - 1) / tile;
    size_t n = (size_t)h->tiles_x * (size_t)h->tiles_y;
    if (!(h->far = malloc(n * sizeof *h->far)))
        return error_set(err, "out of memory for %zu tiles", n);
    t->hiz = h;
    return true;
}

/* Tile k read from the depth buffer: its farthest value. */
void hiz_read_tile(HierarchicalZ *h, const Target *t, int k)
{
    int x0 = k % h->tiles_x * h->tile, y0 = k / h->tiles_x * h->tile;
    int x1 = x0 + h->tile < t->width ? x0 + h->tile : t->width;
    int y1 = y0 + h->tile < t->height ? y0 + h->tile : t->height;
    float far = t->depth[(size_t)y0 * (size_t)t->width + (size_t)x0];
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            float v = t->depth[(size_t)y * (size_t)t->width + (size_t)x];
            far = farther(t->depth_setup, v, far) ? v : far;
        }
    h->far[k] = far;
}

/* Lesson 06's clear, then every tile holds the far plane in all its pixels. */
void hiz_clear(Target *t)
{
    clear_depth(t);
    for (int k = 0; t->hiz && k < t->hiz->tiles_x * t->hiz->tiles_y; k++)
        hiz_read_tile(t->hiz, t, k);
}

/* The nearest value the triangle's plane can store over pixels x0..x1,
 * y0..y1. z_w is affine, so its nearest is at a corner of the rectangle: the
 * one the slopes point away from. A pixel's z_w is the plane evaluated in
 * float32 (lesson 06), a few roundings away from the exact value here: the
 * bound moves 2^-20 of the terms' size nearer, more than those roundings. */
float hiz_nearest(const DepthSetup *s, int x0, int y0, int x1, int y1)
{
    bool reversed = s->mapping == REVERSED; /* nearest: the largest z_w */
    double a = s->plane.a0, gx = s->plane.gx, gy = s->plane.gy;
    double x = (gx < 0) != reversed ? x1 : x0, y = (gy < 0) != reversed ? y1 : y0;
    double z = a + gx * x + gy * y + s->offset;
    double margin = (fabs(a) + fabs(gx * x) + fabs(gy * y) + fabs((double)s->offset)) * 0x1p-20;
    return encode_depth(s->format, (float)(reversed ? z + margin : z - margin));
}

/* A tile is skipped when even the polygon's nearest value is farther than
 * the farthest the tile holds: every fragment there would fail. (Not on a
 * tie: lesson 08's prepass draws again where depth is equal.) */
bool hiz_skips(const Target *t, int tile, float nearest)
{
    bool skip = farther(t->depth_setup, nearest, t->hiz->far[tile]);
    t->hiz->tiles_tested++, t->hiz->tiles_skipped += skip;
    return skip;
}

void hiz_free(HierarchicalZ *h)
{
    free(h->far), h->far = NULL;
}
