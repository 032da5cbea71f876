/* kernels.c: lesson 10's block kernel (fast_raster.h) in plain C, one pixel
 * at a time, and with SSE2, a block row in two registers of 4: the same as
 * simd.c's AVX2 kernel (the page teaches that one), for --simd none and
 * sse2, for a plane only plain C takes, and for an x86-64 without AVX2.
 * Plain C finds the pixels inside the edges first, then tests them; SSE2
 * does both a row at a time, as AVX2 does.
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

/* The pixels inside first, then those tested (none: not called, no farthest value). */
static uint64_t plain_draw(float *depth, int32_t *face, size_t stride, int x0, int y0, uint64_t box,
                           const EdgeFn *e, int n, const BlockDepth *d, uint64_t *inside,
                           float *farthest)
{
    float unasked; /* by a window */
    farthest = farthest ? farthest : &unasked;
    *inside = n > 0 ? plain_inside(e, n, x0, y0, box) : box, *farthest = NAN;
    return *inside ? plain_depth_test(depth, face, stride, x0, y0, *inside, d, farthest) : 0;
}

const BlockKernels PLAIN_KERNELS = {plain_draw};

#if defined(__x86_64__)
#include <immintrin.h>

/* ---- SSE2: a block row is two registers of 4 ---------------------------- */

/* e's values along row y from x0: pixels 0 to 3 in *lo, 4 to 7 in *hi. */
static inline void sse2_edge_values(const EdgeFn *e, int x0, int y, __m128i *lo, __m128i *hi)
{
    *lo = _mm_add_epi32(_mm_set1_epi32((int32_t)edge_at(e, x0, y)),
                        _mm_set_epi32(3 * e->a, 2 * e->a, e->a, 0));
    *hi = _mm_add_epi32(*lo, _mm_set1_epi32(4 * e->a));
}

/* Half a row's z_w from its x and y terms, encoded as encode_depth encodes
 * it: clamped (max, then min), scaled and rounded for a unorm format. */
static inline __m128 sse2_z(__m128 tx, __m128 ty, __m128 offset, float unorm)
{
    __m128 z = _mm_add_ps(_mm_add_ps(tx, ty), offset);
    if (unorm == 0)
        return z;
    z = _mm_min_ps(_mm_set1_ps(1.0f), _mm_max_ps(_mm_setzero_ps(), z));
    return _mm_cvtepi32_ps(_mm_cvtps_epi32(_mm_mul_ps(z, _mm_set1_ps(unorm))));
}

static inline int sse2_wins(__m128 z, __m128 stored, bool reversed) /* a bit per lane */
{
    return _mm_movemask_ps(reversed ? _mm_cmpgt_ps(z, stored) : _mm_cmplt_ps(z, stored));
}

/* Half a row stored whole: z in the lanes whose bit (lane i: bit[i]) kept
 * has, else what was stored (a blend by AND and OR: SSE2 has no blendv); all:
 * every lane z. What it now holds. */
static inline __m128 sse2_write(float *row, int32_t *f, __m128 z, __m128 stored, int kept,
                                __m128i bit, __m128i id, bool all)
{
    if (all) {
        stored = z;
        _mm_storeu_si128((__m128i *)f, id);
    } else {
        __m128i m = _mm_cmpeq_epi32(_mm_and_si128(_mm_set1_epi32(kept), bit), bit);
        __m128 mf = _mm_castsi128_ps(m);
        stored = _mm_or_ps(_mm_and_ps(mf, z), _mm_andnot_ps(mf, stored));
        __m128i was = _mm_loadu_si128((const __m128i *)f);
        _mm_storeu_si128((__m128i *)f,
                         _mm_or_si128(_mm_and_si128(m, id), _mm_andnot_si128(m, was)));
    }
    _mm_storeu_ps(row, stored);
    return stored;
}

/* simd.c's rows with a row in two halves of 4: its coverage (three edges held
 * in registers), z_w, codes, comparison and write, stored whole; in a block
 * covered whole, a row that passes whole needs no blend. half: the first half
 * alone, box having no pixel in the other (nor is a farthest value asked). */
