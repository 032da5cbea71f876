/* simd.c: lesson 10's block kernels (engine.h): in plain C, with SSE2 (4
 * pixels at once, every x86-64 has it) and with AVX2 (8, chosen at run
 * time). The SIMD kernels give the plain C kernels' bits exactly: z_w in the same order, one rounding per
 * operation and no fused multiply-add (mul, then add), a unorm code rounded
 * as rintf rounds (cvtps2dq, to nearest even), and edge values in 32-bit
 * integers only where they fit. */
#include "engine.h"

#include <math.h>

/* ---- Plain C: one pixel at a time ---------------------------------------- */

static uint64_t plain_coverage(const int32_t *g, const int32_t *a, const int32_t *b, int n,
                               uint64_t box)
{
    uint64_t mask = 0;
    for (int bit = 0; bit < 64; bit++) {
        bool inside = box >> bit & 1;
        for (int k = 0; k < n && inside; k++)
            inside = g[k] + a[k] * (bit % 8) + b[k] * (bit / 8) >= 0;
        mask |= (uint64_t)inside << bit;
    }
    return mask;
}

static float plain_farthest(const float *depth, size_t stride, bool reversed)
{
    float far = depth[0];
    for (size_t i = 0; i < 64; i++) {
        float v = depth[i / 8 * stride + i % 8];
        far = reversed ? (v < far ? v : far) : (v > far ? v : far);
    }
    return far;
}

/* z_w in lesson 06's order, encoded by its encode_depth. */
static uint64_t plain_depth_test(float *depth, int32_t *face, size_t stride, int x0, int y0,
                                 uint64_t mask, const BlockDepth *d, float *farthest)
{
    uint64_t passed = 0;
    for (int bit = 0; bit < 64; bit++) {
        if (!(mask >> bit & 1))
            continue;
        int x = bit % 8, y = bit / 8;
        size_t i = (size_t)y * stride + (size_t)x;
        float z_w = d->a0 + d->gx * (float)(x0 + x) + d->gy * (float)(y0 + y) + d->offset;
        float value = encode_depth(d->format, z_w);
        if (d->reversed ? value > depth[i] : value < depth[i]) {
            passed |= (uint64_t)1 << bit;
            if (d->keep >> bit & 1)
                depth[i] = value, face[i] = d->face;
        }
    }
    /* Only a block it covers whole: at the screen's right edge, a row is cut short. */
    *farthest = mask == ~(uint64_t)0 ? plain_farthest(depth, stride, d->reversed) : NAN;
    return passed;
}

const BlockKernels PLAIN_KERNELS = {plain_coverage, plain_depth_test, plain_farthest};

#if defined(__x86_64__)
#include <immintrin.h>

#define ROW(mask, j) ((int)((mask) >> (8 * (j)) & 0xff)) /* row j's 8 bits */

static bool every_row(uint64_t mask) /* a pixel in each: the kernel read the whole block */
{
    uint64_t rows = mask | mask >> 4;
    rows |= rows >> 2, rows |= rows >> 1;
    return (rows & 0x0101010101010101ull) == 0x0101010101010101ull;
}

/* ---- SSE2: a block row is two registers of 4 ---------------------------- */

static uint64_t sse2_coverage(const int32_t *g, const int32_t *a, const int32_t *b, int n,
                              uint64_t box)
{
    uint64_t outside = 0;
    for (int j = 0; j < 8; j++) {
        if (!ROW(box, j))
            continue;
        __m128i lo = _mm_setzero_si128(), hi = lo;
        for (int k = 0; k < n; k++) { /* an OR is negative when one of them is */
            __m128i v = _mm_add_epi32(_mm_set1_epi32(g[k] + j * b[k]),
                                      _mm_set_epi32(3 * a[k], 2 * a[k], a[k], 0));
            lo = _mm_or_si128(lo, v);
            hi = _mm_or_si128(hi, _mm_add_epi32(v, _mm_set1_epi32(4 * a[k])));
        }
        int bits = _mm_movemask_ps(_mm_castsi128_ps(lo)) |
                   _mm_movemask_ps(_mm_castsi128_ps(hi)) << 4;
        outside |= (uint64_t)bits << (8 * j);
    }
    return box & ~outside;
}

/* encode_depth: clamped to [0, 1] (max, then min: a NaN would stay), times
 * 2^bits - 1, rounded to the nearest integer. */
static __m128 sse2_encode(__m128 z, float unorm)
{
    if (unorm == 0)
        return z;
    z = _mm_min_ps(_mm_set1_ps(1.0f), _mm_max_ps(_mm_setzero_ps(), z));
    return _mm_cvtepi32_ps(_mm_cvtps_epi32(_mm_mul_ps(z, _mm_set1_ps(unorm))));
}

static __m128i sse2_lanes(int bits, __m128i bit) /* all ones in the lanes of bits */
{
    return _mm_cmpeq_epi32(_mm_and_si128(_mm_set1_epi32(bits), bit), bit);
}

