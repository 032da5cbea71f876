/* fast_raster_setup.c: lesson 10 in the benchmark (bench_setup.h): its
 * engine with unorm24, standard (as llvmpipe's rows use), the widest SIMD the
 * machine has, once with one thread and once with one per core. To time
 * another kernel: FAST_RASTER_SIMD=none (or sse2, avx2, or pixels) in the environment;
 * every face set up by the calling thread, none by the others: FAST_RASTER_SET_UP=one. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bench_setup.h"
#include "engine.h" /* the lesson's extras/: simd_best */
#include "fast_raster.h"
#include "state.h"
#include "workloads.h"

static LessonState engine;

static int cores(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n < 1 ? 1 : (int)n;
}

int bench_configs(void)
{
    return 2;
}

LessonState *bench_configure(Target *t, int k, char *name, int size, bool *wall_clock)
{
    int threads = k == 0 ? 1 : cores();
    (void)t;
    fast_raster_free(&engine.fast);
    const char *chosen = getenv("FAST_RASTER_SIMD");
    Simd simd = simd_best();
    if (chosen && strcmp(chosen, "none") == 0)
        simd = SIMD_NONE;
    else if (chosen && strcmp(chosen, "sse2") == 0 && simd >= SIMD_SSE2)
        simd = SIMD_SSE2;
    else if (chosen && strcmp(chosen, "avx2") == 0 && simd >= SIMD_AVX2)
        simd = SIMD_AVX2;
    else if (chosen && strcmp(chosen, "pixels") == 0)
        simd = SIMD_PIXELS;
    engine = fast_raster(depth_setup(UNORM24, STANDARD, WORKLOAD_NEAR, WORKLOAD_FAR), simd,
                         threads, false);
    const char *set_up = getenv("FAST_RASTER_SET_UP");
    engine.fast.hold = !(set_up && strcmp(set_up, "one") == 0); /* one: by this thread alone */
    snprintf(name, (size_t)size, "10_fast_raster_%dt", threads);
    *wall_clock = threads > 1;
    return &engine;
}
