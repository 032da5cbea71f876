/* bench.c: times one lesson's rasterizer on the workloads of workloads.h.
 *
 *     bench_<lesson> [--reps N] [WORKLOAD ...]
 *
 * Built once per lesson (make bench): the lessons define the same function
 * names, so each binary links one lesson, and BENCH_RASTERIZER names its
 * Rasterizer (render.h), e.g. -DBENCH_RASTERIZER=ZBUFFER. It draws each
 * workload (all of them when none is named) straight through draw_face, with
 * no camera and no file I/O in the timed part, and prints one CSV line per
 * workload (measure.h); tests/bench/run-bench.sh makes the table. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "measure.h"
#include "render.h"
#include "workloads.h"

#ifndef BENCH_RASTERIZER
#error "compile with -DBENCH_RASTERIZER=<the lesson's Rasterizer>"
#endif
#ifndef BENCH_LESSON
#error "compile with -DBENCH_LESSON='\"<the lesson's directory>\"'"
#endif
extern const Rasterizer BENCH_RASTERIZER;

#define MAX_REPS 100

static int usage_error(const char *program, const char *what)
{
    fprintf(stderr, "%s: error: %s (usage: %s [--reps 1..%d] [WORKLOAD ...])\n", program, what,
            program, MAX_REPS);
    return 2;
}

/* Draws w reps times after the warm-up; false when two repetitions did not
 * leave the same buffer (a rasterizer must not depend on anything but input). */
static bool measure_workload(const Rasterizer *rz, const Workload *w, int reps,
                             Measurement *m, Error *err)
{
    Target t;
    if (!render_target_init(&t, rz, w->width, w->height, err))
        return false;
    double times[MAX_REPS];
    bool same = true;
    for (int k = -BENCH_WARMUP; k < reps; k++) {
        target_reset(&t, rz->clear);
        double start = now_seconds();
        workload_draw(w, &t, rz);
        double elapsed = now_seconds() - start;
        uint64_t sum = depth_checksum(&t);
        if (k < 0) {
            m->checksum = sum;
            m->fragments = t.stats.tested;
            continue;
        }
        times[k] = elapsed;
        same = same && sum == m->checksum && t.stats.tested == m->fragments;
    }
    target_free(&t);
    if (!same)
        return error_set(err, "%s: repetitions of '%s' left different depth buffers",
                         BENCH_LESSON, w->name);
    m->lesson = BENCH_LESSON;
    m->workload = w->name;
    m->width = w->width;
    m->height = w->height;
    m->reps = reps;
    m->triangles = w->ntris;
    summarise_times(times, reps, &m->median_s, &m->min_s, &m->max_s);
    return true;
}

static bool find_workload(const char *name, WorkloadKind *kind)
{
    for (int k = 0; k < WORKLOAD_COUNT; k++)
        if (strcmp(name, workload_name((WorkloadKind)k)) == 0) {
            *kind = (WorkloadKind)k;
            return true;
        }
    return false;
}

int main(int argc, char **argv)
{
    const char *program = argc > 0 ? argv[0] : "bench";
    int reps = BENCH_REPS;
    bool chosen[WORKLOAD_COUNT] = {false};
    bool any = false;
    for (int i = 1; i < argc; i++) {
        WorkloadKind kind;
        if (strcmp(argv[i], "--reps") == 0) {
            char *end;
            long n = i + 1 < argc ? strtol(argv[i + 1], &end, 10) : 0;
            if (i + 1 >= argc || *end != '\0' || n < 1 || n > MAX_REPS)
                return usage_error(program, "--reps needs a number from 1 to 100");
            reps = (int)n;
            i++;
        } else if (find_workload(argv[i], &kind)) {
            chosen[kind] = any = true;
        } else {
            char what[128];
            snprintf(what, sizeof what, "unknown workload '%s'", argv[i]);
            return usage_error(program, what);
        }
    }

    for (int k = 0; k < WORKLOAD_COUNT; k++) {
        if (any && !chosen[k])
            continue;
        Workload w;
        Measurement m;
        Error err;
        bool ok = workload_build(&w, (WorkloadKind)k, &err);
        if (ok) {
            ok = measure_workload(&BENCH_RASTERIZER, &w, reps, &m, &err);
            workload_free(&w);
        }
        if (!ok) {
            fprintf(stderr, "%s: error: %s\n", program, err.msg);
            return 1;
        }
        measure_print(stdout, &m);
        fflush(stdout);
    }
    return 0;
}
