/* fuzz_raster.h: the harness every 3-D lesson's rasterizer fuzz target shares.
 * A target includes its lesson's header and calls fuzz_rasterizer with the
 * lesson's Rasterizer:
 *
 *     #include "raster.h"
 *     #include "fuzz_raster.h"
 *     int LLVMFuzzerTestOneInput(const uint8_t *d, size_t n)
 *     { return fuzz_rasterizer(&ZBUFFER, d, n); }
 *
 * The bytes become a screen of random size and a few faces (3 to 8 corners,
 * fan triangles, either convex flag) whose corners are anything a double can
 * be: ordinary pixels, values around the guard band and the fixed-point
 * limits, 1e30, the largest double, infinities, NaN, raw bit patterns. Each
 * face goes straight to the lesson's draw_face, as if the pipeline had let it
 * through. Whatever the faces, the rasterizer must:
 *   - not crash, hang, or do anything the sanitizers call undefined;
 *   - draw nothing for a face with a corner that is not finite;
 *   - test at most (corners - 2) x 5 x width x height fragments per face: its
 *     cost is bounded by the screen, never by the coordinates. (A triangle cut
 *     at the guard band has up to 7 corners, drawn as up to 5 triangles. Cut
 *     exactly, those never overlap; but where both ends of an edge lie beyond
 *     2^53 pixels, a double cannot place the cut to a pixel, the cut polygon
 *     may fold, and its triangles may then cover a pixel more than once.);
 *   - keep its books: tested = passed + failed = the sum of the overdraw
 *     counts; a pixel holds a face that was drawn exactly when its depth is
 *     no longer the clear value. */
#ifndef FUZZ_RASTER_H
#define FUZZ_RASTER_H

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "guard_band.h"
#include "harness/render.h"
#include "target.h"

#define FUZZ_MAX_FACES 6
#define FUZZ_MAX_CORNERS 8
#define FUZZ_SMALL_SIDE 128  /* most screens are at most this wide and high */
#define FUZZ_STRIP_SIDE 4096 /* some are long strips: up to this by 1 to 4 */

/* A byte reader that gives zeros once the input is used up. */
typedef struct {
    const uint8_t *p;
    size_t n;
} FuzzBytes;

static inline uint8_t fuzz_u8(FuzzBytes *b)
{
    if (b->n == 0)
        return 0;
    b->n--;
    return *b->p++;
}

static inline uint16_t fuzz_u16(FuzzBytes *b)
{
    uint16_t hi = fuzz_u8(b);
    return (uint16_t)(hi << 8 | fuzz_u8(b));
}

/* Values that have broken rasterizers: the guard band's edges, the limits of
 * fixed point (2^21 pixels is 2^29 sub-pixel units, 2^31 overflows an int),
 * the limit of exact integers in a double, and beyond. */
static const double SPECIAL[] = {
    0.0, -0.0, 0.5, 1.0, -1.0, 127.5, 128.0, 1048576.0, -1048576.0, 1048577.0,
    2097152.0, -2097152.0, 2147483648.0, -2147483649.0, 9007199254740992.0,
    1e30, -1e30, 1e300, -1e300, DBL_MAX, -DBL_MAX, DBL_MIN, 4.9e-324, INFINITY, -INFINITY,
    NAN, 1e-30, 16384.0, 16385.0, 0.00390625, 0.001953125,
};
#define SPECIAL_COUNT ((int)(sizeof SPECIAL / sizeof SPECIAL[0]))

static inline double fuzz_double(FuzzBytes *b)
{
    uint8_t tag = fuzz_u8(b);
    switch (tag % 4) {
    case 0: /* on or near a small screen, in 1/64 pixel */
        return (int16_t)fuzz_u16(b) / 64.0;
    case 1:
        return SPECIAL[fuzz_u8(b) % SPECIAL_COUNT];
    case 2: { /* any bit pattern */
        uint64_t bits = 0;
        for (int k = 0; k < 8; k++)
            bits = bits << 8 | fuzz_u8(b);
        double x;
        memcpy(&x, &bits, sizeof x);
        return x;
    }
    default: /* a small number times a power of two, up to 2^70 */
        return (int16_t)fuzz_u16(b) * ldexp(1.0, fuzz_u8(b) % 80 - 10);
    }
}

