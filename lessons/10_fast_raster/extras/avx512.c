/* avx512.c: lesson 10's block kernel with AVX-512, shown but not taught:
 * simd.c's AVX2 kernel two block rows at a time, in one register of 16, and
 * its writes masked (no blend, no read of the faces first); a window asks
 * for no farthest value (8 x 8 only in a tile narrower than 16; else a window
 * 16 wide, extras/wide.c). The same bits as plain C: z_w in the same order,
 * mul then add, rintf's rounding. */
#include "engine.h"

#include <math.h>

#if defined(__x86_64__)
#include <immintrin.h>

#define AVX512 __attribute__((target("avx512f,avx512vl,avx512dq,avx512bw")))

/* e's values along rows y and y + 1 from x0: row y in the low 8 lanes. */
AVX512 static inline __m512i edge_pair(const EdgeFn *e, int x0, int y)
{
    __m256i at = _mm256_set1_epi32((int32_t)edge_at(e, x0, y));
    __m256i steps = _mm256_mullo_epi32(_mm256_set_epi32(7, 6, 5, 4, 3, 2, 1, 0),
                                       _mm256_set1_epi32(e->a));
    __m256i row = _mm256_add_epi32(at, steps);
    __m256i next = _mm256_add_epi32(row, _mm256_set1_epi32(e->b));
    return _mm512_inserti32x8(_mm512_castsi256_si512(row), next, 1);
}

/* simd.c's rows, two at a time: row j in the low half, j + 1 in the high.
 * A pixel is written only where it passed and is kept, each row with its
 * own mask: no pixel outside the box is stored, not even as it was. */
