/* engine.c: lesson 10's plumbing, shown but not taught (engine.h): the
 * bins' memory; each face set up as lesson 07 sets it up; one fragment at
 * a time in plain C, counted for --overdraw-out and --trace. */
#include "engine.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#if defined(__x86_64__)
#include <cpuid.h>
#endif

#include "clip.h"
#include "guard_band.h"
#include "state.h"

#define S ((int64_t)SUBPIXEL_ONE)
#define HALF_PIXEL ((int64_t)SUBPIXEL_HALF)
#define CUTOUT_KEEPS 0xf0f0f0f00f0f0f0full /* lesson 08's cutout_keeps, in any block */

/* ---- The bins ---------------------------------------------------------- */

/* The capacity for need items, from cap: doubled till they fit. */
static size_t capacity(size_t cap, size_t need)
{
    size_t more = cap ? cap : 1024;
    while (more < need)
        more *= 2;
    return more;
}

/* Room for need items in *items of *cap; false (nothing changed) without. */
bool grow_array(void **items, size_t *cap, size_t need, size_t size)
{
    size_t more = capacity(*cap, need);
    void *bigger = need <= *cap ? *items : realloc(*items, more * size);
    if (bigger && need > *cap)
        *items = bigger, *cap = more;
    return bigger != NULL;
}

/* As grow_array, its n items moved to memory on 64-byte lines: a Poly is
 * one line, so that a polygon is stored and read back in one. */
_Static_assert(sizeof(Poly) == 64, "a polygon is one cache line");
static bool grow_lines(void **items, size_t *cap, size_t n, size_t need, size_t size)
{
    size_t more = capacity(*cap, need);
    void *bigger = need <= *cap ? NULL : aligned_alloc(64, (more * size + 63) / 64 * 64);
    if (!bigger) /* room already, or none to be had */
        return need <= *cap;
    if (n > 0)
        memcpy(bigger, *items, n * size);
    free(*items);
    *items = bigger, *cap = more;
    return true;
}

/* Grows b for p, when bins_room found no room (false: out of memory); a
 * function apart, so that the check made for each polygon stays small. */
static __attribute__((noinline, cold)) bool bins_grow(Bins *b, const Poly *p, int n)
{
    void *poly = b->poly, *edge = b->edge;
    bool ok = grow_lines(&poly, &b->cap_poly, b->npoly, b->npoly + 1, sizeof *b->poly) &&
              grow_array(&edge, &b->cap_edge, b->nedge + (size_t)n, sizeof *b->edge);
    b->poly = poly, b->edge = edge;
    for (int ty = tile_of(p->y0); ok && ty <= tile_of(p->y1 - 1); ty++)
        for (int tx = tile_of(p->x0); ok && tx <= tile_of(p->x1 - 1); tx++) {
            Bin *bin = &b->bin[ty * b->tiles_x + tx];
            void *at = bin->at;
            ok = grow_array(&at, &bin->cap, bin->n + 1, sizeof *bin->at);
            bin->at = at;
        }
    return ok;
}

#define AHEAD 8 /* polygons: their lines asked for so far ahead of their stores */

/* Whether the CPU has PREFETCHW (CPUID's PRFCHW); elsewhere __builtin_prefetch asks. */
static bool owns_ahead(void)
{
#if defined(__x86_64__)
    unsigned a, b, c, d;
    return __get_cpuid(0x80000001, &a, &b, &c, &d) && (c >> 8 & 1); /* PRFCHW */
#else
    return true;
#endif
}

/* The cache line of at asked for now, to be written to (a hint: it changes no value). */
static inline void own_line(const void *at)
{
#if defined(__x86_64__)
    __asm__ volatile("prefetchw %0" : : "m"(*(const char *)at));
#else
    __builtin_prefetch(at, 1);
#endif
}

bool bins_room(Bins *b, const Poly *p, int n)
{
    bool room = b->npoly < b->cap_poly && b->nedge + (size_t)n <= b->cap_edge;
    /* With threads, the cache lines of the polygon AHEAD places on and of
     * its edges (3 a triangle) are asked for before they are stored to: the
     * other thread read them at the last finish (its tiles), and each comes
     * back from its core. On two cores far apart a round trip took 0.4 us,
     * and with the stores waiting on them mesh took 18 ms on two threads,
     * now 13 (docs/performance.md, "Two cores far apart"). */
    if (b->ahead && b->npoly + AHEAD < b->cap_poly && b->nedge + 3 * AHEAD < b->cap_edge)
        own_line(&b->poly[b->npoly + AHEAD]), own_line(&b->edge[b->nedge + 3 * AHEAD]);
    for (int ty = tile_of(p->y0); room && ty <= tile_of(p->y1 - 1); ty++)
        for (int tx = tile_of(p->x0); room && tx <= tile_of(p->x1 - 1); tx++)
            room = b->bin[ty * b->tiles_x + tx].n < b->bin[ty * b->tiles_x + tx].cap;
    return room || bins_grow(b, p, n); /* room, as nearly always: nothing grown */
}

