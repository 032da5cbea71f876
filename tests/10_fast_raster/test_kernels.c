/* test_kernels.c: lesson 10's block kernel (fast_raster.h) gives the same
 * bits in plain C, SSE2, AVX2 and AVX-512: the pixels of a box inside 0 to 5 random
 * edges (and those of a brute force in 64-bit integers), then the depth test
 * of random planes over random buffers in every format and mapping, cutout or
 * not: which pixels passed, the depth and face buffers after it, and the
 * block's farthest value; half the time none is asked for (farthest NULL, as
 * a window asks), which SSE2 draws by a copy of its own for 3 edges,
 * and a box in a quarter of the rounds is a window's: columns from the first,
 * 1 to 8 of them (SSE2 draws one of 4 or fewer in half its registers).
 * A kernel's window 16 pixels wide (AVX2's and AVX-512's wide) leaves the bits
 * and counts of plain C's 8 x 8 windows over the same pixels, from any column.
 * A kernel the machine lacks (AVX2, AVX-512) is skipped. */
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
    if (simd_best() >= SIMD_AVX512)
        k[n] = kernels_of(SIMD_AVX512), name[n++] = "avx512";
    return n;
}

typedef struct { float depth[8 * STRIDE]; int32_t face[8 * STRIDE]; } Block;

/* n random edges whose values over the block at (x0, y0) fit in 32 bits, as
 * the kernel's contract asks. */
static void random_edges(EdgeFn *e, int n, int x0, int y0)
{
    for (int k = 0; k < n; k++) {
        int32_t size = between(1, 1 << between(0, 26));
        e[k].a = between(-size, size), e[k].b = between(-size, size);
        int32_t reach = 7 * (abs(e[k].a) + abs(e[k].b)), g = between(-reach, reach);
        e[k].c = g - (int64_t)e[k].a * x0 - (int64_t)e[k].b * y0; /* g at the block's first */
    }
}

/* A window's box: w columns from the first, h rows from the first (each 1 to 8). */
static uint64_t window_box(void)
{
    int w = between(1, 8), h = between(1, 8);
    uint64_t row = ((uint64_t)1 << w) - 1, box = 0;
    for (int j = 0; j < h; j++)
        box |= row << (8 * j);
    return box;
}

static void every_kernel_covers_the_pixels_of_a_brute_force(void **state_)
{
    (void)state_;
    const BlockKernels *k[3];
    const char *name[3];
    int nk = others(k, name);
    BlockDepth d = {0, 0, 0, 0, 0, 7, ~(uint64_t)0, FLOAT32, false}; /* z_w 0: every pixel passes */
    for (int round = 0; round < ROUNDS; round++) {
        EdgeFn e[5];
        int n = between(0, 5), x0 = 8 * between(0, 2000), y0 = 8 * between(0, 2000);
        random_edges(e, n, x0, y0);
        uint64_t box = next() % 4 == 0 ? window_box() : next() | 1, want = 0;
        for (int bit = 0; bit < 64; bit++) {
            bool inside = box >> bit & 1;
            for (int j = 0; j < n; j++)
                inside = inside && e[j].c + (int64_t)e[j].a * (x0 + bit % 8) +
                                           (int64_t)e[j].b * (y0 + bit / 8) >= 0;
            want |= (uint64_t)inside << bit;
        }
        for (int j = -1; j < nk; j++) {
            const BlockKernels *kj = j < 0 ? &PLAIN_KERNELS : k[j];
            Block b;
            for (int i = 0; i < 8 * STRIDE; i++)
                b.depth[i] = 1.0f, b.face[i] = -1;
            uint64_t inside;
            float far;
            uint64_t passed = kj->draw(b.depth, b.face, STRIDE, x0, y0, box, e, n, &d, &inside,
                                       next() & 1 ? &far : NULL);
            if (inside != want || passed != want)
                fail_msg("round %d: %s covers %016llx and passes %016llx, the brute force covers "
                         "%016llx", round, j < 0 ? "plain C" : name[j],
                         (unsigned long long)inside, (unsigned long long)passed,
                         (unsigned long long)want);
        }
    }
}