static inline void fuzz_check(bool ok, const char *what)
{
    if (!ok) {
        fprintf(stderr, "fuzz_raster: broken invariant: %s\n", what);
        abort();
    }
}

static inline bool fuzz_corners_finite(const ScreenVertex *v, int n)
{
    for (int k = 0; k < n; k++)
        if (!isfinite(v[k].x) || !isfinite(v[k].y) || !isfinite(v[k].d))
            return false;
    return true;
}

static inline void fuzz_check_books(const Target *t, const Rasterizer *rz, int nfaces)
{
    size_t n = (size_t)t->width * (size_t)t->height;
    uint64_t overdraw = 0;
    Target one; /* what rz->clear puts in a pixel */
    Error err;
    fuzz_check(render_target_init(&one, rz, 1, 1, &err), "a 1 x 1 target");
    float cleared_value = one.depth[0];
    target_free(&one);
    for (size_t i = 0; i < n; i++) {
        overdraw += t->overdraw[i];
        fuzz_check(t->face[i] == NO_FACE || (t->face[i] >= 0 && t->face[i] < nfaces),
                   "a pixel holds a face that was drawn");
        bool cleared = t->depth[i] == cleared_value ||
                       (isnan(t->depth[i]) && isnan(cleared_value));
        fuzz_check((t->face[i] == NO_FACE) == cleared,
                   "a pixel has a face exactly when its depth changed");
    }
    fuzz_check(t->stats.tested == t->stats.passed + t->stats.failed,
               "tested = passed + failed");
    fuzz_check(overdraw == t->stats.tested, "overdraw counts add up to the fragments tested");
}

static inline int fuzz_rasterizer(const Rasterizer *rz, const uint8_t *data, size_t size)
{
    FuzzBytes b = {data, size};
    uint8_t shape = fuzz_u8(&b);
    int width, height;
    if (shape & 1) { /* a long strip, one way or the other */
        width = 1 + fuzz_u16(&b) % FUZZ_STRIP_SIDE;
        height = 1 + fuzz_u8(&b) % 4;
        if (shape & 2) {
            int swap = width;
            width = height;
            height = swap;
        }
    } else {
        width = 1 + fuzz_u8(&b) % FUZZ_SMALL_SIDE;
        height = 1 + fuzz_u8(&b) % FUZZ_SMALL_SIDE;
    }
    double far = fuzz_double(&b);
    if (!(far > 0))
        far = INFINITY; /* most faces should get past the far plane */
    DrawContext ctx = {0.0, far, width, height};

    Target t;
    Error err;
    fuzz_check(render_target_init(&t, rz, width, height, &err), "target_init");
    int nfaces = 1 + fuzz_u8(&b) % FUZZ_MAX_FACES;
    for (int face = 0; face < nfaces; face++) {
        uint8_t head = fuzz_u8(&b);
        int n = 3 + head % (FUZZ_MAX_CORNERS - 2);
        ScreenVertex v[FUZZ_MAX_CORNERS];
        Tri tris[FUZZ_MAX_CORNERS - 2];
        for (int k = 0; k < n; k++) {
            v[k].x = fuzz_double(&b);
            v[k].y = fuzz_double(&b);
            v[k].d = fuzz_double(&b);
        }
        for (int k = 0; k < n - 2; k++)
            tris[k] = (Tri){{0, k + 1, k + 2}};
        ScreenFace f = {face, n, v, tris, (head & 0x80) != 0, NULL};

        uint64_t before = t.stats.tested;
        rz->draw_face(&t, rz->state, &f, &ctx);
        uint64_t tested = t.stats.tested - before;
        if (!fuzz_corners_finite(v, n))
            fuzz_check(tested == 0, "a face with a corner that is not finite draws nothing");
        uint64_t most = (uint64_t)(n - 2) * (GUARD_BAND_MAX_OUT(3) - 2) * (uint64_t)width *
                        (uint64_t)height;
        fuzz_check(tested <= most,
                   "cost bounded by the screen: at most (n - 2) x 5 x W x H fragments per face");
    }
    fuzz_check_books(&t, rz, nfaces);
    target_free(&t);
    return 0;
}

#endif