/* A finish passes over the pixels of every tile with a polygon, so the bins
 * are full only when their boxes hold HEAPED times those tiles' pixels:
 * polygons scattered over the screen wait for more (up to FLUSH_MAX), those
 * heaped on a few tiles are drawn at FLUSH_POLYGONS, while their bins are in
 * the second-level cache. Weighed once in FLUSH_EVERY polygons. */
#define FLUSH_POLYGONS (1 << 13)
#define FLUSH_EVERY (1 << 10)
#define FLUSH_MAX (1 << 16)
#define HEAPED 4

bool bins_heaped(int tiles, Bins *const *bins, int n)
{
    int64_t busy = 0, work = 0; /* 64 bits: long has 32 in the browser's build */
    for (int i = 0; i < tiles; i++) {
        bool any = false;
        for (int k = 0; k < n; k++)
            any = any || bins[k]->bin[i].n > 0, work += bins[k]->bin[i].work;
        busy += any;
    }
    return work >= HEAPED * busy * TILE_SIZE * TILE_SIZE;
}

bool bins_full(Bins *b)
{
    if (b->npoly >= FLUSH_MAX)
        return true;
    if (b->npoly < FLUSH_POLYGONS || b->npoly % FLUSH_EVERY != 0)
        return false;
    return bins_heaped(b->tiles_x * b->tiles_y, &b, 1);
}

void bins_empty(Bins *b)
{
    for (Bins *next; b; b = next) {
        for (int k = 0; k < b->tiles_x * b->tiles_y; k++)
            b->bin[k].n = 0, b->bin[k].work = 0;
        b->npoly = b->nedge = 0;
        next = b->next, b->next = NULL; /* the chain is made anew at each finish */
    }
}

bool tile_busy(const Bins *b, int tile)
{
    for (; b; b = b->next)
        if (b->bin[tile].n > 0)
            return true;
    return false;
}

/* A tile of b's target still to be cleared (by fast_finish, at the latest). */
static bool clearing(const Bins *b)
{
    for (int k = 0; b->cleared && k < b->tiles_x * b->tiles_y; k++)
        if (b->cleared[k])
            return true;
    return false;
}

void bins_free(Bins *b)
{
    for (int k = 0; b && k < b->tiles_x * b->tiles_y; k++)
        free(b->bin[k].at);
    if (b)
        free(b->bin), free(b->poly), free(b->edge), free(b->cleared);
    free(b);
}

static int tiles_across(int pixels) /* tiles a row or column of them needs */
{
    return (pixels + TILE_SIZE - 1) / TILE_SIZE;
}

/* bins_of's work when the bins are not yet t's, or not of t's size. */
static __attribute__((noinline, cold)) Bins *bins_anew(Target *t, LessonState *s)
{
    FastRaster *fr = &s->fast;
    Bins *b = fr->bins;
    if (b && b->target != t && (b->npoly > 0 || clearing(b)))
        fast_finish((Target *)b->target, s, NULL);
    int tiles_x = tiles_across(t->width), tiles_y = tiles_across(t->height);
    if (!b || b->tiles_x != tiles_x || b->tiles_y != tiles_y) {
        bins_free(b);
        fr->bins = b = calloc(1, sizeof *b);
        size_t tiles = (size_t)tiles_x * (size_t)tiles_y;
        if (b && !(b->bin = calloc(tiles, sizeof *b->bin)))
            free(b), fr->bins = b = NULL;
        if (b && !fr->set_up_only)
            b->cleared = calloc(tiles, sizeof *b->cleared); /* NULL: cleared at once */
        if (b)
            b->tiles_x = tiles_x, b->tiles_y = tiles_y, b->ahead = fr->threads > 1 && owns_ahead();
    }
    if (b)
        b->target = t;
    return b;
}

/* The bins of target t, finishing the picture of another target first. The
 * engine's own (not a thread's copy setting faces up) knows which tiles are
 * yet to be cleared, when there is room for it. */
Bins *bins_of(Target *t, LessonState *s)
{
    Bins *b = s->fast.bins;
    if (b && b->target == t && b->tiles_x == tiles_across(t->width) &&
        b->tiles_y == tiles_across(t->height))
        return b; /* as for each polygon but the first */
    return bins_anew(t, s);
}

