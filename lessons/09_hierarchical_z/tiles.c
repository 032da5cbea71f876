/* tiles.c: lesson 09's rasterizer, in place of lesson 04's scanline.c behind
 * scanline.h's draw_polygon and draw_face (docs/09_hierarchical_z.md).
 *
 * A triangle is drawn tile by tile over its box. A tile it covers at all
 * first asks the tile buffer (hierarchical_z.c) whether any fragment there
 * could pass; if none could, the tile is skipped and its pixels are never
 * tested. In the others, a pixel is covered when its centre lies inside
 * all three edges, or on a left or a top one: lesson 04's [left, right) and
 * [top, bottom), said with edge functions in the same fixed point, so the
 * same pixels. A polygon (a triangle cut by the near or far plane) is drawn
 * as its fan of triangles: draw_face_as_polygons does that when
 * draw_polygon declines it. */
#include <math.h>

#include "hierarchical_z.h"
#include "polygon.h"
#include "scanline.h"

#define S ((int64_t)SUBPIXEL_ONE)
#define HALF ((int64_t)SUBPIXEL_HALF)

/* Edge a -> b of a triangle going clockwise on the screen (y down):
 *     E(px, py) = (bx - ax)(py - ay) - (by - ay)(px - ax)   (sub-pixel units)
 * is > 0 inside. A pixel centre on a left edge (going up) or a top edge
 * (level, going right) is covered, so those get E + 1: covered is E > 0.
 * At the centre of pixel (x, y): E = at + x step_x + y step_y. */
typedef struct { int64_t at, step_x, step_y; } EdgeFunction;

static int64_t snap(double pixels) { return (int64_t)floor(pixels * S + 0.5); }

static int64_t edge_at(const EdgeFunction *e, int x, int y)
{
    return e->at + x * e->step_x + y * e->step_y;
}

/* How the triangle covers pixels x0..x1, y0..y1: none (one edge has them
 * all outside), all (every edge has them all inside), or some. E is
 * affine, so its least and greatest values there are at corners. */
typedef enum { NONE, SOME, ALL } Cover;

static Cover cover_of(const EdgeFunction e[3], int x0, int y0, int x1, int y1)
{
    Cover c = ALL;
    for (int k = 0; k < 3; k++) {
        bool right = e[k].step_x > 0, down = e[k].step_y > 0;
        if (edge_at(&e[k], right ? x1 : x0, down ? y1 : y0) <= 0)
            return NONE;
        if (edge_at(&e[k], right ? x0 : x1, down ? y0 : y1) <= 0)
            c = SOME;
    }
    return c;
}

/* The covered pixels of x0..x1, y0..y1, row by row: in each row of a
 * triangle they are one run, first to last. Each is tested by lesson 06's
 * depth_test or, in a skipped tile, only counted. Returns the farthest
 * value they hold afterwards (the largest, or the smallest if reversed). */
static float draw_tile(Target *t, const EdgeFunction e[3], int x0, int y0, int x1, int y1,
                       int face, Cover cover, bool skip)
{
    float hi = -INFINITY, lo = INFINITY;
    for (int y = y0; y <= y1; y++) {
        int first = x0, last = x1;
        if (cover == SOME) {
            int64_t a = edge_at(&e[0], x0, y), b = edge_at(&e[1], x0, y), c = edge_at(&e[2], x0, y);
            first = x1 + 1, last = x0 - 1;
            for (int x = x0; x <= x1; x++, a += e[0].step_x, b += e[1].step_x, c += e[2].step_x)
                if ((a > 0) & (b > 0) & (c > 0)) {
                    first = first > x1 ? x : first;
                    last = x;
                }
        }
        size_t row = (size_t)y * (size_t)t->width;
        if (skip && first <= last)
            t->hiz->fragments_skipped += (unsigned long long)(last - first + 1);
        for (size_t i = row + (size_t)first; !skip && first <= last && i <= row + (size_t)last; i++)
            depth_test(t, i, face, 0.0f);
        for (size_t i = row + (size_t)first; first <= last && i <= row + (size_t)last; i++) {
            hi = t->depth[i] > hi ? t->depth[i] : hi;
            lo = t->depth[i] < lo ? t->depth[i] : lo;
        }
    }
    return t->depth_setup->mapping == REVERSED ? lo : hi;
}

static bool corner_in_range(const ScreenVertex *v)
{
    return isfinite(v->x) && isfinite(v->y) && isfinite(v->d) && v->d > 0 &&
           fabs(v->x) <= SCANLINE_MAX_COORD && fabs(v->y) <= SCANLINE_MAX_COORD;
}

