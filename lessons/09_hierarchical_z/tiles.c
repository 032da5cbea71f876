/* tiles.c: lesson 09's rasterizer, in place of lesson 04's scanline.c behind
 * scanline.h (docs/09_hierarchical_z.md). Each tile of a triangle's box first
 * asks the tile buffer (hierarchical_z.c) whether any fragment there could
 * pass; if none could, its pixels are never tested. Coverage is lesson 04's,
 * in edge functions of the same fixed point; a cut triangle is drawn as a fan. */
#include <math.h>

#include "hierarchical_z.h"
#include "polygon.h"
#include "scanline.h"
#include "state.h"

#define S ((int64_t)SUBPIXEL_ONE)
#define HALF ((int64_t)SUBPIXEL_HALF)

/* Edge a -> b of a triangle going clockwise on the screen (y down):
 * E(px, py) = (bx - ax)(py - ay) - (by - ay)(px - ax) (sub-pixel units) is
 * > 0 inside. A centre on a left edge (going up) or a top edge (level, going
 * right) is covered: those get E + 1. At pixel (x, y), at + x step_x + y step_y. */
typedef struct { int64_t at, step_x, step_y; } EdgeFunction;

static int64_t snap(double pixels) { return (int64_t)floor(pixels * S + 0.5); }

/* The first pixel (from 0) whose centre is at or after v, in sub-pixel
 * units; the last (below n) whose centre is at or before v; E at a pixel. */
static int first_pixel(int64_t v) { return v < HALF ? 0 : (int)((v - HALF + S - 1) / S); }
static int last_pixel(int64_t v, int n)
{
    return v < HALF ? -1 : (v - HALF) / S < n ? (int)((v - HALF) / S) : n - 1;
}
static int64_t edge_at(const EdgeFunction *e, int x, int y)
{
    return e->at + x * e->step_x + y * e->step_y;
}

/* How the triangle covers pixels x0..x1, y0..y1: none, all or some (E is affine). */
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

/* The covered pixels of x0..x1, y0..y1, row by row (one run in each), each
 * a fragment (lesson 08's fragment step), or in a skipped tile only counted. */
static void draw_tile(const Primitive *p, const EdgeFunction e[3], int x0, int y0, int x1,
                      int y1, Cover cover, bool skip)
{
    for (int y = y0; y <= y1; y++) {
        int first = x0, last = x1;
        if (cover == SOME) { /* the run: from the first pixel inside to the next outside */
            int64_t a = edge_at(&e[0], x0, y), b = edge_at(&e[1], x0, y), c = edge_at(&e[2], x0, y);
            for (; first <= x1 && !((a > 0) & (b > 0) & (c > 0)); first++)
                a += e[0].step_x, b += e[1].step_x, c += e[2].step_x;
            for (last = first; last <= x1 && (a > 0) & (b > 0) & (c > 0); last++)
                a += e[0].step_x, b += e[1].step_x, c += e[2].step_x;
            last--;
        }
        if (skip)
            p->state->hiz->fragments_skipped += (unsigned)(last - first + 1);
        for (int x = first; !skip && x <= last; x++)
            fragment(p, x, y, 0.0f);
    }
}

static bool corner_in_range(const ScreenVertex *v)
{
    return isfinite(v->x) && isfinite(v->y) && isfinite(v->d) && v->d > 0 &&
           fabs(v->x) <= SCANLINE_MAX_COORD && fabs(v->y) <= SCANLINE_MAX_COORD;
}