LessonState fast_raster(DepthSetup depth, Simd simd, int threads, bool count)
{
    return (LessonState){.depth = depth, .fast = {.simd = simd, .threads = threads,
                                                  .count = count, .keep = ~(uint64_t)0,
                                                  .hold = true}};
}

void fast_raster_free(FastRaster *fr)
{
    bins_empty(fr->bins); /* unchained: the held faces' bins are freed with them */
    bins_free(fr->bins);
    fr->bins = NULL;
    held_free(fr);
    pool_free(fr->pool);
    fr->pool = NULL;
}

/* ---- Lesson 07's set-up of a face -------------------------------------- */

/* Triangle tri of f when no plane cuts it, it lies inside the guard band
 * and it is no decal: what lesson 07 does with it, without its copies. Its
 * plane from its corners as clip_to_screen puts them (triangle_plane): f's
 * own, which are its clip corners divided (rasterizer.h), as its coverage
 * is (draw_clipped_face). False: not so simple. */
static bool draw_simple_triangle(Target *t, LessonState *s, const ScreenFace *f, const Tri *tri,
                                 double far)
{
    ScreenVertex v[3];
    for (int j = 0; j < 3; j++) {
        v[j] = f->v[tri->c[j]]; /* x and y: finite if in the guard band (below) */
        if (!(v[j].d > 0 && v[j].d < INFINITY))
            return false;
        const Vec4 *c = f->clip ? &f->clip[tri->c[j]] : NULL;
        if (c && !(plane_distance(*c, NEAR_PLANE) >= 0 && plane_distance(*c, FAR_PLANE) >= 0))
            return false;
    }
    if (!guard_band_contains(v, 3, t->width, t->height))
        return false;
    Primitive p = {.target = t, .state = s, .face = f->face, .plane = depth_plane(&s->depth, v)};
    draw_polygon(&p, v, 3, far); /* refused: lesson 07 draws nothing either */
    return true;
}

/* A face, with threads that hold faces (FastRaster.hold): held back; else, or
 * when it cannot be, set up now. */
void draw_fast_face(Target *t, LessonState *s, const ScreenFace *f, const DrawContext *ctx)
{
    FastRaster *fr = &s->fast;
    if (fr->count || fr->threads < 2 || !fr->hold || fr->set_up_only || !hold_face(t, s, f, ctx))
        set_up_face(t, s, f, ctx);
}

/* A face: a decal as lesson 07 draws it, any other triangle by triangle
 * (lesson 07's draw_triangles for a triangle that is not simple). */
void set_up_face(Target *t, LessonState *s, const ScreenFace *f, const DrawContext *ctx)
{
    static const Tri first = {{0, 1, 2}};
    const Mesh *m = s->bias.mesh;
    s->fast.keep = m && mesh_face_in(m, f->face, "cutout") ? CUTOUT_KEEPS : ~(uint64_t)0;
    if (m && mesh_face_in(m, f->face, "decal")) {
        DEPTH_BIAS_ZBUFFER.draw_face(t, s, f, ctx);
        return;
    }
    for (int k = 0; k < f->n - 2; k++) {
        if (draw_simple_triangle(t, s, f, &f->tris[k], ctx->far))
            continue;
        ScreenVertex v[3];
        Vec4 clip[3];
        for (int j = 0; j < 3; j++) {
            v[j] = f->v[f->tris[k].c[j]];
            clip[j] = f->clip ? f->clip[f->tris[k].c[j]] : vec4(0, 0, 0, 0);
        }
        ScreenFace one = {.face = f->face, .n = 3, .v = v, .tris = &first, .convex = true,
                          .clip = f->clip ? clip : NULL};
        draw_triangles(t, s, &one, ctx, 0.0f);
    }
}

/* ---- A corner snapped, one fragment, a block's depth ------------------ */

static int64_t snap(double pixels) /* lesson 04's floor(pixels S + 1/2), without a call */
{
    double v = pixels * S + 0.5; /* |v| < 2^30 (SCANLINE_MAX_COORD): a cast is exact */
    int64_t i = (int64_t)v;
    return (double)i > v ? i - 1 : i;
}

bool snap_corner(const ScreenVertex *v, Corner *c)
{
    if (!(v->d > 0 && v->d < INFINITY && /* a NaN fails each */
          fabs(v->x) <= SCANLINE_MAX_COORD && fabs(v->y) <= SCANLINE_MAX_COORD))
        return false;
    *c = (Corner){snap(v->x), snap(v->y)};
    return true;
}