/* A triangle, either winding, drawn tile by tile. False for anything else
 * (drawn as triangles instead), as for lesson 04 a polygon out of range. */
bool draw_polygon(Target *t, const ScreenVertex *v, int n, int face, double far)
{
    (void)far; /* lesson 05 clipped at the far plane: no fragment lies beyond */
    int turn;
    if (n != 3 || !corner_in_range(&v[0]) || !corner_in_range(&v[1]) || !corner_in_range(&v[2]))
        return n < 3;
    if (!convex_on_screen(v, 3, SUBPIXEL_ONE, &turn) || turn == 0)
        return true; /* no area */
    int64_t x[3], y[3];
    for (int i = 0; i < 3; i++) /* snapped, in clockwise order */
        x[i] = snap(v[turn > 0 ? i : 2 - i].x), y[i] = snap(v[turn > 0 ? i : 2 - i].y);
    EdgeFunction e[3];
    for (int i = 0; i < 3; i++) {
        int64_t dx = x[(i + 1) % 3] - x[i], dy = y[(i + 1) % 3] - y[i];
        e[i] = (EdgeFunction){dx * (HALF - y[i]) - dy * (HALF - x[i]) +
                                  (dy < 0 || (dy == 0 && dx > 0)), -dy * S, dx * S};
    }
    /* The box: the pixels whose centres lie in the corners' range, on the screen. */
    int64_t lo_x = x[0] < x[1] ? x[0] : x[1], lo_y = y[0] < y[1] ? y[0] : y[1];
    int64_t hi_x = x[0] > x[1] ? x[0] : x[1], hi_y = y[0] > y[1] ? y[0] : y[1];
    lo_x = x[2] < lo_x ? x[2] : lo_x, lo_y = y[2] < lo_y ? y[2] : lo_y;
    hi_x = x[2] > hi_x ? x[2] : hi_x, hi_y = y[2] > hi_y ? y[2] : hi_y;
    int bx0 = (int)(lo_x < HALF ? 0 : (lo_x - HALF + S - 1) / S);
    int by0 = (int)(lo_y < HALF ? 0 : (lo_y - HALF + S - 1) / S);
    int bx1 = hi_x < HALF ? -1 : (int)((hi_x - HALF) / S < t->width ? (hi_x - HALF) / S : t->width - 1);
    int by1 = hi_y < HALF ? -1 : (int)((hi_y - HALF) / S < t->height ? (hi_y - HALF) / S : t->height - 1);
    HierarchicalZ *h = t->hiz;
    int side = h ? h->tile : 8;
    for (int ty = by0 / side; by0 <= by1 && ty <= by1 / side; ty++)
        for (int tx = bx0 / side; bx0 <= bx1 && tx <= bx1 / side; tx++) {
            int x0 = (int)fmax(tx * side, bx0), x1 = (int)fmin(tx * side + side - 1, bx1);
            int y0 = (int)fmax(ty * side, by0), y1 = (int)fmin(ty * side + side - 1, by1);
            int k = h ? ty * h->tiles_x + tx : 0;
            bool whole = x0 == tx * side && x1 == (int)fmin(tx * side + side, t->width) - 1 &&
                         y0 == ty * side && y1 == (int)fmin(ty * side + side, t->height) - 1;
            Cover cover = cover_of(e, x0, y0, x1, y1);
            if (cover == NONE)
                continue;
            /* SOLUTION BEGIN: ask the tile buffer first: the plane's nearest value over
             * this part of the tile against the farthest the tile holds. */
            bool skip = h && hiz_skips(t, k, hiz_nearest(t->depth_setup, x0, y0, x1, y1));
            /* SOLUTION STUB
            bool skip = false;
            */
            /* SOLUTION END */
            if (skip && !h->count_skipped)
                continue;
            float far_after = draw_tile(t, e, x0, y0, x1, y1, face, cover, skip);
            /* SOLUTION BEGIN: then keep it up to date: a tile the triangle covered
             * whole holds, everywhere, what was just tested there; any other, read
             * again (exact) or left with its old farthest value, still a bound. */
            if (h && !skip && cover == ALL && whole)
                h->far[k] = far_after;
            else if (h && !skip && h->exact)
                hiz_read_tile(h, t, k);
            /* SOLUTION STUB
            (void)far_after;
            */
            /* SOLUTION END */
        }
    return true;
}

/* One face: a convex face as one polygon, any other as its triangles (polygon.h). */
void draw_face(Target *t, const ScreenFace *f, const DrawContext *ctx)
{
    draw_face_as_polygons(t, f, ctx, draw_polygon);
}
