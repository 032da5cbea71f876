/* fast_raster.h: lesson 10, a fast rasterizer (docs/10_fast_raster.md).
 * Lesson 09's pictures, drawn as Mesa's llvmpipe draws:
 *   bins     each polygon in the bin of every screen tile it may touch;
 *            fast_finish draws the tiles, each its polygons in order
 *   blocks   edge functions at a block's corners take or reject it whole;
 *            a block an edge crosses is tested per pixel (lesson 04's rule)
 *   depth    lessons 06 to 09's: a block lesson 09's tile buffer hides is skipped
 *   memory   a busy tile drawn in 32 KB of its thread's own; each tile cleared
 *            when it is first drawn, or at fast_finish
 *   SIMD     a block row at once: SSE2 4 pixels, AVX2 8
 *   threads  tiles handed out one at a time: no two share a pixel */
#ifndef FAST_RASTER_H
#define FAST_RASTER_H

#include <stdint.h>

#include "depth_buffer.h"

#define TILE_SIZE 64 /* pixels: a tile is 8 x 8 blocks */
#define BLOCK_SIZE 8 /* pixels: a block row is one AVX2 register of floats */

typedef enum { SIMD_PIXELS, SIMD_NONE, SIMD_SSE2, SIMD_AVX2 } Simd; /* pixels: no blocks */
typedef struct Bins Bins; /* what waits for fast_finish (extras/engine.h) */
typedef struct Held Held; /* faces held back for the threads to set up */

typedef struct {
    Simd simd;        /* the widest this machine has, or --simd */
    int threads;      /* --threads */
    bool count;       /* overdraw[] and --trace: plain C, one thread */
    uint64_t keep;    /* the face's pixels a cutout keeps, in any block */
    Bins *bins; Held *held;
    bool set_up_only; /* a thread's copy, setting faces up: it never draws */
    bool out_of_memory; /* an allocation failed: a face or a tile went undrawn */
} FastRaster;

/* The lesson's state (state.h): depth, the engine, no tile buffer yet. */
LessonState fast_raster(DepthSetup depth, Simd simd, int threads, bool count);
Simd simd_best(void);
/* Draws every tile's bin and clears every tile not yet cleared: the picture
 * is done. False, with err (when not NULL) set, when memory ran out for a
 * face or a tile since the clear: the picture is not whole. */
bool fast_finish(Target *t, LessonState *s, Error *err);
void fast_raster_free(FastRaster *fr);

/* The clear (each tile's waits for it to be drawn); each face set up as
 * lesson 07 sets it up, its polygons binned; then fast_finish draws them. */
extern const Rasterizer FAST_ZBUFFER;

#endif
