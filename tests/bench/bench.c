/* bench.c: times one lesson's rasterizer on the workloads of workloads.h.
 *
 *     bench_<lesson> [--reps N] [WORKLOAD ...]
 *
 * Built once per lesson (make bench): the lessons define the same function
 * names, so each binary links one lesson, and BENCH_RASTERIZER names its
 * Rasterizer (rasterizer.h), e.g. -DBENCH_RASTERIZER=ZBUFFER. It times
 * frames of each workload (all of them when none is named) as a GPU's frame
 * is timed, glClear, the draw and glFinish: the lesson's clear, then
 * workload_draw (every corner from clip space to the screen, every face into
 * draw_face), then whatever the lesson still holds back drawn; no file I/O.
 * It prints one CSV line per workload (measure.h); tests/bench/run-bench.sh
 * makes the table. For run-bench.sh's cores side by side, BENCH_CONFIG=k
 * in the environment times only configuration k of a lesson timed in more
 * than one (bench_setup.h), and BENCH_WALL_CLOCK=1 times every row by the
 * wall clock. Lessons 06
 * on draw into a unorm24 buffer, standard mapping, with the workload's near
 * and far, as GL's default framebuffer has it. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "measure.h"
#include "rasterizer.h"
#include "workloads.h"

/* Lessons 06 on keep their depth buffer's format in their state (state.h):
 * here unorm24 with the standard mapping, the buffer of lessons 08 and 09 and
 * of llvmpipe's rows. Lessons 08 and 09 draw depth only (lesson 08's
 * fragment step without its shader: the rasterizer is timed, not the
 * shader, which bench_early_z times). Lesson 09 on add a tile buffer, 8 x 8. */
#if BENCH_LESSON_NUMBER >= 6
#include "depth_format.h"
#include "state.h"
#endif
#if BENCH_LESSON_NUMBER >= 9
#include "hierarchical_z.h"
#endif
/* Lesson 10 is timed in more than one set-up (its threads): bench_setup.h. */
#ifdef BENCH_SETUP
#include "bench_setup.h"
#endif

#ifndef BENCH_RASTERIZER
#error "compile with -DBENCH_RASTERIZER=<the lesson's Rasterizer>"
#endif
#ifndef BENCH_LESSON
#error "compile with -DBENCH_LESSON='\"<the lesson's directory>\"'"
#endif
extern const Rasterizer BENCH_RASTERIZER;

/* Draws w reps times after the warm-up; false when two repetitions did not
 * leave the same buffer (a rasterizer must not depend on anything but input).
 * The warm-up counts (Target.counting): the fragments tested come from it.
 * The timed repetitions count nothing, as a renderer that is asked for no
 * counts would draw (docs/performance.md, "What counting costs"). */
static bool measure_workload(const Rasterizer *lesson_rz, Workload *w, int reps,
                             int config, Measurement *m, Error *err)
{
    Target t;
    static char name[64] = BENCH_LESSON;
    bool wall_clock = false;
    Rasterizer with_state = *lesson_rz;
    const Rasterizer *rz = &with_state;
    if (!target_init(&t, w->width, w->height, err))
        return false;
#ifdef BENCH_SETUP
    LessonState *state = bench_configure(&t, config, name, (int)sizeof name, &wall_clock);
    if (!state) {
        target_free(&t);
        return error_set(err, "out of memory for the set-up of %s", BENCH_LESSON);
    }
    with_state.state = state;
#elif BENCH_LESSON_NUMBER >= 6
    (void)config;
    LessonState state = {.depth = depth_setup(UNORM24, STANDARD, w->ctx.near, w->ctx.far)};
#if BENCH_LESSON_NUMBER >= 8
    state.early_z.pass = 1; /* depth only */
#endif
    with_state.state = &state;
#else
    (void)config;
#endif
    const char *wall = getenv("BENCH_WALL_CLOCK");
    wall_clock = wall_clock || (wall && strcmp(wall, "1") == 0);
#if BENCH_LESSON_NUMBER >= 9
    HierarchicalZ hiz = {0};
    if (!hiz_begin(&hiz, &t, 8, err)) {
        target_free(&t);
        return false;
    }
    with_state.state->hiz = &hiz;
#endif
    double times[MAX_REPS];
    bool same = true;
    for (int k = -BENCH_WARMUP; k < reps; k++) {
        target_reset(&t, rz);
        t.counting = k < 0;
        double start = wall_clock ? now_wall_seconds() : now_seconds();
        rz->clear(&t, rz->state); /* timed, as glClear is */
        workload_draw(w, &t, rz);
#ifdef BENCH_FINISH
        BENCH_FINISH(&t, rz->state, NULL); /* a rasterizer that holds faces back draws them now */
#endif
        double elapsed = (wall_clock ? now_wall_seconds() : now_seconds()) - start;
        uint64_t sum = depth_checksum(&t);
        if (k < 0) {
            m->checksum = sum;
            m->fragments = t.stats.tested;
            continue;
        }
        times[k] = elapsed;
        same = same && sum == m->checksum && t.stats.tested == 0;
    }
    target_free(&t);
#if BENCH_LESSON_NUMBER >= 9
    hiz_free(&hiz);
#endif
    if (!same)
        return error_set(err, "%s: repetitions of '%s' left different depth buffers",
                         BENCH_LESSON, w->name);
    m->lesson = name;
    m->workload = w->name;
    m->width = w->width;
    m->height = w->height;
    m->reps = reps;
    m->triangles = w->ntris;
    summarise_times(times, reps, &m->median_s, &m->min_s, &m->max_s);
    return true;
}

int main(int argc, char **argv)
{
    const char *program = argc > 0 ? argv[0] : "bench";
    int reps;
    bool chosen[WORKLOAD_COUNT], any;
    int usage = bench_parse_args(argc, argv, program, &reps, chosen, &any);
    if (usage != 0)
        return usage;

#ifdef BENCH_SETUP
    int configs = bench_configs(); /* rows per workload */
#else
    int configs = 1;
#endif
    int first = 0; /* BENCH_CONFIG=k: configuration k alone */
    const char *only = getenv("BENCH_CONFIG");
    if (only) {
        char *end;
        long k = strtol(only, &end, 10);
        if (*only == '\0' || *end != '\0' || k < 0 || k >= configs) {
            fprintf(stderr, "%s: error: BENCH_CONFIG: '%s' is not 0 to %d\n", program, only,
                    configs - 1);
            return 2;
        }
        first = (int)k, configs = first + 1;
    }
    for (int k = 0; k < WORKLOAD_COUNT; k++) {
        if (any && !chosen[k])
            continue;
        Workload w;
        Measurement m;
        Error err;
        bool built = workload_build(&w, (WorkloadKind)k, &err), ok = built;
        for (int c = first; ok && c < configs; c++) {
            ok = measure_workload(&BENCH_RASTERIZER, &w, reps, c, &m, &err);
            if (ok)
                measure_print(stdout, &m);
            fflush(stdout);
        }
        if (built)
            workload_free(&w);
        if (!ok) {
            fprintf(stderr, "%s: error: %s\n", program, err.msg);
            return 1;
        }
    }
    return 0;
}
