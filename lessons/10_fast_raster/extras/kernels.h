/* kernels.h: lesson 10's block kernels (simd.c: plain C, SSE2, AVX2, the
 * same bits). Bit 8 j + i of a block's mask is its pixel (i, j). */
#ifndef KERNELS_H
#define KERNELS_H

#include "fast_raster.h"

typedef struct {
    float a0, gx, gy, offset; /* z_w = a0 + gx x + gy y + offset, in this order */
    float unorm;              /* 2^bits - 1 for a unorm format, 0 for float32 */
    bool reversed; int32_t face;
    uint64_t keep;            /* the pixels a cutout keeps (all: not a cutout) */
    DepthFormat format;
} BlockDepth;

typedef struct {
    /* The pixels of box where each g[k] + a[k] i + b[k] j >= 0 (32 bits). */
    uint64_t (*coverage)(const int32_t *g, const int32_t *a, const int32_t *b, int n,
                         uint64_t box);
    /* Tests mask's pixels of the block at (x0, y0) (its first at depth[0]):
     * those that passed; *farthest the block's farthest value then, or NaN. */
    uint64_t (*depth_test)(float *depth, int32_t *face, size_t stride, int x0, int y0,
                           uint64_t mask, const BlockDepth *d, float *farthest);
    float (*farthest)(const float *depth, size_t stride, bool reversed); /* of the 64 */
} BlockKernels;

extern const BlockKernels PLAIN_KERNELS;   /* simd.c */
const BlockKernels *kernels_of(Simd simd); /* PLAIN_KERNELS without SIMD */

#endif