/* A random plane in a random format and mapping, its pixels kept by keep. */
static BlockDepth random_depth(uint64_t keep)
{
    static const DepthFormat FORMATS[3] = {UNORM16, UNORM24, FLOAT32};
    static const float UNORM[3] = {65535.0f, 16777215.0f, 0.0f};
    int f = between(0, 2);
    return (BlockDepth){(float)(unit() * 1.2 - 0.1), (float)((unit() - 0.5) * 1e-3),
                        (float)((unit() - 0.5) * 1e-3), (float)((unit() - 0.5) * 1e-5),
                        .unorm = UNORM[f], .reversed = next() & 1, .face = between(0, 1000),
                        .keep = keep, .format = FORMATS[f]};
}

static float random_stored(const BlockDepth *d)
{
    float z = (float)unit();
    return d->unorm ? rintf(z * d->unorm) : z;
}

static void every_kernel_tests_depth_as_plain_c(void **state_)
{
    (void)state_;
    const BlockKernels *k[3];
    const char *name[3];
    int nk = others(k, name);
    for (int round = 0; round < ROUNDS; round++) {
        BlockDepth d = random_depth(next() & 1 ? ~(uint64_t)0 : 0xf0f0f0f00f0f0f0full);
        int x0 = 8 * between(0, 2000), y0 = 8 * between(0, 2000), n = between(0, 5);
        EdgeFn e[5];
        random_edges(e, n, x0, y0);
        uint64_t box = next() & next() ? next() & next() : 1;
        if (next() % 4 == 0)
            box = window_box();
        else if (next() & 1)
            box = ~(uint64_t)0, n = next() & 1 ? 0 : n; /* covered whole: the farthest back */
        Block start;
        for (int i = 0; i < 8 * STRIDE; i++)
            start.depth[i] = random_stored(&d), start.face[i] = between(-1, 1000);
        Block plain = start;
        bool asked = next() & 1; /* the farthest value: else NULL, as a window asks */
        float plain_far = NAN;
        uint64_t plain_inside;
        uint64_t want = PLAIN_KERNELS.draw(plain.depth, plain.face, STRIDE, x0, y0, box, e, n, &d,
                                           &plain_inside, asked ? &plain_far : NULL);
        float far = plain.depth[0]; /* the block's farthest value after the test */
        for (int i = 0; i < 64; i++) {
            float v = plain.depth[i / 8 * STRIDE + i % 8];
            far = d.reversed ? fminf(far, v) : fmaxf(far, v);
        }
        if (asked && plain_inside == ~(uint64_t)0 && plain_far != far)
            fail_msg("round %d: plain C says the farthest is %.9g, the buffer %.9g", round,
                     (double)plain_far, (double)far);
        for (int j = 0; j < nk; j++) {
            Block b = start;
            float b_far = NAN;
            uint64_t inside;
            uint64_t got = k[j]->draw(b.depth, b.face, STRIDE, x0, y0, box, e, n, &d, &inside,
                                      asked ? &b_far : NULL);
            if (got != want || inside != plain_inside)
                fail_msg("round %d: %s passed %016llx of %016llx, plain C %016llx of %016llx",
                         round, name[j], (unsigned long long)got, (unsigned long long)inside,
                         (unsigned long long)want, (unsigned long long)plain_inside);
            if (memcmp(&b, &plain, sizeof b) != 0)
                fail_msg("round %d: %s left other depths or faces than plain C", round, name[j]);
            if (asked && inside == ~(uint64_t)0 && b_far != far)
                fail_msg("round %d: %s says the farthest is %.9g, the buffer %.9g", round,
                         name[j], (double)b_far, (double)far);
        }
    }
}

