/* memory.c: where lesson 10 draws a tile, shown but not taught
 * (docs/10_fast_raster.md, "A tile's own memory"): a busy tile in 32 KB of
 * its thread's own, copied back after; and the clear, which waits for each
 * tile to be drawn, and stores an empty tile past the caches. The same
 * pixels either way: only the time differs. */
#include "fast_raster.h"

#include <stdint.h>
#include <string.h>
#if defined(__x86_64__)
#include <emmintrin.h> /* SSE2: every x86-64 has it */
#endif

#include "state.h"

#define OWN_WORK (4 * TILE_SIZE * TILE_SIZE) /* pixels of boxes: a tile in its own memory */
_Static_assert(NO_FACE == -1, "a cleared face row is every byte 0xff (memset)");

/* The pixels of the tile that its polygons' boxes hold, in all. */
static long tile_work(const Bins *b, int tile)
{
    long work = 0;
    for (; b; b = b->next)
        work += b->bin[tile].work;
    return work;
}

/* n values of 4 bytes at row, each v (a float's bits or a face), in a
 * tile nothing is drawn in now: its whole cache lines stored past the
 * caches (SSE2's streaming stores), so no line is read from memory before
 * it is written, as an ordinary store reads it. A line stored so only in
 * part is read after all, and later: the target's rows start on a line
 * (target_init), and so do a tile's when the width is a multiple of 16.
 * mesh leaves most tiles empty: its clear took 6 to 7.5 ms a frame, now 2. */
static void stream_row(void *row, size_t n, uint32_t v)
{
    unsigned char *p = row; /* n values of 4 bytes: stored as bytes, whatever their type */
    size_t i = 0;
#if defined(__x86_64__)
    size_t head = (64 - (uintptr_t)p % 64) % 64 / 4, end = head < n ? head + (n - head) / 16 * 16 : 0;
    for (; i < head && i < n; i++)
        memcpy(p + 4 * i, &v, 4);
    for (; i < end; i += 4)
        _mm_stream_si128((__m128i *)(p + 4 * i), _mm_set1_epi32((int)v));
#endif
    for (; i < n; i++)
        memcpy(p + 4 * i, &v, 4);
}

/* Where the tile is drawn. Much work (its boxes hold OWN_WORK pixels or
 * more): in memory of its own (TileWork.tile_depth, rows TILE_SIZE apart),
 * where a 64 x 64 tile's depth and faces fill 32 KB, as a core's first
 * cache holds them; in the target, rows a power of two apart share the
 * cache's few places for their addresses. Little work: in the target.
 * Either way a tile cleared since is cleared there first (a tile of its own
 * memory, read from the target else). */
void tile_memory(TileWork *w, Bins *b, int tile)
{
    Target *t = w->t;
    long work = tile_work(b, tile);
    bool own = !w->fr->count && work >= OWN_WORK; /* counting: the target's */
    bool clear = b->cleared && b->cleared[tile];
    w->depth = own ? w->tile_depth : t->depth, w->face = own ? w->tile_face : t->face;
    w->stride = own ? TILE_SIZE : (size_t)t->width;
    w->ox = own ? w->tx0 : 0, w->oy = own ? w->ty0 : 0;
    size_t n = (size_t)(w->tx1 - w->tx0);
    float cleared[TILE_SIZE]; /* a cleared row, copied: a copy is faster than a loop */
    for (size_t i = 0; clear && i < n; i++)
        cleared[i] = b->clear;
    uint32_t bits; /* of the cleared value */
    memcpy(&bits, &b->clear, sizeof bits);
    for (int y = w->ty0; (own || clear) && y < w->ty1; y++) {
        float *depth = w->depth + (size_t)(y - w->oy) * w->stride + (size_t)(w->tx0 - w->ox);
        int32_t *face = w->face + (size_t)(y - w->oy) * w->stride + (size_t)(w->tx0 - w->ox);
        size_t from = (size_t)y * (size_t)t->width + (size_t)w->tx0;
        if (clear && work == 0) /* nothing to draw now: no need of the cache */
            stream_row(depth, n, bits), stream_row(face, n, (uint32_t)NO_FACE);
        else if (clear)
            memcpy(depth, cleared, n * sizeof *depth), memset(face, 0xff, n * sizeof *face);
        else
            memcpy(depth, t->depth + from, n * sizeof *depth),
                memcpy(face, t->face + from, n * sizeof *face);
    }
    if (clear)
        b->cleared[tile] = false;
#if defined(__x86_64__)
    if (clear && work == 0)
        _mm_sfence(); /* the streamed rows stored before any other thread reads them */
#endif
}

/* The tile's own memory, if it was drawn there, back into the target's. */
void write_tile(TileWork *w)
{
    Target *t = w->t;
    size_t n = (size_t)(w->tx1 - w->tx0);
    for (int y = w->ty0; w->depth == w->tile_depth && y < w->ty1; y++) {
        size_t from = (size_t)(y - w->ty0) * TILE_SIZE;
        size_t to = (size_t)y * (size_t)t->width + (size_t)w->tx0;
        memcpy(t->depth + to, w->depth + from, n * sizeof *t->depth);
        memcpy(t->face + to, w->face + from, n * sizeof *t->face);
    }
}

/* Nothing waits any more: the picture starts again. Each tile is cleared
 * when it is first drawn, by the thread that draws it (tile_memory), or by
 * fast_finish, not now: lesson 09's hiz_clear of one pixel gives the clear
 * value, and every tile of the tile buffer the far plane. Counting clears
 * at once. */
void clear_fast(Target *t, LessonState *s)
{
    FastRaster *fr = &s->fast;
    bins_empty(fr->bins);
    fr->out_of_memory = false;
    Bins *b = fr->count ? NULL : bins_of(t, s);
    if (!b || !b->cleared) {
        hiz_clear(t, s);
        return;
    }
    int32_t face;
    Target pixel = {.width = 1, .height = 1, .depth = &b->clear, .face = &face};
    hiz_clear(&pixel, s);
    for (int k = 0; k < b->tiles_x * b->tiles_y; k++)
        b->cleared[k] = true;
}