/* The fragment at (x, y): discarded where a cutout has a hole (as lesson
 * 08's late-Z: never tested), else z_w in lesson 06's order, its test and
 * its write; counted by target_record when counting. */
static bool test_pixel(TileWork *w, const BlockDepth *d, int x, int y)
{
    Target *t = w->t;
    size_t i = (size_t)(y - w->oy) * w->stride + (size_t)(x - w->ox);
    if (!(d->keep >> ((y % BLOCK_SIZE) * BLOCK_SIZE + x % BLOCK_SIZE) & 1))
        return false;
    float z_w = d->a0 + d->gx * (float)x + d->gy * (float)y + d->offset;
    float value = encode_depth(d->format, z_w), stored = w->depth[i];
    bool passed = d->reversed ? value > stored : value < stored;
    if (w->fr->count) /* counting draws in the target's own memory */
        target_record(t, i, d->face, value, stored, passed);
    else
        w->stats.tested++, w->stats.passed += passed;
    if (passed) {
        w->depth[i] = value;
        w->face[i] = d->face;
    }
    return passed;
}

BlockDepth block_depth(const Primitive *p, bool *plain)
{
    const DepthSetup *s = &p->state->depth;
    BlockDepth d = {p->plane.a0, p->plane.gx, p->plane.gy, p->offset,
                    s->format == UNORM16 ? 65535.0f : s->format == UNORM24 ? 16777215.0f : 0,
                    p->face, p->state->fast.keep, s->format, s->mapping == REVERSED};
    *plain = !(isfinite(d.a0) && isfinite(d.gx) && isfinite(d.gy) && isfinite(d.offset));
    return d;
}

/* ---- Hierarchical Z, lesson 09's ---------------------------------------- */

Primitive plane_of(const TileWork *w, const BlockDepth *d)
{
    return (Primitive){.target = w->t, .state = w->s, .face = d->face,
                       .plane = {d->a0, d->gx, d->gy}, .offset = d->offset};
}

/* A thread's work: its own copy of the tile buffer's counts (hiz_skips adds
 * to them), the buffer itself shared: no two threads draw the same tile. A
 * tile buffer of other tiles than blocks is not used. */
void tile_work_begin(TileWork *w, Target *t, LessonState *s)
{
    const FastRaster *fr = &s->fast;
    /* field by field: a compound literal would clear the tile's memory too */
    w->t = t, w->s = s, w->fr = fr, w->k = kernels_of(fr->count ? SIMD_NONE : fr->simd);
    w->wide = wide_of(fr->count ? SIMD_NONE : fr->simd);
    w->stats = (FragmentStats){0};
    w->hiz = s->hiz && s->hiz->tile == BLOCK_SIZE ? &w->own : NULL;
    if (w->hiz)
        w->own = *s->hiz, w->own.tiles_tested = w->own.tiles_skipped = 0;
}

void tile_work_end(TileWork *w)
{
    Target *t = w->t;
    HierarchicalZ *h = w->s->hiz;
    if (w->hiz)
        h->tiles_tested += w->own.tiles_tested, h->tiles_skipped += w->own.tiles_skipped;
    if (!t->counting)
        return;
    t->stats.tested += w->stats.tested;
    t->stats.passed += w->stats.passed;
    t->stats.failed += w->stats.tested - w->stats.passed;
}

uint64_t long_edge_coverage(const EdgeFn *e, int64_t at)
{
    uint64_t mask = 0;
    for (int bit = 0; bit < 64; bit++)
        mask |= (uint64_t)(at + (int64_t)e->a * (bit % 8) + (int64_t)e->b * (bit / 8) >= 0) << bit;
    return mask;
}

/* --simd pixels, the page's "bins" step, and counting (--trace,
 * --overdraw-out): p's part of the tile without blocks, each pixel of its
 * box inside every edge tested in plain C, one fragment after another. */
void draw_pixels(TileWork *w, const Poly *p, const EdgeFn *e)
{
    int x0 = p->x0 > w->tx0 ? p->x0 : w->tx0, x1 = p->x1 < w->tx1 ? p->x1 : w->tx1;
    int y0 = p->y0 > w->ty0 ? p->y0 : w->ty0, y1 = p->y1 < w->ty1 ? p->y1 : w->ty1;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            bool inside = true;
            for (uint32_t k = 0; k < p->n && inside; k++)
                inside = edge_at(&e[k], x, y) >= 0;
            if (inside)
                test_pixel(w, &p->depth, x, y);
        }
}