static inline __attribute__((always_inline)) uint64_t
sse2_rows(float *depth, int32_t *face, size_t stride, int x0, int y0, uint64_t box,
          const EdgeFn *e, int n, bool half, const BlockDepth *d, uint64_t *inside,
          float *farthest)
{
    const float gy = d->gy, unorm = d->unorm;
    const bool reversed = d->reversed, whole = n == 0 && box == ~(uint64_t)0;
    const uint64_t keep = d->keep;
    const __m128 offset = _mm_set1_ps(d->offset), a0 = _mm_set1_ps(d->a0), gx = _mm_set1_ps(d->gx);
    const __m128i id = _mm_set1_epi32(d->face);
    const __m128i bit_lo = _mm_set_epi32(8, 4, 2, 1), bit_hi = _mm_set_epi32(128, 64, 32, 16);
    __m128 far = _mm_set1_ps(reversed ? INFINITY : -INFINITY);
    __m128 x_lo = _mm_add_ps(_mm_set1_ps((float)x0), _mm_set_ps(3.0f, 2.0f, 1.0f, 0.0f));
    __m128 x_hi = _mm_add_ps(x_lo, _mm_set1_ps(4.0f)); /* exact: integers below 2^24 */
    __m128 tx_lo = _mm_add_ps(a0, _mm_mul_ps(gx, x_lo));
    __m128 tx_hi = _mm_add_ps(a0, _mm_mul_ps(gx, x_hi));
    uint64_t passed = 0, covered = box;
    int first = __builtin_ctzll(box) / 8, last = 7 - __builtin_clzll(box) / 8;
    const EdgeFn *e1 = &e[n > 1 ? 1 : 0], *e2 = &e[n > 2 ? 2 : n > 1 ? 1 : 0];
    __m128i v0 = _mm_setzero_si128(), v1 = v0, v2 = v0, w0 = v0, w1 = v0, w2 = v0; /* lo, hi */
    __m128i down0 = v0, down1 = v0, down2 = v0;
    if (n != 0) /* else none is read */
        sse2_edge_values(e, x0, y0 + first, &v0, &w0),
        sse2_edge_values(e1, x0, y0 + first, &v1, &w1),
        sse2_edge_values(e2, x0, y0 + first, &v2, &w2), down0 = _mm_set1_epi32(e->b),
        down1 = _mm_set1_epi32(e1->b), down2 = _mm_set1_epi32(e2->b);
    for (int j = first; j <= last; j++) {
        if (n != 0) { /* an OR is negative where one of them is: outside */
            __m128i lo = _mm_or_si128(_mm_or_si128(v0, v1), v2);
            __m128i hi = _mm_or_si128(_mm_or_si128(w0, w1), w2);
            for (int k = 3; k < n; k++) {
                __m128i l, h;
                sse2_edge_values(&e[k], x0, y0 + j, &l, &h);
                lo = _mm_or_si128(lo, l), hi = _mm_or_si128(hi, h);
            }
            int out = _mm_movemask_ps(_mm_castsi128_ps(lo)) |
                      (half ? 0 : _mm_movemask_ps(_mm_castsi128_ps(hi)) << 4);
            covered &= ~((uint64_t)out << (8 * j));
            v0 = _mm_add_epi32(v0, down0), v1 = _mm_add_epi32(v1, down1);
            v2 = _mm_add_epi32(v2, down2), w0 = _mm_add_epi32(w0, down0);
            w1 = _mm_add_epi32(w1, down1), w2 = _mm_add_epi32(w2, down2);
        }
        __m128 ty = _mm_set1_ps(gy * (float)(y0 + j));
        __m128 z_lo = sse2_z(tx_lo, ty, offset, unorm), z_hi = sse2_z(tx_hi, ty, offset, unorm);
        float *row = depth + (size_t)j * stride;
        int32_t *f = face + (size_t)j * stride;
        __m128 lo = _mm_loadu_ps(row), hi = half ? lo : _mm_loadu_ps(row + 4);
        int won = sse2_wins(z_lo, lo, reversed) | (half ? 0 : sse2_wins(z_hi, hi, reversed) << 4);
        won &= ROW(covered, j);
        int kept = won & ROW(keep, j);
        passed |= (uint64_t)won << (8 * j);
        bool all = whole && kept == 0xff; /* the row stored as it is, no blend */
        lo = sse2_write(row, f, z_lo, lo, kept, bit_lo, id, all);
        if (!half)
            hi = sse2_write(row + 4, f + 4, z_hi, hi, kept, bit_hi, id, all);
        if (farthest) /* asked for: not by a window */
            far = reversed ? _mm_min_ps(far, _mm_min_ps(lo, hi))
                           : _mm_max_ps(far, _mm_max_ps(lo, hi));
    }
    *inside = covered;
    if (farthest) {
        float lane[4];
        _mm_storeu_ps(lane, far);
        *farthest = every_row(covered) ? farthest_of(lane, 4, reversed) : NAN;
    }
    return passed;
}

/* A window asks for no farthest value: one 4 pixels wide or less (its box
 * starts at its first column, but where moved left) in its first half
 * alone; a triangle's with its 3 edges known. */
static uint64_t sse2_draw(float *depth, int32_t *face, size_t stride, int x0, int y0, uint64_t box,
                          const EdgeFn *e, int n, const BlockDepth *d, uint64_t *inside, float *far)
{
    bool half = !(box & 0xf0f0f0f0f0f0f0f0ull);
    if (!far && n == 3)
        return half ? sse2_rows(depth, face, stride, x0, y0, box, e, 3, true, d, inside, NULL)
                    : sse2_rows(depth, face, stride, x0, y0, box, e, 3, false, d, inside, NULL);
    if (!far)
        return half ? sse2_rows(depth, face, stride, x0, y0, box, e, n, true, d, inside, NULL)
                    : sse2_rows(depth, face, stride, x0, y0, box, e, n, false, d, inside, NULL);
    if (n == 0) /* a block covered whole */
        return sse2_rows(depth, face, stride, x0, y0, box, e, 0, false, d, inside, far);
    return sse2_rows(depth, face, stride, x0, y0, box, e, n, false, d, inside, far); /* crossed */
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

WideKernel *wide_of(Simd simd)
{
#if defined(__x86_64__)
    if (simd == SIMD_AVX512)
        return avx512_wide;
    if (simd == SIMD_AVX2)
        return avx2_wide;
#endif
    (void)simd;
    return NULL;
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
