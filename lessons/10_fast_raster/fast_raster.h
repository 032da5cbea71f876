/* fast_raster.h: lesson 10, a fast rasterizer (docs/10_fast_raster.md).
 * Lesson 09's pictures, drawn as Mesa's llvmpipe draws:
 *   bins     each polygon in the bin of every screen tile it may touch;
 *            fast_finish draws the tiles, each its polygons in order
 *   blocks   edge functions at a block's corners take or reject it whole;
 *            a block an edge crosses is tested per pixel (lesson 04's rule)
 *   depth    lessons 06 to 09's: a block lesson 09's tile buffer hides is skipped
 *   SIMD     a block row at once: AVX2 8 pixels (simd.c), SSE2 4; AVX-512 2 rows
 *   threads  tiles handed out one at a time: no two share a pixel
 * Bit 8 j + i of a block's mask is its pixel (i, j). */
#ifndef FAST_RASTER_H
#define FAST_RASTER_H

#include <stdint.h>

#include "hierarchical_z.h"
#include "polygon.h"
#include "scanline.h"

#define TILE_SIZE 64 /* pixels: a tile is 8 x 8 blocks */
#define BLOCK_SIZE 8 /* pixels: a block row is one AVX2 register of floats */
static inline int tile_of(int x) { return (int)((unsigned)x / TILE_SIZE); } /* x >= 0: a shift */

typedef enum { SIMD_PIXELS /* no blocks */, SIMD_NONE, SIMD_SSE2, SIMD_AVX2, SIMD_AVX512 } Simd;
typedef struct Bins Bins; /* what waits for fast_finish */
typedef struct Held Held; /* faces held back for the threads to set up (extras/held.c) */
typedef struct Pool Pool; /* the threads, started once, then kept (extras/pool.c) */

typedef struct {
    Simd simd;        /* the widest this machine has, or --simd */
    int threads;      /* --threads */
    bool count;       /* overdraw[] and --trace: plain C, one thread */
    uint64_t keep;    /* the face's pixels a cutout keeps, in any block */
    Bins *bins; Held *held; Pool *pool;
    bool hold;        /* with threads: faces held back for them to set up (else: by this one) */
    bool set_up_only; /* a thread's copy, setting faces up: it never draws */
    bool out_of_memory; /* an allocation failed: a face or a tile went undrawn */
} FastRaster;

/* The lesson's state (state.h): depth, the engine, no tile buffer yet. */
LessonState fast_raster(DepthSetup depth, Simd simd, int threads, bool count);
/* Draws every tile's bin and clears every tile not yet cleared: what was
 * drawn is done (the frame may go on). False, with err (when not NULL) set,
 * when memory ran out for a face or a tile since the clear: not whole. */
bool fast_finish(Target *t, LessonState *s, Error *err);
void fast_raster_free(FastRaster *fr); /* and its threads */

extern const Rasterizer FAST_ZBUFFER; /* the clear; faces set up and binned; then fast_finish */

/* ---- What the lesson's files share ------------------------------------- */

typedef struct { int64_t x, y; } Corner;            /* snapped, as lesson 04 */
typedef struct { int64_t c; int32_t a, b; } EdgeFn; /* a x + b y + c >= 0: inside */
static inline int64_t edge_at(const EdgeFn *e, int x, int y) /* e at pixel (x, y) */
{
    return (int64_t)e->a * x + (int64_t)e->b * y + e->c;
}
typedef struct {
    float a0, gx, gy, offset; /* z_w = a0 + gx x + gy y + offset, in this order */
    float unorm;              /* 2^bits - 1 for a unorm format, 0 for float32 */
    int32_t face;
    uint64_t keep;            /* the pixels a cutout keeps (all: not a cutout) */
    DepthFormat format; bool reversed;
} BlockDepth;

typedef struct {
    BlockDepth depth;
    int x0, y0, x1, y1;  /* the pixels it may cover, on the screen */
    uint32_t first; uint16_t n; /* its edges in the bins */
    bool plain, small;   /* a plane only plain C takes; corners 16 pixels apart at most */
} Poly; /* 64 bytes: a cache line */

