/* extras.c: lesson 10's flags (see extras.h). The depth flags are lesson
 * 07's, with the same words. */
#include "extras.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bias_flags.h"
#include "depth_flags.h"
#include "engine.h"
#include "harness/cli.h"

enum { FLAG_SIMD, FLAG_THREADS, FLAG_FORMAT, FLAG_MAPPING, FLAG_OFFSET, FLAG_CLAMP, FLAG_COUNT };

#define MAX_THREADS 256
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
#define BUILD_THREADS 1 /* the browser's build (make wasm) has no threads */
#else
#define BUILD_THREADS MAX_THREADS
#endif

static const LessonFlag FLAGS[FLAG_COUNT] = {
    [FLAG_SIMD] = {"--simd", "S", "none (plain C), sse2, avx2 or avx512: how many pixels of a "
                                  "block at once (default: the widest this machine has); "
                                  "pixels: no blocks, each pixel of a polygon's box in plain C"},
    [FLAG_THREADS] = {"--threads", "N", "threads drawing tiles, 1 to 256 (default: the "
                                        "machine's cores); the picture is the same for any N"},
    [FLAG_FORMAT] = {"--depth-format", "F", "what the depth buffer stores: unorm16, unorm24 "
                                            "(the default) or float32"},
    [FLAG_MAPPING] = {"--depth-mapping", "M", "standard (the default: 0 at near, 1 at far) or "
                                              "reversed (1 at near, 0 at far; takes --far inf)"},
    [FLAG_OFFSET] = {"--polygon-offset", "FACTOR,UNITS",
                     "depth bias of the faces in group or object `decal`: o = m * FACTOR + "
                     "r * UNITS added to z_w (default 0,0)"},
    [FLAG_CLAMP] = {"--offset-clamp", "C", "limit o to C as Direct3D and Vulkan do (0, the "
                                           "default: no limit)"},
};

static const char *const SIMD_NAMES[] = {[SIMD_PIXELS] = "pixels", [SIMD_NONE] = "none",
                                         [SIMD_SSE2] = "sse2", [SIMD_AVX2] = "avx2",
                                         [SIMD_AVX512] = "avx512"};
static const char *simd_name(Simd simd)
{
    return SIMD_NAMES[simd];
}

void print_engine(const Target *t, const LessonState *s)
{
    const FastRaster *fr = &s->fast;
    (void)t;
    printf("  drawn in tiles of %d x %d pixels, ", TILE_SIZE, TILE_SIZE);
    if (fr->simd == SIMD_PIXELS)
        printf("pixel by pixel (no blocks)");
    else
        printf("blocks of %d x %d, SIMD %s", BLOCK_SIZE, BLOCK_SIZE, simd_name(fr->simd));
    printf(", %d thread%s%s\n", fr->threads, fr->threads == 1 ? "" : "s",
           fr->count ? " (counting: plain C, one thread)" : "");
    if (s->hiz && !fr->count)
        printf("  hierarchical Z, %dx%d tiles (one per block): tiles tested %llu, skipped %llu\n",
               s->hiz->tile, s->hiz->tile, s->hiz->tiles_tested, s->hiz->tiles_skipped);
}

static int find_name(const char *name, const char *const *names, int n)
{
    for (int i = 0; i < n; i++)
        if (strcmp(name, names[i]) == 0)
            return i;
    return -1;
}

static int cores(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n < 1 ? 1 : n > BUILD_THREADS ? BUILD_THREADS : (int)n;
}

LessonState fast_chosen(const Run *run)
{
    const char *const *x = run->opt.extra;
    Error ignored; /* choose() has checked every flag */
    long threads = cores();
    if (x[FLAG_THREADS])
        parse_int("--threads", x[FLAG_THREADS], 1, MAX_THREADS, &threads, &ignored);
    Simd simd = x[FLAG_SIMD] ? (Simd)find_name(x[FLAG_SIMD], SIMD_NAMES, 5) : simd_best();
    LessonState state = fast_raster(depth_flags_setup(run, x[FLAG_FORMAT], x[FLAG_MAPPING]), simd,
                                    (int)threads, run->opt.overdraw_out || run->opt.trace_set);
    state.bias = bias_flags_chosen(x[FLAG_OFFSET], x[FLAG_CLAMP], &run->render.mesh);
    return state;
}

static bool choose(Run *run, Error *err)
{
    const char *const *x = run->opt.extra;
    long threads;
    if (run->opt.steps_dir)
        return error_set(err, "--steps does not apply to 10_fast_raster (faces are drawn "
                              "later, tile by tile: there is no picture after each face)");
    int simd = x[FLAG_SIMD] ? find_name(x[FLAG_SIMD], SIMD_NAMES, 5) : SIMD_NONE;
    if (simd < 0)
        return error_set(err, "--simd: '%s' is not one of none, sse2, avx2, avx512, pixels",
                         x[FLAG_SIMD]);
    if (simd > (int)simd_best())
        return error_set(err, "--simd %s: this machine (or build) has only %s", x[FLAG_SIMD],
                         SIMD_NAMES[simd_best()]);
    if (x[FLAG_THREADS] && !parse_int("--threads", x[FLAG_THREADS], 1, MAX_THREADS, &threads, err))
        return false;
    if (x[FLAG_THREADS] && threads > BUILD_THREADS)
        return error_set(err, "--threads %ld: this build runs on one thread (the browser's has "
                              "no threads)", threads);
    return depth_flags_ok(run, x[FLAG_FORMAT], x[FLAG_MAPPING], false, err) &&
           bias_flags_ok(x[FLAG_OFFSET], x[FLAG_CLAMP], err);
}

const Extras EXTRAS = {.flags = FLAGS, .n_flags = FLAG_COUNT, .choose = choose};