AVX512 static inline __attribute__((always_inline)) uint64_t
pairs(float *depth, int32_t *face, size_t stride, int x0, int y0, uint64_t box, const EdgeFn *e,
      int n, const BlockDepth *d, uint64_t *inside, float *farthest)
{
    const float gy = d->gy, unorm = d->unorm;
    const bool reversed = d->reversed;
    const uint64_t keep = d->keep;
    const __m512 offset = _mm512_set1_ps(d->offset);
    const __m256i id = _mm256_set1_epi32(d->face);
    __m512 far = _mm512_set1_ps(reversed ? INFINITY : -INFINITY);
    __m256 x = _mm256_add_ps(_mm256_set1_ps((float)x0),
                             _mm256_set_ps(7.0f, 6.0f, 5.0f, 4.0f, 3.0f, 2.0f, 1.0f, 0.0f));
    __m256 tx8 = _mm256_add_ps(_mm256_set1_ps(d->a0), _mm256_mul_ps(_mm256_set1_ps(d->gx), x));
    __m512 tx = _mm512_insertf32x8(_mm512_castps256_ps512(tx8), tx8, 1);
    uint64_t passed = 0, covered = box;
    int first = __builtin_ctzll(box) / 8, last = 7 - __builtin_clzll(box) / 8;
    const EdgeFn *e1 = &e[n > 1 ? 1 : 0], *e2 = &e[n > 2 ? 2 : n > 1 ? 1 : 0];
    __m512i v0 = _mm512_setzero_si512(), v1 = v0, v2 = v0, down0 = v0, down1 = v0, down2 = v0;
    if (n != 0)
        v0 = edge_pair(e, x0, y0 + first), v1 = edge_pair(e1, x0, y0 + first),
        v2 = edge_pair(e2, x0, y0 + first), down0 = _mm512_set1_epi32(2 * e->b),
        down1 = _mm512_set1_epi32(2 * e1->b), down2 = _mm512_set1_epi32(2 * e2->b);
    __m512i one_below = _mm512_inserti32x8(_mm512_setzero_si512(), _mm256_set1_epi32(1), 1);
    __m512i y = _mm512_add_epi32(_mm512_set1_epi32(y0 + first), one_below); /* each lane's row */
    for (int j = first; j <= last; j += 2) {
        bool two = j < last; /* row j + 1 is the box's too */
        if (n != 0) {
            __m512i any = _mm512_or_si512(_mm512_or_si512(v0, v1), v2);
            for (int k = 3; k < n; k++)
                any = _mm512_or_si512(any, edge_pair(&e[k], x0, y0 + j));
            covered &= ~((uint64_t)_mm512_movepi32_mask(any) << (8 * j));
            v0 = _mm512_add_epi32(v0, down0), v1 = _mm512_add_epi32(v1, down1);
            v2 = _mm512_add_epi32(v2, down2);
        }
        /* gy y a product in each row, as simd.c's (a sum stepped down would round apart) */
        __m512 gyy = _mm512_mul_ps(_mm512_set1_ps(gy), _mm512_cvtepi32_ps(y));
        y = _mm512_add_epi32(y, _mm512_set1_epi32(2));
        __m512 z = _mm512_add_ps(_mm512_add_ps(tx, gyy), offset);
        if (unorm != 0) {
            z = _mm512_min_ps(_mm512_set1_ps(1.0f), _mm512_max_ps(_mm512_setzero_ps(), z));
            z = _mm512_cvtepi32_ps(_mm512_cvtps_epi32(_mm512_mul_ps(z, _mm512_set1_ps(unorm))));
        }
        /* row j + 1 read only when the box reaches it: past the box may be past the buffer */
        float *row = depth + (size_t)j * stride, *below = two ? row + stride : row;
        int32_t *f = face + (size_t)j * stride;
        __m256 lo = _mm256_loadu_ps(row);
        __m512 stored = _mm512_insertf32x8(_mm512_castps256_ps512(lo), _mm256_loadu_ps(below), 1);
        __mmask16 win = reversed ? _mm512_cmp_ps_mask(z, stored, _CMP_GT_OQ)
                                 : _mm512_cmp_ps_mask(z, stored, _CMP_LT_OQ);
        unsigned rows = (unsigned)(two ? 0xffff : 0xff);
        unsigned won = (unsigned)win & (unsigned)(covered >> (8 * j)) & rows;
        unsigned kept = won & (unsigned)(keep >> (8 * j));
        passed |= (uint64_t)won << (8 * j);
        _mm256_mask_storeu_ps(row, (__mmask8)kept, _mm512_castps512_ps256(z));
        _mm256_mask_storeu_epi32(f, (__mmask8)kept, id);
        if (two)
            _mm256_mask_storeu_ps(below, (__mmask8)(kept >> 8), _mm512_extractf32x8_ps(z, 1)),
                _mm256_mask_storeu_epi32(f + stride, (__mmask8)(kept >> 8), id);
        if (farthest) { /* asked for: not by a window */
            stored = _mm512_mask_blend_ps((__mmask16)kept, stored, z);
            far = reversed ? _mm512_min_ps(far, stored) : _mm512_max_ps(far, stored);
        }
    }
    *inside = covered;
    if (!farthest)
        return passed;
    float lane[4]; /* the farthest of 16 lanes, as SSE2's of 4: in registers, not 16 in C */
    __m256 lo = _mm512_castps512_ps256(far), hi = _mm512_extractf32x8_ps(far, 1);
    __m256 half = reversed ? _mm256_min_ps(lo, hi) : _mm256_max_ps(lo, hi);
    __m128 a = _mm256_castps256_ps128(half), b = _mm256_extractf128_ps(half, 1);
    _mm_storeu_ps(lane, reversed ? _mm_min_ps(a, b) : _mm_max_ps(a, b));
    *farthest = every_row(covered) ? farthest_of(lane, 4, reversed) : NAN;
    return passed;
}

AVX512 static uint64_t avx512_draw(float *depth, int32_t *face, size_t stride, int x0, int y0,
                                   uint64_t box, const EdgeFn *e, int n, const BlockDepth *d,
                                   uint64_t *inside, float *farthest)
{
    if (farthest) /* a block, covered whole or crossed */
        return n == 0 ? pairs(depth, face, stride, x0, y0, box, e, 0, d, inside, farthest)
                      : pairs(depth, face, stride, x0, y0, box, e, n, d, inside, farthest);
    return pairs(depth, face, stride, x0, y0, box, e, n, d, inside, NULL); /* a window */
}

const BlockKernels AVX512_KERNELS = {avx512_draw};
#endif
