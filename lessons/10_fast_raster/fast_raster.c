/* fast_raster.c: lesson 10's rasterizer, step by step (fast_raster.h), in
 * place of lesson 04's scanline.c: draw_polygon draws nothing till fast_finish. */
#include "fast_raster.h"

#include <math.h>
#include <stdatomic.h>
#include <stdlib.h>

#include "state.h"

#define S ((int64_t)SUBPIXEL_ONE) /* sub-pixel units per pixel */
#define HALF_PIXEL ((int64_t)SUBPIXEL_HALF)
#define POLYGON_MAX_CORNERS 256 /* more: drawn as triangles, as lesson 04 does */
#define LAST (BLOCK_SIZE - 1)           /* a block's last pixel, from its first */
#define SHORT_EDGE (1 << 27)     /* |a| + |b| below it: a block's values fit in 32 bits */

static int imin(int a, int b) { return a < b ? a : b; }
static int imax(int a, int b) { return a > b ? a : b; }
/* v / S rounded down (intmath.h's floor_div) in one shift, as S is a power of two:
 * gcc and clang shift a negative v arithmetically, which C leaves to them. */
static int64_t floor_pixels(int64_t v) { return v >> SUBPIXEL_BITS; }

/* ---- Set-up: each polygon into the bins of the tiles it may touch ------ */

/* The edge from a to b of a polygon going clockwise on the screen. A pixel
 * centre is inside when it is right of every edge, or on one that goes up
 * (a left edge) or right (a top edge): lesson 04's rule. In sub-pixel units
 * that is S (a x + b y) + C >= 0, a = -dy, b = dx; and with C = S c + r,
 * 0 <= r < S, it is a x + b y + c >= 0: 32-bit steps per pixel. */
static EdgeFn edge_function(Corner from, Corner to)
{
    int64_t dx = to.x - from.x, dy = to.y - from.y;
    /* SOLUTION BEGIN: C, the edge's value at pixel (0, 0), one less when a
     * centre on the edge is outside it. */
    bool on_edge_inside = dy < 0 || (dy == 0 && dx > 0);
    int64_t c = (HALF_PIXEL - from.y) * dx - (HALF_PIXEL - from.x) * dy - !on_edge_inside;
    return (EdgeFn){floor_pixels(c), (int32_t)-dy, (int32_t)dx};
    /* SOLUTION STUB
    return (EdgeFn){0, (int32_t)-dy, (int32_t)dx};
    */
    /* SOLUTION END */
}

/* The largest value of e over pixels x0 .. x0 + w, y0 .. y0 + h (a corner's). */
static int64_t edge_max(const EdgeFn *e, int x0, int y0, int w, int h)
{
    return edge_at(e, x0, y0) + (e->a > 0 ? (int64_t)e->a * w : 0) +
           (e->b > 0 ? (int64_t)e->b * h : 0);
}

/* p and its edges into the bin of every tile of its box no edge leaves out. */
static void bin_polygon(Bins *b, Poly *p, const Corner *c, int n, int turn)
{
    EdgeFn *e = b->edge + b->nedge;
    uint32_t m = 0; /* its edges */
    for (int k = 0; k < n; k++) {
        int next = k + 1 < n ? k + 1 : 0; /* clockwise: backwards when p turns the other way */
        Corner from = c[turn < 0 ? next : k], to = c[turn < 0 ? k : next];
        if (from.x != to.x || from.y != to.y) /* a corner twice is no edge */
            e[m++] = edge_function(from, to);
    }
    int x0 = p->x0, x1 = p->x1, y0 = p->y0, y1 = p->y1; /* kept here: a bin's store may alias p */
    bool one = tile_of(x0) == tile_of(x1 - 1) && tile_of(y0) == tile_of(y1 - 1);
    for (int ty = tile_of(y0); ty <= tile_of(y1 - 1); ty++)
        for (int tx = tile_of(x0); tx <= tile_of(x1 - 1); tx++) {
            int left = imax(x0, tx * TILE_SIZE), top = imax(y0, ty * TILE_SIZE);
            int w = imin(x1, (tx + 1) * TILE_SIZE) - 1 - left;
            int h = imin(y1, (ty + 1) * TILE_SIZE) - 1 - top;
            bool outside = false;
            for (uint32_t k = 0; !one && k < m && !outside; k++) /* one tile: binned untested */
                outside = edge_max(&e[k], left, top, w, h) < 0;
            Bin *bin = &b->bin[ty * b->tiles_x + tx];
            if (!outside) /* bins_room made room */
                bin->at[bin->n++] = (uint32_t)b->npoly, bin->work += (long)(w + 1) * (h + 1);
        }
    p->first = (uint32_t)b->nedge, p->n = (uint16_t)m, b->nedge += m, b->poly[b->npoly++] = *p;
}

