/* wide.c: lesson 10's kernels for a small polygon's window 16 pixels wide
 * (fast_raster.c's draw_windows), shown but not taught: the block kernel's
 * steps (simd.c), a row of the window at a time, in one call where windows of
 * 8 x 8 take up to 4. AVX-512 holds a row in one register; AVX2 in two, or in
 * one for a window 8 wide or less. The same bits as plain C: z_w in the same
 * order, mul then add, rintf's rounding; edge values in 32 bits. */
#include "engine.h"

#include <math.h>

#if defined(__x86_64__)
#include <immintrin.h>

#define AVX2 __attribute__((target("avx2")))
#define AVX512 __attribute__((target("avx512f,avx512vl,avx512dq,avx512bw")))

/* e's values along row y from x0, 16 of them: lanes holds 0 .. 15. */
AVX512 static inline __m512i edge_row(const EdgeFn *e, int x0, int y, __m512i lanes)
{
    return _mm512_add_epi32(_mm512_set1_epi32((int32_t)edge_at(e, x0, y)),
                            _mm512_mullo_epi32(lanes, _mm512_set1_epi32(e->a)));
}

/* A window 16 wide, a row in one register: pairs' steps (avx512.c), writes under a mask. */
AVX512 static inline __attribute__((always_inline)) void
rows16(float *depth, int32_t *face, size_t stride, int x0, int y0, uint32_t cols, int rows,
       const EdgeFn *e, int n, const BlockDepth *d, FragmentStats *counts)
{
    const float gy = d->gy, unorm = d->unorm;
    const bool reversed = d->reversed;
    const __m512 offset = _mm512_set1_ps(d->offset);
    const __m512i id = _mm512_set1_epi32(d->face);
    const __m512i lanes = _mm512_set_epi32(15, 14, 13, 12, 11, 10, 9, 8, 7, 6, 5, 4, 3, 2, 1, 0);
    __m512 x = _mm512_add_ps(_mm512_set1_ps((float)x0), _mm512_cvtepi32_ps(lanes));
    __m512 tx = _mm512_add_ps(_mm512_set1_ps(d->a0), _mm512_mul_ps(_mm512_set1_ps(d->gx), x));
    const EdgeFn *e1 = &e[n > 1 ? 1 : 0], *e2 = &e[n > 2 ? 2 : n > 1 ? 1 : 0];
    __m512i v0 = edge_row(e, x0, y0, lanes), v1 = edge_row(e1, x0, y0, lanes),
            v2 = edge_row(e2, x0, y0, lanes);
    const __m512i down0 = _mm512_set1_epi32(e->b), down1 = _mm512_set1_epi32(e1->b),
                  down2 = _mm512_set1_epi32(e2->b);
    uint64_t tested = 0, passed = 0;
    for (int j = 0; j < rows; j++) {
        __m512i any = _mm512_or_si512(_mm512_or_si512(v0, v1), v2);
        for (int k = 3; k < n; k++)
            any = _mm512_or_si512(any, edge_row(&e[k], x0, y0 + j, lanes));
        __mmask16 in = (__mmask16)(~_mm512_movepi32_mask(any) & cols);
        v0 = _mm512_add_epi32(v0, down0), v1 = _mm512_add_epi32(v1, down1);
        v2 = _mm512_add_epi32(v2, down2);
        __m512 z = _mm512_add_ps(_mm512_add_ps(tx, _mm512_set1_ps(gy * (float)(y0 + j))), offset);
        if (unorm != 0) {
            z = _mm512_min_ps(_mm512_set1_ps(1.0f), _mm512_max_ps(_mm512_setzero_ps(), z));
            z = _mm512_cvtepi32_ps(_mm512_cvtps_epi32(_mm512_mul_ps(z, _mm512_set1_ps(unorm))));
        }
        float *row = depth + (size_t)j * stride;
        __m512 stored = _mm512_loadu_ps(row); /* 16 columns of the tile: its own pixels */
        __mmask16 won = (__mmask16)((reversed ? _mm512_cmp_ps_mask(z, stored, _CMP_GT_OQ)
                                              : _mm512_cmp_ps_mask(z, stored, _CMP_LT_OQ)) & in);
        _mm512_mask_storeu_ps(row, won, z);
        _mm512_mask_storeu_epi32(face + (size_t)j * stride, won, id);
        tested += (uint64_t)__builtin_popcount(in), passed += (uint64_t)__builtin_popcount(won);
    }
    if (counts)
        counts->tested += tested, counts->passed += passed;
}

AVX512 void avx512_wide(float *depth, int32_t *face, size_t stride, int x0, int y0, uint32_t cols,
                        int rows, const EdgeFn *e, int n, const BlockDepth *d,
                        FragmentStats *counts)
{
    if (n == 3) /* a triangle's, with its 3 edges known */
        rows16(depth, face, stride, x0, y0, cols, rows, e, 3, d, counts);
    else
        rows16(depth, face, stride, x0, y0, cols, rows, e, n, d, counts);
}

/* e's values along row y from x0, 8 of them. */
AVX2 static inline __m256i edge_half(const EdgeFn *e, int x0, int y)
{
    return _mm256_add_epi32(_mm256_set1_epi32((int32_t)edge_at(e, x0, y)),
                            _mm256_mullo_epi32(_mm256_set_epi32(7, 6, 5, 4, 3, 2, 1, 0),
                                               _mm256_set1_epi32(e->a)));
}

/* z_w's 8 values, encoded as encode_depth does, tested against row[0 .. 7] where
 * in has a bit, the winners written with a blend as simd.c's rows: their bits. */