/* A triangle, either winding, tile by tile; false for anything else (drawn as triangles). */
bool draw_polygon(const Primitive *p, const ScreenVertex *v, int n, double far)
{
    const Target *t = p->target;
    const DepthSetup *s = &p->state->depth;
    (void)far; /* lesson 05 clipped at the far plane: no fragment lies beyond */
    int turn;
    if (n != 3 || !corner_in_range(&v[0]) || !corner_in_range(&v[1]) || !corner_in_range(&v[2]))
        return n < 3;
    if (!convex_on_screen(v, 3, SUBPIXEL_ONE, &turn) || turn == 0)
        return true; /* no area */
    int64_t x[3], y[3], x_lo = INT64_MAX, y_lo = INT64_MAX, x_hi = INT64_MIN, y_hi = INT64_MIN;
    for (int i = 0; i < 3; i++) { /* snapped, in clockwise order; their range */
        x[i] = snap(v[turn > 0 ? i : 2 - i].x), y[i] = snap(v[turn > 0 ? i : 2 - i].y);
        x_lo = x[i] < x_lo ? x[i] : x_lo, x_hi = x[i] > x_hi ? x[i] : x_hi;
        y_lo = y[i] < y_lo ? y[i] : y_lo, y_hi = y[i] > y_hi ? y[i] : y_hi;
    }
    EdgeFunction e[3];
    for (int i = 0; i < 3; i++) {
        int64_t dx = x[(i + 1) % 3] - x[i], dy = y[(i + 1) % 3] - y[i];
        e[i] = (EdgeFunction){dx * (HALF - y[i]) - dy * (HALF - x[i]) +
                                  (dy < 0 || (dy == 0 && dx > 0)), -dy * S, dx * S};
    }
    /* The box: the pixels whose centres lie in the corners' range, on the screen. */
    int bx0 = first_pixel(x_lo), by0 = first_pixel(y_lo);
    int bx1 = last_pixel(x_hi, t->width), by1 = last_pixel(y_hi, t->height);
    HierarchicalZ *h = p->state->hiz;
    bool discards = is_cutout(&p->state->early_z, p->face); /* holes: what is behind stays */
    int side = h ? h->tile : 8;
    float nearest = h ? hiz_bound(p, bx0, by0, bx1, by1, true) : 0; /* in the box */
    for (int ty = by0 / side; by0 <= by1 && ty <= by1 / side; ty++) {
        int ty0 = ty * side, ty1 = ty0 + side - 1 < t->height ? ty0 + side - 1 : t->height - 1;
        int y0 = ty0 > by0 ? ty0 : by0, y1 = ty1 < by1 ? ty1 : by1;
        int run = -1; /* from x = run, tiles covered whole, drawn together as long rows */
        for (int tx = bx0 / side; bx0 <= bx1 && tx <= bx1 / side; tx++) {
            int tx0 = tx * side, tx1 = tx0 + side - 1 < t->width ? tx0 + side - 1 : t->width - 1;
            int x0 = tx0 > bx0 ? tx0 : bx0, x1 = tx1 < bx1 ? tx1 : bx1;
            int k = h ? ty * h->tiles_x + tx : 0;
            /* SOLUTION BEGIN: ask the tile buffer first: can any fragment here pass? */
            bool skip = h && hiz_skips(h, s, k, nearest);
            /* SOLUTION STUB
            bool skip = false; (void)nearest, (void)k, (void)s;
            */
            /* SOLUTION END */
            Cover cover = skip && !h->count_skipped ? NONE : cover_of(e, x0, y0, x1, y1);
            bool joins = cover == ALL && !skip && !(h && (h->exact || discards));
            if (run >= 0 && !joins)
                draw_tile(p, e, run, y0, x0 - 1, y1, ALL, false), run = -1;
            if (joins && run < 0)
                run = x0;
            else if (!joins && cover != NONE)
                draw_tile(p, e, x0, y0, x1, y1, cover, skip);
            /* SOLUTION BEGIN: then keep it up to date: a tile the triangle covers whole
             * holds nothing farther than the plane's farthest value there (unless
             * a cutout left holes: that tile is read again). */
            if (h && !skip && (h->exact || (discards && cover != NONE)))
                hiz_read_tile(h, s, t, k);
            else if (h && !skip && cover == ALL && x0 == tx0 && x1 == tx1 && y0 == ty0 && y1 == ty1)
                hiz_covered(h, s, k, hiz_bound(p, x0, y0, x1, y1, false));
            /* SOLUTION STUB
            */
            /* SOLUTION END */
        }
        if (run >= 0)
            draw_tile(p, e, run, y0, bx1, y1, ALL, false);
    }
    return true;
}

/* Lesson 07's face (a decal biased), drawn by draw_polygon above; counted
 * when the tile buffer skipped every tile it asked about. */
static void draw_tiled_face(Target *t, LessonState *s, const ScreenFace *f,
                            const DrawContext *ctx)
{
    HierarchicalZ *h = s->hiz;
    unsigned long long tested = h ? h->tiles_tested : 0, skipped = h ? h->tiles_skipped : 0;
    DEPTH_BIAS_ZBUFFER.draw_face(t, s, f, ctx);
    if (h && h->tiles_tested > tested && h->tiles_tested - tested == h->tiles_skipped - skipped)
        h->faces_skipped++;
}

const Rasterizer HIERARCHICAL_ZBUFFER = {
    .clear = hiz_clear, .draw_face = draw_tiled_face, .stored_to_depth = stored_to_depth,
    .clips = true,
};
