/* hierarchical_z.c: lesson 09's tile buffer, step by step
 * (hierarchical_z.h, docs/09_hierarchical_z.md). */
#include "hierarchical_z.h"

#include <math.h>
#include <stdlib.h>

#include "state.h"

/* Farther: larger in the standard mapping, smaller in the reversed one. */
static bool farther(const DepthSetup *s, float a, float b)
{
    return s->mapping == REVERSED ? a < b : a > b;
}

/* One tile buffer for the target; every tile is set at the clear. */
bool hiz_begin(HierarchicalZ *h, const Target *t, int tile, Error *err)
{
    h->tile = tile;
    h->tiles_x = (t->width + tile - 1) / tile;
    h->tiles_y = (t->height + tile - 1) / tile;
    size_t n = (size_t)h->tiles_x * (size_t)h->tiles_y;
    h->far = malloc(n * sizeof *h->far), h->skipped_at = calloc(n, sizeof *h->skipped_at);
    if (!h->far || !h->skipped_at)
        return error_set(err, "out of memory for %zu tiles", n);
    return true;
}

/* Tile k read from the depth buffer: its farthest value. */
void hiz_read_tile(HierarchicalZ *h, const DepthSetup *s, const Target *t, int k)
{
    int x0 = k % h->tiles_x * h->tile, y0 = k / h->tiles_x * h->tile;
    int x1 = x0 + h->tile < t->width ? x0 + h->tile : t->width;
    int y1 = y0 + h->tile < t->height ? y0 + h->tile : t->height;
    float far = t->depth[(size_t)y0 * (size_t)t->width + (size_t)x0];
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            float v = t->depth[(size_t)y * (size_t)t->width + (size_t)x];
            far = farther(s, v, far) ? v : far;
        }
    h->far[k] = far;
}

void hiz_clear(Target *t, LessonState *s) /* 06's: every pixel, so every tile, the far plane */
{
    clear_depth(t, s);
    for (int k = 0; s->hiz && k < s->hiz->tiles_x * s->hiz->tiles_y; k++)
        s->hiz->far[k] = t->depth[0];
}

/* The nearest (or farthest) value the triangle's plane can store over pixels
 * x0..x1, y0..y1: z_w is affine, so at the corner the slopes point to (or
 * away from). A pixel's z_w is the plane in float32 (lesson 06), a few
 * roundings from the value here: the bound moves out by 2^-20 of the terms. */
float hiz_bound(const Primitive *p, int x0, int y0, int x1, int y1, bool nearest)
{
    const DepthSetup *s = &p->state->depth;
    bool largest = (s->mapping == REVERSED) == nearest; /* nearest: the largest z_w if reversed */
    double a = p->plane.a0, gx = p->plane.gx, gy = p->plane.gy;
    double x = (gx > 0) == largest ? x1 : x0, y = (gy > 0) == largest ? y1 : y0;
    double z = a + gx * x + gy * y + p->offset;
    double margin = (fabs(a) + fabs(gx * x) + fabs(gy * y) + fabs((double)p->offset)) * 0x1p-20;
    return encode_depth(s->format, (float)(largest ? z + margin : z - margin));
}

/* Skipped when even the nearest value is farther than the tile's farthest: every
 * fragment there would fail (not on a tie: lesson 08's prepass draws on equal). */
bool hiz_skips(HierarchicalZ *h, const DepthSetup *s, int tile, float nearest)
{
    bool skip = farther(s, nearest, h->far[tile]);
    h->tiles_tested++;
    if (skip)
        h->tiles_skipped++, h->skipped_at[tile]++;
    return skip;
}

/* A triangle covered all of the tile: each pixel kept its value or took the
 * triangle's, so none is farther than the plane's farthest value there. */
void hiz_covered(HierarchicalZ *h, const DepthSetup *s, int tile, float farthest)
{
    float *far = &h->far[tile];
    *far = farther(s, *far, farthest) ? farthest : *far;
}

void hiz_free(HierarchicalZ *h) { free(h->far), free(h->skipped_at); }