/* Its box on the screen; binned. */
static void set_up_polygon(const Primitive *q, const Corner *c, int n, int turn)
{
    Target *t = q->target;
    Corner lo = c[0], hi = c[0]; /* the least and largest x and y of the corners */
    for (int k = 1; k < n; k++) {
        lo.x = c[k].x < lo.x ? c[k].x : lo.x, hi.x = c[k].x > hi.x ? c[k].x : hi.x;
        lo.y = c[k].y < lo.y ? c[k].y : lo.y, hi.y = c[k].y > hi.y ? c[k].y : hi.y;
    }
    Poly p = {/* the pixel centres of the box, on the screen (rounded up: -floor(-v)) */
              .x0 = imin(t->width, imax(0, (int)-floor_pixels(HALF_PIXEL - lo.x))),
              .y0 = imin(t->height, imax(0, (int)-floor_pixels(HALF_PIXEL - lo.y))),
              .x1 = imax(0, imin(t->width, (int)floor_pixels(hi.x - HALF_PIXEL) + 1)),
              .y1 = imax(0, imin(t->height, (int)floor_pixels(hi.y - HALF_PIXEL) + 1))};
    if (p.x0 >= p.x1 || p.y0 >= p.y1)
        return; /* no pixel centre on the screen */
    p.small = hi.x - lo.x <= 2 * BLOCK_SIZE * S && hi.y - lo.y <= 2 * BLOCK_SIZE * S;
    p.depth = block_depth(q, &p.plain);
    Bins *b = bins_of(t, q->state);
    bool room = b && !bins_full(b) && bins_room(b, &p, n);
    if (b && !room) /* draw what waits, then there is room */
        fast_finish(t, q->state, NULL), room = bins_room(b, &p, n);
    if (room)
        bin_polygon(b, &p, c, n, turn);
    q->state->fast.out_of_memory = q->state->fast.out_of_memory || !room;
}

/* A convex polygon as lesson 04 takes it (false: draw its triangles); no 1/d is
 * stepped, none discarded past far (lesson 05's clipper keeps corners inside). */
bool draw_polygon(const Primitive *p, const ScreenVertex *v, int n, double far)
{
    (void)far;
    if (n < 3 || n > POLYGON_MAX_CORNERS)
        return n < 3; /* no area; or drawn as its triangles */
    Corner c[POLYGON_MAX_CORNERS];
    for (int i = 0; i < n; i++)
        if (!snap_corner(&v[i], &c[i])) /* as lesson 04 snaps it */
            return false;
    int turn; /* a triangle is convex: its turn is that of its snapped corners */
    if (n == 3) {
        int64_t cross = (c[1].x - c[0].x) * (c[2].y - c[1].y) - (c[1].y - c[0].y) * (c[2].x - c[1].x);
        turn = (cross > 0) - (cross < 0);
    } else if (!convex_on_screen(v, n, SUBPIXEL_ONE, &turn))
        return false;
    if (turn != 0) /* else no area: no pixel */
        set_up_polygon(p, c, n, turn);
    return true;
}

/* ---- Blocks: coverage, hierarchical Z, the depth test ------------------ */

/* The pixels of box in the block at (x0, y0) not outside an edge: none for a
 * block wholly outside one; the *m edges that cross it, into crossed. */