static int sse2_half(float *depth, int32_t *face, __m128 tx, __m128 ty, int bits,
                     const BlockDepth *d, __m128 *far)
{
    __m128 z = _mm_add_ps(_mm_add_ps(tx, ty), _mm_set1_ps(d->offset));
    __m128 value = sse2_encode(z, d->unorm), stored = _mm_loadu_ps(depth);
    __m128 win = d->reversed ? _mm_cmpgt_ps(value, stored) : _mm_cmplt_ps(value, stored);
    int passed = _mm_movemask_ps(win) & bits, kept = passed & (int)(d->keep & 0xf);
    __m128i m = sse2_lanes(kept, _mm_set_epi32(8, 4, 2, 1)); /* stored whole: no branch */
    __m128i f = _mm_loadu_si128((const __m128i *)face);
    stored = _mm_or_ps(_mm_and_ps(_mm_castsi128_ps(m), value),
                       _mm_andnot_ps(_mm_castsi128_ps(m), stored));
    _mm_storeu_ps(depth, stored);
    _mm_storeu_si128((__m128i *)face, _mm_or_si128(_mm_and_si128(m, _mm_set1_epi32(d->face)),
                                                   _mm_andnot_si128(m, f)));
    *far = d->reversed ? _mm_min_ps(*far, stored) : _mm_max_ps(*far, stored);
    return passed;
}

static float sse2_lanes_farthest(__m128 far, bool reversed)
{
    float lane[4];
    _mm_storeu_ps(lane, far);
    float f = lane[0];
    for (int k = 1; k < 4; k++)
        f = reversed ? (lane[k] < f ? lane[k] : f) : (lane[k] > f ? lane[k] : f);
    return f;
}

static uint64_t sse2_depth_test(float *depth, int32_t *face, size_t stride, int x0, int y0,
                                uint64_t mask, const BlockDepth *d, float *farthest)
{
    __m128 far = _mm_set1_ps(d->reversed ? INFINITY : -INFINITY);
    __m128 a0 = _mm_set1_ps(d->a0), gx = _mm_set1_ps(d->gx);
    __m128 x_lo = _mm_set_ps((float)(x0 + 3), (float)(x0 + 2), (float)(x0 + 1), (float)x0);
    __m128 x_hi = _mm_add_ps(x_lo, _mm_set1_ps(4.0f)); /* exact: integers below 2^24 */
    __m128 tx_lo = _mm_add_ps(a0, _mm_mul_ps(gx, x_lo)), tx_hi = _mm_add_ps(a0, _mm_mul_ps(gx, x_hi));
    BlockDepth lo = *d, hi = *d;
    uint64_t passed = 0;
    int first = __builtin_ctzll(mask) / 8, last = 7 - __builtin_clzll(mask) / 8;
    for (int j = first; j <= last; j++) { /* the rows of mask, every one whole */
        int bits = ROW(mask, j);
        __m128 ty = _mm_set1_ps(d->gy * (float)(y0 + j));
        lo.keep = d->keep >> (8 * j), hi.keep = d->keep >> (8 * j + 4);
        size_t at = (size_t)j * stride;
        int row = sse2_half(depth + at, face + at, tx_lo, ty, bits & 0xf, &lo, &far) |
                  sse2_half(depth + at + 4, face + at + 4, tx_hi, ty, bits >> 4, &hi, &far) << 4;
        passed |= (uint64_t)row << (8 * j);
    }
    *farthest = every_row(mask) ? sse2_lanes_farthest(far, d->reversed) : NAN;
    return passed;
}

static float sse2_farthest(const float *depth, size_t stride, bool reversed)
{
    __m128 far = _mm_loadu_ps(depth);
    for (size_t j = 0; j < 8; j++)
        for (size_t h = 0; h < 8; h += 4) {
            __m128 v = _mm_loadu_ps(depth + j * stride + h);
            far = reversed ? _mm_min_ps(far, v) : _mm_max_ps(far, v);
        }
    return sse2_lanes_farthest(far, reversed);
}

static const BlockKernels SSE2_KERNELS = {sse2_coverage, sse2_depth_test, sse2_farthest};

/* ---- AVX2: a block row is one register of 8 ----------------------------- */

#define AVX2 __attribute__((target("avx2")))

AVX2 static __m256i avx2_edge_row(const int32_t *g, const int32_t *a, const int32_t *b, int k,
                                  int j) /* edge k's values along row j */
{
    return _mm256_add_epi32(_mm256_set1_epi32(g[k] + j * b[k]),
                            _mm256_mullo_epi32(_mm256_set_epi32(7, 6, 5, 4, 3, 2, 1, 0),
                                               _mm256_set1_epi32(a[k])));
}