#define WIDE_STRIDE 40 /* floats per row of a window 16 wide, and more */
typedef struct { float depth[16 * WIDE_STRIDE]; int32_t face[16 * WIDE_STRIDE]; } Window;

/* A window 16 wide drawn by wide, and by plain C as its 4 pieces of 8 x 8: the same
 * depths and faces, and the same counts. */
static void wide_window_as_plain_c(WideKernel *wide_kernel, const char *name, int round)
{
    BlockDepth d = random_depth(~(uint64_t)0); /* a window's: no cutout */
    int x0 = between(0, 16000), y0 = between(0, 16000), n = between(1, 5);
    EdgeFn e[5];
    for (int j = 0; j < n; j++) { /* values over the 16 x 16 pixels in 32 bits */
        int32_t size = between(1, 1 << between(0, 25));
        e[j].a = between(-size, size), e[j].b = between(-size, size);
        int32_t reach = 15 * (abs(e[j].a) + abs(e[j].b)), g = between(-reach, reach);
        e[j].c = g - (int64_t)e[j].a * x0 - (int64_t)e[j].b * y0;
    }
    int left = between(0, 15), right = between(left + 1, 16), rows = between(1, 16);
    uint32_t cols = ((uint32_t)1 << right) - ((uint32_t)1 << left);
    Window start, plain, wide;
    for (int i = 0; i < 16 * WIDE_STRIDE; i++)
        start.depth[i] = random_stored(&d), start.face[i] = between(-1, 1000);
    plain = start, wide = start;
    FragmentStats want = {0}, got = {0};
    for (int by = 0; by < 16; by += 8)
        for (int bx = 0; bx < 16; bx += 8) {
            uint64_t box = 0, inside;
            for (int j = by; j < by + 8 && j < rows; j++)
                box |= (uint64_t)(cols >> bx & 0xff) << (8 * (j - by));
            if (box == 0)
                continue;
            size_t i = (size_t)by * WIDE_STRIDE + (size_t)bx;
            uint64_t passed = PLAIN_KERNELS.draw(plain.depth + i, plain.face + i, WIDE_STRIDE,
                                                 x0 + bx, y0 + by, box, e, n, &d, &inside, NULL);
            want.tested += (uint64_t)__builtin_popcountll(inside);
            want.passed += (uint64_t)__builtin_popcountll(passed);
        }
    bool counted = next() & 1; /* else counts NULL, as when nothing is counted */
    wide_kernel(wide.depth, wide.face, WIDE_STRIDE, x0, y0, cols, rows, e, n, &d,
                counted ? &got : NULL);
    if (memcmp(&wide, &plain, sizeof wide) != 0)
        fail_msg("round %d: %s's wide window left other depths or faces than plain C", round,
                 name);
    if (counted && (got.tested != want.tested || got.passed != want.passed))
        fail_msg("round %d: %s's wide window counted %llu tested, %llu passed; plain C %llu, %llu",
                 round, name, (unsigned long long)got.tested, (unsigned long long)got.passed,
                 (unsigned long long)want.tested, (unsigned long long)want.passed);
}

static void every_wide_window_tests_as_plain_c_windows(void **state_)
{
    (void)state_;
    static const Simd SIMD[2] = {SIMD_AVX2, SIMD_AVX512};
    static const char *const NAME[2] = {"avx2", "avx512"};
    for (int j = 0; j < 2 && simd_best() >= SIMD[j]; j++) {
        if (!wide_of(SIMD[j]))
            fail_msg("%s has no kernel for windows 16 wide", NAME[j]);
        for (int round = 0; round < ROUNDS; round++)
            wide_window_as_plain_c(wide_of(SIMD[j]), NAME[j], round);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_kernel_covers_the_pixels_of_a_brute_force),
        cmocka_unit_test(every_kernel_tests_depth_as_plain_c),
        cmocka_unit_test(every_wide_window_tests_as_plain_c_windows),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