static uint64_t block_coverage(const EdgeFn *e, int n, int x0, int y0, uint64_t box,
                               EdgeFn *crossed, int *m)
{
    *m = 0;
    for (int k = 0; k < n; k++) {
        int64_t at = edge_at(&e[k], x0, y0), hi = edge_max(&e[k], x0, y0, LAST, LAST);
        /* SOLUTION BEGIN: the block against edge k, from its corners. */
        int64_t lo = at + LAST * (int64_t)(e[k].a < 0 ? e[k].a : 0) +
                     LAST * (int64_t)(e[k].b < 0 ? e[k].b : 0);
        if (hi < 0)
            return 0; /* wholly outside this edge */
        if (lo >= 0)
            continue; /* wholly inside it */
        /* SOLUTION STUB
        (void)hi;
        */
        /* SOLUTION END */
        if (abs(e[k].a) + abs(e[k].b) < SHORT_EDGE)
            crossed[(*m)++] = e[k];
        else
            box &= long_edge_coverage(&e[k], at); /* in 64 bits */
    }
    return box;
}

static void count(TileWork *w, uint64_t tested, uint64_t passed) /* the summary's, if asked */
{
    if (w->t->counting)
        w->stats.tested += (uint64_t)__builtin_popcountll(tested),
            w->stats.passed += (uint64_t)__builtin_popcountll(passed);
}

/* The block's pixels of box: skipped when lesson 09's tile buffer (its tile
 * k) says none can pass, else those inside the m edges crossed tested by the
 * kernel (plain C where the screen cuts a row short). farthest: p's over the tile. */
static void draw_block(TileWork *w, const Poly *p, const Primitive *plane, float farthest,
                       int k, int x0, int y0, uint64_t box, const EdgeFn *crossed, int m)
{
    HierarchicalZ *h = w->hiz, *ask = h;
    bool reversed = w->s->depth.mapping == REVERSED;
    if (h && !(reversed ? farthest < h->far[k] : farthest > h->far[k]))
        h->tiles_tested++, ask = NULL; /* p is nowhere farther than the block: asked, not skipped */
    /* SOLUTION BEGIN: lesson 09's question, per block: the plane's nearest
     * value over the block's part of the box against the block's farthest. */
    int x1 = imin(x0 + LAST, p->x1 - 1), y1 = imin(y0 + LAST, p->y1 - 1);
    float nearest = ask ? hiz_bound(plane, imax(x0, p->x0), imax(y0, p->y0), x1, y1, true) : 0;
    if (ask && hiz_skips(ask, &w->s->depth, k, nearest))
        return;
    /* SOLUTION STUB
    (void)plane, (void)ask;
    */
    /* SOLUTION END */
    const BlockKernels *kernels = p->plain || x0 + BLOCK_SIZE > w->t->width ? &PLAIN_KERNELS : w->k;
    size_t i = (size_t)(y0 - w->oy) * w->stride + (size_t)(x0 - w->ox);
    float far;
    uint64_t mask, passed = kernels->draw(w->depth + i, w->face + i, w->stride, x0, y0, box,
                                          crossed, m, &p->depth, &mask, &far);
    count(w, mask & p->depth.keep, passed & p->depth.keep); /* a hole is never tested */
    if (h && !isnan(far)) /* else, as writes only come nearer, it still bounds them */
        h->far[k] = far;
}

/* The pixels of a block from column left to right - 1, row top to bottom - 1. */
static uint64_t box_mask(int left, int right, int top, int bottom)
{
    uint64_t row = ((uint64_t)1 << right) - ((uint64_t)1 << left);
    return row * 0x0101010101010101ull & ~(uint64_t)0 << (BLOCK_SIZE * top) &
           ~(uint64_t)0 >> (BLOCK_SIZE * (BLOCK_SIZE - bottom));
}

/* When p is small (corners 16 pixels apart at most) and its part of the tile
 * (x0 .. x1 - 1, y0 .. y1 - 1) fits in 16 x 16 pixels: in one window 16 wide at its first
 * pixel (w->wide), or its up to 4 pieces of 8 x 8 each in the window 8 wide at its first,
 * moved left to stay in the tile (no other thread's pixel). p is near its windows: no edge's
 * values there leave 32 bits. False: p is larger, or a cutout, kept by its place in a block. */
