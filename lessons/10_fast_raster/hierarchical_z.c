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

/* One tile buffer for the target, t->hiz; every tile is set at the clear. */
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

void hiz_clear(Target *t) /* lesson 06's: every pixel, so every tile, holds the far plane */
{
    clear_depth(t);
    for (int k = 0; t->hiz && k < t->hiz->tiles_x * t->hiz->tiles_y; k++)
        t->hiz->far[k] = t->depth[0];
}

/* The nearest (or farthest) value the triangle's plane can store over pixels
 * x0..x1, y0..y1: z_w is affine, so at the corner the slopes point to (or
 * away from). A pixel's z_w is the plane in float32 (lesson 06), a few
 * roundings from the value here: the bound moves out by 2^-20 of the terms. */
float hiz_bound(const DepthSetup *s, int x0, int y0, int x1, int y1, bool nearest)
{
    bool largest = (s->mapping == REVERSED) == nearest; /* nearest: the largest z_w if reversed */
    double a = s->plane.a0, gx = s->plane.gx, gy = s->plane.gy;
    double x = (gx > 0) == largest ? x1 : x0, y = (gy > 0) == largest ? y1 : y0;
    double z = a + gx * x + gy * y + s->offset;
    double margin = (fabs(a) + fabs(gx * x) + fabs(gy * y) + fabs((double)s->offset)) * 0x1p-20;
    return encode_depth(s->format, (float)(largest ? z + margin : z - margin));
}

/* Skipped when even the nearest value is farther than the tile's farthest: every
 * fragment there would fail (not on a tie: lesson 08's prepass draws on equal). */
bool hiz_skips(const Target *t, int tile, float nearest)
{
    bool skip = farther(t->depth_setup, nearest, t->hiz->far[tile]);
    t->hiz->tiles_tested++, t->hiz->tiles_skipped += skip;
    return skip;
}

/* A triangle covered all of the tile: each pixel kept its value or took the
 * triangle's, so none is farther than the plane's farthest value there. */
void hiz_covered(const Target *t, int tile, float farthest)
{
    float *far = &t->hiz->far[tile];
    *far = farther(t->depth_setup, *far, farthest) ? farthest : *far;
}

void hiz_free(HierarchicalZ *h) { free(h->far), h->far = NULL; }
