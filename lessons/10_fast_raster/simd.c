/* simd.c: lesson 10's block kernel with AVX2, a block row in one register
 * of 8 (fast_raster.h); extras/kernels.c has it in plain C and SSE2 (every
 * x86-64 has it), and chooses at run time. Each gives plain C's bits: z_w
 * in the same order, mul then add (no fused multiply-add), a unorm code
 * rounded as rintf (cvtps2dq), edge values in 32 bits only where they fit. */
#include "fast_raster.h"

#include <math.h>

#if defined(__x86_64__)
#include <immintrin.h>

#define AVX2 __attribute__((target("avx2")))

AVX2 static inline __m256i edge_values(const EdgeFn *e, int x0, int y) /* along row y from x0 */
{
    __m256i at = _mm256_set1_epi32((int32_t)edge_at(e, x0, y));
    return _mm256_add_epi32(at, _mm256_mullo_epi32(_mm256_set_epi32(7, 6, 5, 4, 3, 2, 1, 0),
                                                   _mm256_set1_epi32(e->a)));
}

/* Each row of box from its first to its last: its coverage (three edges held
 * in registers, the last again if fewer), its z_w, codes, comparison and
 * write, stored whole with a blend whatever its bits: a branch on them, often
 * mispredicted, costs more (mesh: a tenth, against the mask first). In a
 * block covered whole, a row that passes whole needs no blend. */
AVX2 static inline __attribute__((always_inline)) uint64_t
rows(float *depth, int32_t *face, size_t stride, int x0, int y0, uint64_t box, const EdgeFn *e,
     int n, const BlockDepth *d, uint64_t *inside, float *farthest)
{
    /* d's fields in locals: the stores below could alias them for the compiler */
    const float gy = d->gy, unorm = d->unorm;
    const bool reversed = d->reversed, whole = n == 0 && box == ~(uint64_t)0;
    const uint64_t keep = d->keep;
    const __m256 offset = _mm256_set1_ps(d->offset);
    __m256i id = _mm256_set1_epi32(d->face), bit = _mm256_set_epi32(128, 64, 32, 16, 8, 4, 2, 1);
    __m256 far = _mm256_set1_ps(reversed ? INFINITY : -INFINITY);
    __m256 x = _mm256_add_ps(_mm256_set1_ps((float)x0),
                             _mm256_set_ps(7.0f, 6.0f, 5.0f, 4.0f, 3.0f, 2.0f, 1.0f, 0.0f));
    __m256 tx = _mm256_add_ps(_mm256_set1_ps(d->a0), _mm256_mul_ps(_mm256_set1_ps(d->gx), x));
    uint64_t passed = 0, covered = box;
    int first = __builtin_ctzll(box) / 8, last = 7 - __builtin_clzll(box) / 8;
    const EdgeFn *e1 = &e[n > 1 ? 1 : 0], *e2 = &e[n > 2 ? 2 : n > 1 ? 1 : 0];
    __m256i v0 = _mm256_setzero_si256(), v1 = v0, v2 = v0, down0 = v0, down1 = v0, down2 = v0;
    if (n != 0) /* else none is read */
        v0 = edge_values(e, x0, y0 + first), v1 = edge_values(e1, x0, y0 + first),
        v2 = edge_values(e2, x0, y0 + first), down0 = _mm256_set1_epi32(e->b),
        down1 = _mm256_set1_epi32(e1->b), down2 = _mm256_set1_epi32(e2->b);
    for (int j = first; j <= last; j++) {
        if (n != 0) { /* an OR is negative where one of them is: outside */
            __m256i any = _mm256_or_si256(_mm256_or_si256(v0, v1), v2);
            for (int k = 3; k < n; k++)
                any = _mm256_or_si256(any, edge_values(&e[k], x0, y0 + j));
            covered &= ~((uint64_t)_mm256_movemask_ps(_mm256_castsi256_ps(any)) << (8 * j));
            v0 = _mm256_add_epi32(v0, down0), v1 = _mm256_add_epi32(v1, down1);
            v2 = _mm256_add_epi32(v2, down2);
        }
        __m256 z = _mm256_add_ps(_mm256_add_ps(tx, _mm256_set1_ps(gy * (float)(y0 + j))), offset);
        if (unorm != 0) { /* encode_depth: clamped (max, then min), scaled, rounded */
            z = _mm256_min_ps(_mm256_set1_ps(1.0f), _mm256_max_ps(_mm256_setzero_ps(), z));
            z = _mm256_cvtepi32_ps(_mm256_cvtps_epi32(_mm256_mul_ps(z, _mm256_set1_ps(unorm))));
        }
        float *row = depth + (size_t)j * stride;
        __m256i *f = (__m256i *)(face + (size_t)j * stride);
        __m256 stored = _mm256_loadu_ps(row);
        __m256 win = reversed ? _mm256_cmp_ps(z, stored, _CMP_GT_OQ)
                              : _mm256_cmp_ps(z, stored, _CMP_LT_OQ);
        int won = _mm256_movemask_ps(win) & ROW(covered, j), kept = won & ROW(keep, j);
        passed |= (uint64_t)won << (8 * j);
        if (whole && kept == 0xff) { /* the row stored as it is, no blend */
            stored = z;
            _mm256_storeu_ps(row, z);
            _mm256_storeu_si256(f, id);
        } else {
            __m256i m = _mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32(kept), bit), bit);
            stored = _mm256_blendv_ps(stored, z, _mm256_castsi256_ps(m));
            _mm256_storeu_ps(row, stored);
            _mm256_storeu_si256(f, _mm256_blendv_epi8(_mm256_loadu_si256(f), id, m));
        }
        far = reversed ? _mm256_min_ps(far, stored) : _mm256_max_ps(far, stored);
    }
    float lane[4]; /* the farthest of 8 lanes, as SSE2's of 4 */
    __m128 lo = _mm256_castps256_ps128(far), hi = _mm256_extractf128_ps(far, 1);
    _mm_storeu_ps(lane, reversed ? _mm_min_ps(lo, hi) : _mm_max_ps(lo, hi));
    *inside = covered;
    if (farthest) /* asked for: not by a window */
        *farthest = every_row(covered) ? farthest_of(lane, 4, reversed) : NAN;
    return passed;
}

AVX2 static uint64_t avx2_draw(float *depth, int32_t *face, size_t stride, int x0, int y0,
                               uint64_t box, const EdgeFn *e, int n, const BlockDepth *d,
                               uint64_t *inside, float *farthest)
{
    if (!farthest) /* a window, which asks for none */
        return rows(depth, face, stride, x0, y0, box, e, n, d, inside, NULL);
    return n == 0 ? rows(depth, face, stride, x0, y0, box, e, 0, d, inside, farthest)  /* covered */
                  : rows(depth, face, stride, x0, y0, box, e, n, d, inside, farthest); /* crossed */
}

const BlockKernels AVX2_KERNELS = {avx2_draw};
#endif