static bool draw_windows(TileWork *w, const Poly *p, const EdgeFn *e, int x0, int y0, int x1,
                         int y1)
{
    if (!p->small || x1 - x0 > 2 * BLOCK_SIZE || y1 - y0 > 2 * BLOCK_SIZE ||
        w->tx1 - w->tx0 < BLOCK_SIZE || p->depth.keep != ~(uint64_t)0)
        return false;
    if (w->wide && !p->plain && w->tx1 - w->tx0 >= 2 * BLOCK_SIZE) {
        int left = imin(x0, w->tx1 - 2 * BLOCK_SIZE);
        size_t i = (size_t)(y0 - w->oy) * w->stride + (size_t)(left - w->ox);
        w->wide(w->depth + i, w->face + i, w->stride, left, y0,
                ((uint32_t)1 << (x1 - left)) - ((uint32_t)1 << (x0 - left)), y1 - y0, e, (int)p->n,
                &p->depth, w->t->counting ? &w->stats : NULL);
        return true;
    }
    const BlockKernels *kernels = p->plain ? &PLAIN_KERNELS : w->k; /* the screen holds it */
    for (int y = y0; y < y1; y += BLOCK_SIZE)
        for (int x = x0; x < x1; x += BLOCK_SIZE) {
            int left = imin(x, w->tx1 - BLOCK_SIZE); /* the window's first column */
            uint64_t box = box_mask(x - left, imin(x + BLOCK_SIZE, x1) - left, 0,
                                    imin(y + BLOCK_SIZE, y1) - y), inside;
            size_t i = (size_t)(y - w->oy) * w->stride + (size_t)(left - w->ox);
            uint64_t passed = kernels->draw(w->depth + i, w->face + i, w->stride, left, y, box, e,
                                            (int)p->n, &p->depth, &inside, NULL);
            count(w, inside, passed);
        }
    return true;
}

/* p's blocks in the tile, row by row, only where its box is (or its windows).
 * An edge that p's part of the tile lies wholly inside is left out: where p
 * covers the tile whole, its blocks test no edge at all. Uncounted, a block
 * behind p's nearest value over the tile is skipped before its coverage. */
static void draw_in_tile(TileWork *w, const Poly *p, const EdgeFn *e)
{
    int x0 = imax(p->x0, w->tx0), x1 = imin(p->x1, w->tx1);
    int y0 = imax(p->y0, w->ty0), y1 = imin(p->y1, w->ty1);
    if (draw_windows(w, p, e, x0, y0, x1, y1)) /* small: 8 x 8 windows */
        return;
    Primitive plane = plane_of(w, &p->depth);
    bool uncounted = w->hiz && !w->t->counting, reversed = w->s->depth.mapping == REVERSED;
    float farthest = w->hiz ? hiz_bound(&plane, x0, y0, x1 - 1, y1 - 1, false) : 0;
    float nearest = uncounted ? hiz_bound(&plane, x0, y0, x1 - 1, y1 - 1, true) : 0;
    EdgeFn crossing[POLYGON_MAX_CORNERS], crossed[POLYGON_MAX_CORNERS]; /* tile's, block's */
    int n = 0, m; /* of each */
    for (uint32_t k = 0; k < p->n; k++) {
        int64_t hi = edge_max(&e[k], x0, y0, x1 - 1 - x0, y1 - 1 - y0);
        int64_t lo = hi - (int64_t)abs(e[k].a) * (x1 - 1 - x0) - (int64_t)abs(e[k].b) * (y1 - 1 - y0);
        if (hi < 0)
            return; /* none of the tile's pixels */
        if (lo < 0)
            crossing[n++] = e[k];
    }
    for (int by = y0 & ~LAST; by < y1; by += BLOCK_SIZE)
        for (int bx = x0 & ~LAST; bx < x1; bx += BLOCK_SIZE) {
            int k = w->hiz ? by / BLOCK_SIZE * w->hiz->tiles_x + bx / BLOCK_SIZE : 0;
            if (uncounted && (reversed ? nearest < w->hiz->far[k] : nearest > w->hiz->far[k]))
                continue; /* no fragment of it can pass */
            uint64_t box = box_mask(imax(p->x0 - bx, 0), imin(p->x1 - bx, BLOCK_SIZE),
                                    imax(p->y0 - by, 0), imin(p->y1 - by, BLOCK_SIZE));
            if ((box = block_coverage(crossing, n, bx, by, box, crossed, &m)))
                draw_block(w, p, &plane, farthest, k, bx, by, box, crossed, m);
        }
}

