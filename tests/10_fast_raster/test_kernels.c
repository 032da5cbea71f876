/* test_kernels.c: lesson 10's block kernels (fast_raster.h) give the same
 * bits in plain C, SSE2 and AVX2: the coverage of random edges (and that of
 * a brute force in 64-bit integers), the depth test of random planes over
 * random buffers in every format and mapping, cutout or not: which pixels
 * passed, the depth and face buffers after it, and the block's farthest
 * value. A kernel the machine lacks (AVX2) is skipped. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "engine.h" /* extras/: the kernels of every width */
#include "fast_raster.h"
#include "test_support.h"

#define ROUNDS 20000
#define STRIDE 16 /* floats per row of the test buffer: the block and more */

static uint64_t state = 88172645463325252ull;

static uint64_t next(void) /* xorshift64: the same numbers on every machine */
{
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return state;
}

static int32_t between(int32_t lo, int32_t hi)
{
    return lo + (int32_t)(next() % (uint64_t)(hi - lo + 1));
}

static double unit(void)
{
    return (double)(next() >> 11) / 9007199254740992.0;
}

/* The kernels to compare with plain C: those this machine runs. */
static int others(const BlockKernels **k, const char **name)
{
    int n = 0;
    if (simd_best() >= SIMD_SSE2)
        k[n] = kernels_of(SIMD_SSE2), name[n++] = "sse2";
    if (simd_best() >= SIMD_AVX2)
        k[n] = kernels_of(SIMD_AVX2), name[n++] = "avx2";
    return n;
}

static void every_kernel_covers_the_pixels_of_a_brute_force(void **state_)
{
    (void)state_;
    const BlockKernels *k[2];
    const char *name[2];
    int nk = others(k, name);
    for (int round = 0; round < ROUNDS; round++) {
        int32_t g[4], a[4], b[4];
        int n = between(1, 4);
        for (int e = 0; e < n; e++) { /* values over the block within 32 bits */
            int32_t size = between(1, 1 << between(0, 26));
            a[e] = between(-size, size), b[e] = between(-size, size);
            int32_t reach = 7 * (abs(a[e]) + abs(b[e]));
            g[e] = between(-reach, reach);
        }
        uint64_t box = next() | 1, want = 0;
        for (int bit = 0; bit < 64; bit++) {
            bool inside = box >> bit & 1;
            for (int e = 0; e < n; e++)
                inside = inside && (int64_t)g[e] + (int64_t)a[e] * (bit % 8) +
                                           (int64_t)b[e] * (bit / 8) >= 0;
            want |= (uint64_t)inside << bit;
        }
        uint64_t got = PLAIN_KERNELS.coverage(g, a, b, n, box);
        if (got != want)
            fail_msg("round %d: plain C covers %016llx, the brute force %016llx", round,
                     (unsigned long long)got, (unsigned long long)want);
        for (int j = 0; j < nk; j++)
            if ((got = k[j]->coverage(g, a, b, n, box)) != want)
                fail_msg("round %d: %s covers %016llx, the brute force %016llx", round, name[j],
                         (unsigned long long)got, (unsigned long long)want);
    }
}

typedef struct { float depth[8 * STRIDE]; int32_t face[8 * STRIDE]; } Block;

static float random_stored(const BlockDepth *d)
{
    float z = (float)unit();
    return d->unorm ? rintf(z * d->unorm) : z;
}

static void every_kernel_tests_depth_as_plain_c(void **state_)
{
    (void)state_;
    const BlockKernels *k[2];
    const char *name[2];
    int nk = others(k, name);
    static const DepthFormat FORMATS[3] = {UNORM16, UNORM24, FLOAT32};
    static const float UNORM[3] = {65535.0f, 16777215.0f, 0.0f};
    for (int round = 0; round < ROUNDS; round++) {
        int f = between(0, 2);
        BlockDepth d = {(float)(unit() * 1.2 - 0.1), (float)((unit() - 0.5) * 1e-3),
                        (float)((unit() - 0.5) * 1e-3), (float)((unit() - 0.5) * 1e-5),
                        UNORM[f], next() & 1, between(0, 1000),
                        next() & 1 ? ~(uint64_t)0 : 0xf0f0f0f00f0f0f0full, FORMATS[f]};
        int x0 = 8 * between(0, 2000), y0 = 8 * between(0, 2000);
        uint64_t mask = next() & next();
        if (next() & 1)
            mask = ~(uint64_t)0; /* every row: the kernels hand back the farthest */
        Block start;
        for (int i = 0; i < 8 * STRIDE; i++)
            start.depth[i] = random_stored(&d), start.face[i] = between(-1, 1000);
        Block plain = start;
        float plain_far;
        uint64_t want = PLAIN_KERNELS.depth_test(plain.depth, plain.face, STRIDE, x0, y0, mask,
                                                 &d, &plain_far);
        float far = plain.depth[0]; /* the block's farthest value after the test */
        for (int i = 0; i < 64; i++) {
            float v = plain.depth[i / 8 * STRIDE + i % 8];
            far = d.reversed ? fminf(far, v) : fmaxf(far, v);
        }
        if (mask == ~(uint64_t)0 && plain_far != far)
            fail_msg("round %d: plain C says the farthest is %.9g, the buffer %.9g", round,
                     (double)plain_far, (double)far);
        for (int j = 0; j < nk; j++) {
            Block b = start;
            float b_far;
            uint64_t got = k[j]->depth_test(b.depth, b.face, STRIDE, x0, y0, mask, &d, &b_far);
            if (got != want)
                fail_msg("round %d: %s passed %016llx, plain C %016llx", round, name[j],
                         (unsigned long long)got, (unsigned long long)want);
            if (memcmp(&b, &plain, sizeof b) != 0)
                fail_msg("round %d: %s left other depths or faces than plain C", round, name[j]);
            if (mask == ~(uint64_t)0 && b_far != far)
                fail_msg("round %d: %s says the farthest is %.9g, the buffer %.9g", round,
                         name[j], (double)b_far, (double)far);
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_kernel_covers_the_pixels_of_a_brute_force),
        cmocka_unit_test(every_kernel_tests_depth_as_plain_c),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
