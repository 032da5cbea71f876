/* kernels.c: lesson 10's block kernel (fast_raster.h) in plain C, one pixel
 * at a time, and with SSE2, a block row in two registers of 4: the same as
 * simd.c's AVX2 kernel (the page teaches that one), for --simd none and
 * sse2, for a plane only plain C takes, and for an x86-64 without AVX2. Both
 * find the pixels inside the edges first, then test them.
 * They give the same bits (simd.c says how). Then which kernels run: the
 * widest the machine has, AVX-512's (avx512.c) where it has AVX-512. */
#include "engine.h"

#include <math.h>

/* ---- Plain C: one pixel at a time ---------------------------------------- */

float farthest_of(const float *v, int n, bool reversed)
{
    float far = v[0];
    for (int i = 1; i < n; i++)
        far = reversed ? (v[i] < far ? v[i] : far) : (v[i] > far ? v[i] : far);
    return far;
}

bool every_row(uint64_t mask)
{
    uint64_t rows = mask | mask >> 4;
    rows |= rows >> 2, rows |= rows >> 1;
    return (rows & 0x0101010101010101ull) == 0x0101010101010101ull;
}

static float plain_farthest(const float *depth, size_t stride, bool reversed)
{
    float row[64];
    for (size_t i = 0; i < 64; i++)
        row[i] = depth[i / 8 * stride + i % 8];
    return farthest_of(row, 64, reversed);
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

/* The pixels of box inside e's n edges: their values there fit in 32 bits. */
typedef uint64_t Inside(const EdgeFn *e, int n, int x0, int y0, uint64_t box);
typedef uint64_t DepthTest(float *depth, int32_t *face, size_t stride, int x0, int y0,
                           uint64_t mask, const BlockDepth *d, float *farthest);

static uint64_t plain_inside(const EdgeFn *e, int n, int x0, int y0, uint64_t box)
{
    uint64_t mask = box;
    for (uint64_t left = box; left; left &= left - 1) { /* each pixel of box */
        int bit = __builtin_ctzll(left), x = x0 + bit % 8, y = y0 + bit / 8;
        for (int k = 0; k < n && mask >> bit & 1; k++)
            if (edge_at(&e[k], x, y) < 0)
                mask &= ~((uint64_t)1 << bit); /* outside edge k */
    }
    return mask;
}

/* The kernel in plain C and SSE2: the pixels inside first, then those
 * tested (none: not called, no farthest value). */
static uint64_t inside_then(Inside *cover, DepthTest *test, float *depth, int32_t *face,
                            size_t stride, int x0, int y0, uint64_t box, const EdgeFn *e, int n,
                            const BlockDepth *d, uint64_t *inside, float *farthest)
{
    float unasked; /* by a window */
    farthest = farthest ? farthest : &unasked;
    *inside = n > 0 ? cover(e, n, x0, y0, box) : box, *farthest = NAN;
    return *inside ? test(depth, face, stride, x0, y0, *inside, d, farthest) : 0;
}

static uint64_t plain_draw(float *depth, int32_t *face, size_t stride, int x0, int y0, uint64_t box,
                           const EdgeFn *e, int n, const BlockDepth *d, uint64_t *in, float *far)
{
    return inside_then(plain_inside, plain_depth_test, depth, face, stride, x0, y0, box, e, n, d,
                       in, far);
}

const BlockKernels PLAIN_KERNELS = {plain_draw};

#if defined(__x86_64__)
#include <immintrin.h>

/* ---- SSE2: a block row is two registers of 4 ---------------------------- */

static uint64_t sse2_inside(const EdgeFn *e, int n, int x0, int y0, uint64_t box)
{
    uint64_t outside = 0;
    for (int j = 0; j < 8; j++) {
        if (!ROW(box, j))
            continue;
        __m128i lo = _mm_setzero_si128(), hi = lo;
        for (int k = 0; k < n; k++) { /* an OR is negative when one of them is */
            int32_t g = (int32_t)edge_at(&e[k], x0, y0 + j);
            __m128i v = _mm_add_epi32(_mm_set1_epi32(g),
                                      _mm_set_epi32(3 * e[k].a, 2 * e[k].a, e[k].a, 0));
            lo = _mm_or_si128(lo, v);
            hi = _mm_or_si128(hi, _mm_add_epi32(v, _mm_set1_epi32(4 * e[k].a)));
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
    float lane[4];
    _mm_storeu_ps(lane, far);
    *farthest = every_row(mask) ? farthest_of(lane, 4, d->reversed) : NAN;
    return passed;
}

static uint64_t sse2_draw(float *depth, int32_t *face, size_t stride, int x0, int y0, uint64_t box,
                          const EdgeFn *e, int n, const BlockDepth *d, uint64_t *inside, float *far)
{
    return inside_then(sse2_inside, sse2_depth_test, depth, face, stride, x0, y0, box, e, n, d,
                       inside, far);
}

const BlockKernels SSE2_KERNELS = {sse2_draw};

#endif

const BlockKernels *kernels_of(Simd simd)
{
#if defined(__x86_64__)
    if (simd == SIMD_AVX512)
        return &AVX512_KERNELS;
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
    if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
        __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512bw"))
        return SIMD_AVX512;
    return __builtin_cpu_supports("avx2") ? SIMD_AVX2 : SIMD_SSE2;
#else
    return SIMD_NONE;
#endif
}