AVX2 static uint64_t avx2_coverage(const int32_t *g, const int32_t *a, const int32_t *b, int n,
                                   uint64_t box)
{
    int first = __builtin_ctzll(box) / 8, last = 7 - __builtin_clzll(box) / 8;
    uint64_t outside = 0;
    for (int k = 0; k < n; k += 3) { /* three edges at a time; the last again if fewer */
        int k1 = k + 1 < n ? k + 1 : k, k2 = k + 2 < n ? k + 2 : k1;
        __m256i v0 = avx2_edge_row(g, a, b, k, first), down0 = _mm256_set1_epi32(b[k]);
        __m256i v1 = avx2_edge_row(g, a, b, k1, first), down1 = _mm256_set1_epi32(b[k1]);
        __m256i v2 = avx2_edge_row(g, a, b, k2, first), down2 = _mm256_set1_epi32(b[k2]);
        for (int j = first; j <= last; j++) { /* an OR is negative when one of them is */
            __m256i any = _mm256_or_si256(_mm256_or_si256(v0, v1), v2);
            outside |= (uint64_t)_mm256_movemask_ps(_mm256_castsi256_ps(any)) << (8 * j);
            v0 = _mm256_add_epi32(v0, down0), v1 = _mm256_add_epi32(v1, down1);
            v2 = _mm256_add_epi32(v2, down2);
        }
    }
    return box & ~outside;
}

AVX2 static float avx2_lanes_farthest(__m256 far, bool reversed)
{
    __m128 lo = _mm256_castps256_ps128(far), hi = _mm256_extractf128_ps(far, 1);
    return sse2_lanes_farthest(reversed ? _mm_min_ps(lo, hi) : _mm_max_ps(lo, hi), reversed);
}

AVX2 static uint64_t avx2_depth_test(float *depth, int32_t *face, size_t stride, int x0, int y0,
                                     uint64_t mask, const BlockDepth *d, float *farthest)
{
    /* d's fields in locals: the stores below could alias them for the compiler */
    const float gy = d->gy, unorm = d->unorm;
    const bool reversed = d->reversed;
    const uint64_t keep = d->keep;
    const __m256 offset = _mm256_set1_ps(d->offset);
    const __m256i id = _mm256_set1_epi32(d->face);
    __m256 far = _mm256_set1_ps(reversed ? INFINITY : -INFINITY);
    __m256 x = _mm256_add_ps(_mm256_set1_ps((float)x0),
                             _mm256_set_ps(7.0f, 6.0f, 5.0f, 4.0f, 3.0f, 2.0f, 1.0f, 0.0f));
    __m256 tx = _mm256_add_ps(_mm256_set1_ps(d->a0), _mm256_mul_ps(_mm256_set1_ps(d->gx), x));
    __m256i bit = _mm256_set_epi32(128, 64, 32, 16, 8, 4, 2, 1);
    uint64_t passed = 0;
    int first = __builtin_ctzll(mask) / 8, last = 7 - __builtin_clzll(mask) / 8;
    /* Every row from mask's first to its last is stored whole, even when no
     * pixel passes: a branch on a row's bits, often mispredicted, costs more
     * than a blend. Only in a block the polygon covers whole, where rows
     * tend to pass alike, a row that passes whole skips the blend. */
    bool whole = mask == ~(uint64_t)0;
    for (int j = first; j <= last; j++) {
        int bits = ROW(mask, j);
        __m256 z = _mm256_add_ps(_mm256_add_ps(tx, _mm256_set1_ps(gy * (float)(y0 + j))), offset);
        if (unorm != 0) {
            z = _mm256_min_ps(_mm256_set1_ps(1.0f), _mm256_max_ps(_mm256_setzero_ps(), z));
            z = _mm256_cvtepi32_ps(_mm256_cvtps_epi32(_mm256_mul_ps(z, _mm256_set1_ps(unorm))));
        }
        float *row = depth + (size_t)j * stride;
        __m256i *f = (__m256i *)(face + (size_t)j * stride);
        __m256 stored = _mm256_loadu_ps(row);
        __m256 win = reversed ? _mm256_cmp_ps(z, stored, _CMP_GT_OQ)
                              : _mm256_cmp_ps(z, stored, _CMP_LT_OQ);
        int won = _mm256_movemask_ps(win) & bits, kept = won & ROW(keep, j);
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
    *farthest = every_row(mask) ? avx2_lanes_farthest(far, reversed) : NAN;
    return passed;
}

AVX2 static float avx2_farthest(const float *depth, size_t stride, bool reversed)
{
    __m256 far = _mm256_loadu_ps(depth);
    for (size_t j = 1; j < 8; j++) {
        __m256 v = _mm256_loadu_ps(depth + j * stride);
        far = reversed ? _mm256_min_ps(far, v) : _mm256_max_ps(far, v);
    }
    return avx2_lanes_farthest(far, reversed);
}

static const BlockKernels AVX2_KERNELS = {avx2_coverage, avx2_depth_test, avx2_farthest};

#endif

const BlockKernels *kernels_of(Simd simd)
{
#if defined(__x86_64__)
    if (simd == SIMD_AVX2)
        return &AVX2_KERNELS;
    if (simd == SIMD_SSE2)
        return &SSE2_KERNELS;
#endif
    (void)simd;
    return &PLAIN_KERNELS;
}

Simd simd_best(void)
{
#if defined(__x86_64__)
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") ? SIMD_AVX2 : SIMD_SSE2;
#else
    return SIMD_NONE;
#endif
}