typedef struct { uint32_t *at; size_t n, cap; long work; } Bin; /* polygons, in order; box pixels */
struct Bins {
    const Target *target; int tiles_x, tiles_y;
    Bins *next; /* the bins of faces set up after these (extras/held.c) */
    Poly *poly; size_t npoly, cap_poly;
    EdgeFn *edge; size_t nedge, cap_edge;
    Bin *bin; /* one per tile, row by row */
    bool *cleared; /* per tile: cleared since, its pixels not (NULL: cleared at once) */
    float clear; bool ahead; /* the cleared depth value; lines owned ahead (engine.c) */
};

typedef struct { /* simd.c's AVX2; extras/: plain C, SSE2, AVX-512: the same bits */
    /* The block at (x0, y0), its first pixel at depth[0]: its pixels of box inside e's
     * n edges (values there in 32 bits; none: all of box), *inside, tested: those that
     * passed. *farthest (when not NULL): the block's farthest value after, when every
     * row had one; or NaN. */
    uint64_t (*draw)(float *depth, int32_t *face, size_t stride, int x0, int y0, uint64_t box,
                     const EdgeFn *e, int n, const BlockDepth *d, uint64_t *inside, float *farthest);
} BlockKernels;
#define ROW(mask, j) ((int)((mask) >> (8 * (j)) & 0xff)) /* row j's 8 bits */

/* A small polygon's window 16 wide (extras/wide.c): draw's test of columns cols (bit i:
 * x0 + i) of rows y0 .. y0 + rows - 1, a row at once, n >= 1; counts to *counts if any. */
typedef void WideKernel(float *depth, int32_t *face, size_t stride, int x0, int y0, uint32_t cols,
                        int rows, const EdgeFn *e, int n, const BlockDepth *d, FragmentStats *counts);
typedef struct { /* what one thread needs to draw a tile */
    Target *t; LessonState *s; const FastRaster *fr; const BlockKernels *k; WideKernel *wide;
    FragmentStats stats;
    int tx0, ty0, tx1, ty1; /* its pixels on the screen */
    float *depth; int32_t *face; /* pixel (x, y): [(y - oy) stride + x - ox] */
    size_t stride; int ox, oy;   /* in memory, the tile's own or the target's (0, 0) */
    HierarchicalZ *hiz, own; /* &own or NULL (none); own: this thread's counts */
    _Alignas(64) float tile_depth[TILE_SIZE * TILE_SIZE]; /* a tile's own memory */
    int32_t tile_face[TILE_SIZE * TILE_SIZE];
} TileWork;

extern const BlockKernels PLAIN_KERNELS; /* extras/ (shown, not taught): kernels.c */
bool every_row(uint64_t mask); /* a pixel in each: the kernel read the whole block */
float farthest_of(const float *v, int n, bool reversed); /* of v[0 .. n - 1] */
void clear_fast(Target *t, LessonState *s); /* memory.c: each tile cleared when first drawn */
void tile_memory(TileWork *w, Bins *b, int tile); /* w->depth, w->face: its own or t's */
void write_tile(TileWork *w); /* its own memory (if so) back into the target's */
bool snap_corner(const ScreenVertex *v, Corner *c); /* engine.c; false: not finite, too far */
Bins *bins_of(Target *t, LessonState *s); /* NULL: out of memory */
bool bins_room(Bins *b, const Poly *p, int n); /* for p, of n corners */
bool bins_full(Bins *b); /* its polygons are to be drawn before more come */
void bins_empty(Bins *b); /* and the bins chained after it, unchained */
bool tile_busy(const Bins *b, int tile); /* a polygon in it, in b or after */
void draw_fast_face(Target *t, LessonState *s, const ScreenFace *f, const DrawContext *ctx);
void set_up_held_faces(Target *t, LessonState *s); /* held.c: by the threads, in chained bins */
/* pool.c: run(args + k size) for k = 0 .. n - 1 at once, each by the first thread to take it:
 * 0 by this one, not one of *pool's (started when needed, then kept); back when all are done. */
void run_threads(Pool **pool, int n, void *(*run)(void *), void *args, size_t size);
BlockDepth block_depth(const Primitive *p, bool *plain); /* plain: not finite */
Primitive plane_of(const TileWork *w, const BlockDepth *d); /* for hiz_bound: d's plane */
void tile_work_begin(TileWork *w, Target *t, LessonState *s); /* the tile buffer, kernels */
void tile_work_end(TileWork *w); /* its counts added to t's */
void draw_pixels(TileWork *w, const Poly *p, const EdgeFn *e); /* --simd pixels, counting */
uint64_t long_edge_coverage(const EdgeFn *e, int64_t at); /* at: e at the block's first */

#endif
