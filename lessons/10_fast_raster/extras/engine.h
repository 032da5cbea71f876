/* engine.h: what fast_raster.c and extras/ share: the bins, a tile's work,
 * the block kernels (kernels.h). */
#ifndef ENGINE_H
#define ENGINE_H

#include "fast_raster.h"
#include "hierarchical_z.h"
#include "intmath.h"
#include "kernels.h"
#include "polygon.h"
#include "scanline.h"

typedef struct { int64_t x, y; } Corner;            /* snapped, as lesson 04 */
typedef struct { int64_t c; int32_t a, b; } EdgeFn;     /* a x + b y + c >= 0: inside */

typedef struct {
    BlockDepth depth;
    int x0, y0, x1, y1;  /* the pixels it may cover, on the screen */
    uint32_t first, n;   /* its edges in the bins */
    bool plain;          /* a plane only plain C takes */
    int turn;
} Poly;

typedef struct { uint32_t *at; size_t n, cap; long work; } Bin; /* polygons, in the order
                                                                 drawn; their boxes' pixels */

struct Bins {
    const Target *target; int tiles_x, tiles_y;
    Bins *next; /* the bins of faces set up after these (held.c) */
    Poly *poly; size_t npoly, cap_poly;
    EdgeFn *edge; size_t nedge, cap_edge;
    Bin *bin; /* one per tile, row by row */
    bool *cleared; /* per tile: cleared since, its pixels not (NULL: cleared at once) */
    float clear;   /* the cleared depth value */
};

typedef struct { /* what one thread needs to draw a tile */
    Target *t; LessonState *s; const FastRaster *fr; const BlockKernels *k;
    FragmentStats stats;
    int tx0, ty0, tx1, ty1; /* its pixels on the screen */
    float *depth; int32_t *face; /* pixel (x, y): [(y - oy) stride + x - ox] */
    size_t stride; int ox, oy;   /* in memory, the tile's own or the target's (0, 0) */
    HierarchicalZ *hiz;     /* &own, or NULL: none */
    HierarchicalZ own;      /* the tile buffer, with this thread's counts */
    _Alignas(64) float tile_depth[TILE_SIZE * TILE_SIZE]; /* a tile's own memory */
    int32_t tile_face[TILE_SIZE * TILE_SIZE];
} TileWork;

uint64_t popcount(uint64_t mask);
int64_t snap(double pixels); /* lesson 04's floor(pixels S + 1/2), without a call */

/* engine.c: bins, set-up, a fragment in plain C. */
Bins *bins_of(Target *t, LessonState *s);
bool bins_room(Bins *b, const Poly *p, int n); /* for p, of n corners */
void bins_empty(Bins *b); /* and the bins chained after it, unchained */
bool tile_busy(const Bins *b, int tile); /* a polygon in it, in b or after */
void fast_flush(Target *t, LessonState *s); /* the bins drawn, the frame not finished */
void draw_fast_face(Target *t, LessonState *s, const ScreenFace *f, const DrawContext *ctx);
void set_up_held_faces(Target *t, LessonState *s); /* held.c: by the threads, in chained bins */
/* p's plane and format; plain: not finite. */
BlockDepth block_depth(const Primitive *p, bool *plain);
bool corner_in_range(const ScreenVertex *v);
bool test_pixel(TileWork *w, const BlockDepth *d, int x, int y);
Primitive plane_of(const TileWork *w, const BlockDepth *d); /* for hiz_bound: d's plane */
void tile_work_begin(TileWork *w, Target *t, LessonState *s); /* the tile buffer, kernels */
void tile_work_end(TileWork *w); /* its counts added to t's */
uint64_t box_mask(int left, int right, int top, int bottom); /* of a block, each in 0..8 */
typedef struct { int x, y; uint64_t box; } Window; /* 8 x 8 pixels at (x, y), of box */
int windows_of(const TileWork *w, const Poly *p, Window win[4]); /* 0: p larger */
void draw_pixels(TileWork *w, const Poly *p, const EdgeFn *e); /* --simd pixels */
uint64_t long_edge_coverage(const EdgeFn *e, int64_t at); /* at: e at the block's first */
void clear_fast(Target *t, LessonState *s); /* each tile cleared when first drawn */

#endif