AVX2 static inline unsigned test_half(float *row, int32_t *face, __m256 z, unsigned in,
                                      float unorm, bool reversed, __m256i id)
{
    if (unorm != 0) {
        z = _mm256_min_ps(_mm256_set1_ps(1.0f), _mm256_max_ps(_mm256_setzero_ps(), z));
        z = _mm256_cvtepi32_ps(_mm256_cvtps_epi32(_mm256_mul_ps(z, _mm256_set1_ps(unorm))));
    }
    __m256 stored = _mm256_loadu_ps(row);
    unsigned won = (unsigned)_mm256_movemask_ps(reversed ? _mm256_cmp_ps(z, stored, _CMP_GT_OQ)
                                                         : _mm256_cmp_ps(z, stored, _CMP_LT_OQ)) &
                   in;
    __m256i bit = _mm256_set_epi32(128, 64, 32, 16, 8, 4, 2, 1);
    __m256i m = _mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32((int)won), bit), bit);
    _mm256_storeu_ps(row, _mm256_blendv_ps(stored, z, _mm256_castsi256_ps(m)));
    _mm256_storeu_si256((__m256i *)face,
                        _mm256_blendv_epi8(_mm256_loadu_si256((__m256i *)face), id, m));
    return won;
}

/* rows16 in two registers a row, left and right; in the left alone when not two. */
AVX2 static inline __attribute__((always_inline)) void
halves(float *depth, int32_t *face, size_t stride, int x0, int y0, uint32_t cols, int rows,
       const EdgeFn *e, int n, const BlockDepth *d, FragmentStats *counts, bool two)
{
    const float gy = d->gy, unorm = d->unorm;
    const bool reversed = d->reversed;
    const __m256 offset = _mm256_set1_ps(d->offset);
    const __m256i id = _mm256_set1_epi32(d->face);
    __m256 x = _mm256_add_ps(_mm256_set1_ps((float)x0),
                             _mm256_set_ps(7.0f, 6.0f, 5.0f, 4.0f, 3.0f, 2.0f, 1.0f, 0.0f));
    __m256 gx = _mm256_set1_ps(d->gx), a0 = _mm256_set1_ps(d->a0);
    __m256 tl = _mm256_add_ps(a0, _mm256_mul_ps(gx, x));
    __m256 tr = _mm256_add_ps(a0, _mm256_mul_ps(gx, _mm256_add_ps(x, _mm256_set1_ps(8.0f))));
    const EdgeFn *e1 = &e[n > 1 ? 1 : 0], *e2 = &e[n > 2 ? 2 : n > 1 ? 1 : 0];
    __m256i l0 = edge_half(e, x0, y0), l1 = edge_half(e1, x0, y0), l2 = edge_half(e2, x0, y0);
    __m256i r0 = l0, r1 = l1, r2 = l2;
    if (two)
        r0 = edge_half(e, x0 + 8, y0), r1 = edge_half(e1, x0 + 8, y0),
        r2 = edge_half(e2, x0 + 8, y0);
    const __m256i down0 = _mm256_set1_epi32(e->b), down1 = _mm256_set1_epi32(e1->b),
                  down2 = _mm256_set1_epi32(e2->b);
    uint64_t tested = 0, passed = 0;
    for (int j = 0; j < rows; j++) {
        __m256i left = _mm256_or_si256(_mm256_or_si256(l0, l1), l2);
        __m256i right = _mm256_or_si256(_mm256_or_si256(r0, r1), r2);
        for (int k = 3; k < n; k++) {
            left = _mm256_or_si256(left, edge_half(&e[k], x0, y0 + j));
            if (two)
                right = _mm256_or_si256(right, edge_half(&e[k], x0 + 8, y0 + j));
        }
        unsigned out = (unsigned)_mm256_movemask_ps(_mm256_castsi256_ps(left));
        if (two)
            out |= (unsigned)_mm256_movemask_ps(_mm256_castsi256_ps(right)) << 8;
        unsigned in = ~out & cols;
        l0 = _mm256_add_epi32(l0, down0), l1 = _mm256_add_epi32(l1, down1);
        l2 = _mm256_add_epi32(l2, down2);
        if (two)
            r0 = _mm256_add_epi32(r0, down0), r1 = _mm256_add_epi32(r1, down1),
            r2 = _mm256_add_epi32(r2, down2);
        __m256 ty = _mm256_set1_ps(gy * (float)(y0 + j));
        float *row = depth + (size_t)j * stride;
        int32_t *f = face + (size_t)j * stride;
        unsigned won = test_half(row, f, _mm256_add_ps(_mm256_add_ps(tl, ty), offset), in & 0xff,
                                 unorm, reversed, id);
        if (two)
            won |= test_half(row + 8, f + 8, _mm256_add_ps(_mm256_add_ps(tr, ty), offset),
                             in >> 8, unorm, reversed, id) << 8;
        tested += (uint64_t)__builtin_popcount(in), passed += (uint64_t)__builtin_popcount(won);
    }
    if (counts)
        counts->tested += tested, counts->passed += passed;
}

AVX2 void avx2_wide(float *depth, int32_t *face, size_t stride, int x0, int y0, uint32_t cols,
                    int rows, const EdgeFn *e, int n, const BlockDepth *d, FragmentStats *counts)
{
    bool two = cols >> 8 != 0; /* else the window's pixels are in its first 8 columns */
    if (n == 3 && two) /* a triangle's, with its 3 edges known */
        halves(depth, face, stride, x0, y0, cols, rows, e, 3, d, counts, true);
    else if (n == 3)
        halves(depth, face, stride, x0, y0, cols, rows, e, 3, d, counts, false);
    else
        halves(depth, face, stride, x0, y0, cols, rows, e, n, d, counts, two);
}
#endif