/* ---- Tiles and threads ------------------------------------------------- */

/* One tile: its polygons in order, b's first. */
static void draw_tile(TileWork *w, Bins *b, int tile)
{
    w->tx0 = tile % b->tiles_x * TILE_SIZE, w->ty0 = tile / b->tiles_x * TILE_SIZE;
    w->tx1 = imin(w->tx0 + TILE_SIZE, w->t->width), w->ty1 = imin(w->ty0 + TILE_SIZE, w->t->height);
    tile_memory(w, b, tile); /* extras/memory.c: where it is drawn, cleared first if it waits */
    for (const Bins *c = b; c; c = c->next)
        for (const uint32_t *at = c->bin[tile].at, *end = at + c->bin[tile].n; at < end; at++) {
            if (at + 4 < end) /* fetched ahead: a bin's polygons may lie far apart in c */
                __builtin_prefetch(&c->poly[at[4]]), __builtin_prefetch(&c->edge[c->poly[at[2]].first]);
            const Poly *p = &c->poly[*at];
            (w->fr->simd == SIMD_PIXELS || w->fr->count ? draw_pixels : draw_in_tile)(
                w, p, &c->edge[p->first]); /* counting: fragment by fragment, in plain C */
        }
    write_tile(w); /* extras/memory.c: its own memory, if it had one, back in the target */
}

typedef struct { Bins *b; int ntiles; atomic_int next; } Work;
typedef struct { _Alignas(64) Work *work; TileWork tw; } Thread; /* no cache line shared */

/* Takes tiles, down each column (side by side, two threads' tiles would share
 * cache lines of the tile buffer), until none is left: no two threads share a
 * pixel, each tile is drawn in order: the picture does not depend on who took which. */
static void *draw_tiles(void *arg)
{
    Thread *th = arg;
    Bins *b = th->work->b;
    for (int n; (n = atomic_fetch_add(&th->work->next, 1)) < th->work->ntiles;) {
        int k = n % b->tiles_y * b->tiles_x + n / b->tiles_y; /* row n % tiles_y */
        if (tile_busy(b, k) || (b->cleared && b->cleared[k])) /* else nothing to do */
            draw_tile(&th->tw, b, k);
    }
    return NULL;
}

bool fast_finish(Target *t, LessonState *s, Error *err)
{
    FastRaster *fr = &s->fast;
    if (fr->set_up_only)
        return true;
    set_up_held_faces(t, s);
    Bins *b = fr->bins;
    int nthreads = fr->count ? 1 : imax(1, fr->threads);
    Thread *th = b ? aligned_alloc(64, (size_t)nthreads * sizeof *th) : NULL;
    Work work = {.b = b, .ntiles = b ? b->tiles_x * b->tiles_y : 0};
    atomic_init(&work.next, 0);
    for (int i = 0; th && i < nthreads; i++)
        th[i].work = &work, tile_work_begin(&th[i].tw, t, s);
    if (th) /* this thread draws too */
        run_threads(&fr->pool, imin(nthreads, work.ntiles), draw_tiles, th, sizeof *th);
    for (int i = 0; th && i < nthreads; i++) /* a share not run (no tile left) adds nothing */
        tile_work_end(&th[i].tw);
    bins_empty(b);
    free(th);
    fr->out_of_memory = fr->out_of_memory || (b && !th);
    if (fr->out_of_memory && err)
        error_set(err, "out of memory for the bins and tiles: the picture is not whole");
    return !fr->out_of_memory;
}

const Rasterizer FAST_ZBUFFER = {
    .clear = clear_fast, .draw_face = draw_fast_face, .stored_to_depth = stored_to_depth,
    .clips = true,
};
