/* limit.c: the fastest a rasterizer of this series could draw.
 *
 *     bench_limit [--reps N]
 *
 * The limit: the fill_back_to_front workload with every piece of coverage
 * work taken away. FILL_LAYERS layers, nearest last, each one a plain walk
 * over the rows of the same 1024x1024 Target, and at every pixel the depth
 * test every lesson must do: compare with the stored value, report the
 * fragment with target_record, write depth and face when it passes. No edge,
 * no interpolation, no setup: what remains is the memory traffic of one
 * fragment. Counting is off (target.h), as in the lessons' timed repetitions
 * (bench.c), so target_record returns at once. Every row of the benchmark's
 * table is compared with it.
 *
 * Then the same for the small workload: for each of its triangles, the same
 * depth tests on a staircase of pixels in the rows and columns of the
 * triangle's square (1 + 2 + ... + 10 = 55 pixels where the lessons cover
 * about 50), with no coverage work. It shows what small's scattered memory
 * accesses cost by themselves.
 *
 * And both once more with counting on, as a lesson program counts for its
 * summary: overdraw[], the totals and the --trace check at every fragment.
 * The difference is what the bookkeeping costs.
 *
 * Prints four CSV lines (measure.h), lesson "limit", workloads
 * "fill_back_to_front", "fill_counted", "small" and "small_counted". */
#include <math.h>
#include <stdio.h>

#include "measure.h"
#include "target.h"
#include "workloads.h"

#define LIMIT_SIDE 1024
/* Pixels of one staircase: 1 + 2 + ... + SMALL_LEG. */
#define SMALL_STAIR_PIXELS ((int)SMALL_LEG * ((int)SMALL_LEG + 1) / 2)
#define MAX_REPS 100

/* The z-buffer test of lessons 02 and 03, d < stored (lesson 04's 1/d > stored
 * costs the same), on pixels x0 .. x1 - 1 of row y, each fragment reported
 * with target_record as the lessons report it. */
static void depth_test_run(Target *t, int y, int x0, int x1, float d, int face)
{
    size_t i = (size_t)y * (size_t)t->width + (size_t)x0;
    for (int x = x0; x < x1; x++, i++) {
        float stored = t->depth[i];
        bool passed = d < stored;
        target_record(t, i, face, d, stored, passed);
        if (passed) {
            t->depth[i] = d;
            t->face[i] = face;
        }
    }
}

/* The layers of fill_back_to_front, farthest first: d from WORKLOAD_D_MAX
 * down to WORKLOAD_D_MIN, as workloads.c spaces them. */
static void fill_layers(Target *t)
{
    for (int j = 0; j < FILL_LAYERS; j++) {
        double step = (WORKLOAD_D_MAX - WORKLOAD_D_MIN) * j / (FILL_LAYERS - 1);
        float d = (float)(WORKLOAD_D_MAX - step);
        for (int y = 0; y < t->height; y++)
            depth_test_run(t, y, 0, t->width, d, 2 * j);
    }
}

/* small's triangles, each as a staircase in its square: row k of the square
 * gets k + 1 pixels, at the triangle's first corner's depth. */
static void small_staircases(Target *t, const Workload *w)
{
    int leg = (int)SMALL_LEG; /* staircase rows */
    for (int f = 0; f < w->nfaces; f++) {
        const ScreenVertex *v = w->faces[f].v;
        int x0 = (int)fmin(v[0].x, fmin(v[1].x, v[2].x));
        int y0 = (int)fmin(v[0].y, fmin(v[1].y, v[2].y));
        if (x0 + leg > t->width)
            x0 = t->width - leg;
        if (y0 + leg > t->height)
            y0 = t->height - leg;
        for (int k = 0; k < leg; k++)
            depth_test_run(t, y0 + k, x0, x0 + k + 1, (float)v[0].d, f);
    }
}

typedef void (*DrawFn)(Target *t, const Workload *w);

static void draw_fill(Target *t, const Workload *w)
{
    (void)w;
    fill_layers(t);
}

/* The limit's buffer holds d, cleared to +infinity as lessons 02 and 03 clear it. */
static void clear_to_infinity(Target *t, LessonState *s)
{
    (void)s;
    size_t n = (size_t)t->width * (size_t)t->height;
    for (size_t i = 0; i < n; i++) {
        t->depth[i] = INFINITY;
        t->face[i] = NO_FACE;
    }
}

static const Rasterizer CLEAR_TO_INFINITY = {.clear = clear_to_infinity};

/* Draws reps times after the warm-up into a fresh LIMIT_SIDE target, counting
 * or not. fragments: how many depth tests one drawing makes, worked out by
 * the caller (an uncounted drawing cannot tell); a counted one must agree. */
static bool measure(DrawFn draw, bool counting, const Workload *w, const char *workload,
                    long triangles, uint64_t fragments, int reps, Measurement *m, Error *err)
{
    Target t;
    if (!target_init(&t, LIMIT_SIDE, LIMIT_SIDE, err))
        return false;
    t.counting = counting;
    double times[MAX_REPS];
    for (int k = -BENCH_WARMUP; k < reps; k++) {
        target_reset(&t, &CLEAR_TO_INFINITY);
        double start = now_seconds();
        draw(&t, w);
        double elapsed = now_seconds() - start;
        if (k >= 0)
            times[k] = elapsed;
    }
    uint64_t counted = t.stats.tested;
    Measurement r = {"limit", workload, LIMIT_SIDE, LIMIT_SIDE, reps, triangles,
                     fragments, 0, 0, 0, depth_checksum(&t)};
    summarise_times(times, reps, &r.median_s, &r.min_s, &r.max_s);
    *m = r;
    target_free(&t);
    if (counted != (counting ? fragments : 0))
        return error_set(err, "limit %s: %llu fragments counted, %llu expected", workload,
                         (unsigned long long)counted, (unsigned long long)fragments);
    return true;
}

int main(int argc, char **argv)
{
    const char *program = argc > 0 ? argv[0] : "bench_limit";
    int reps;
    int usage = bench_parse_reps(argc, argv, program, &reps);
    if (usage != 0)
        return usage;

    Workload small;
    Measurement m[4];
    Error err;
    bool ok = workload_build(&small, WORKLOAD_SMALL, &err);
    if (ok) {
        uint64_t fill_fragments = (uint64_t)FILL_LAYERS * LIMIT_SIDE * LIMIT_SIDE;
        uint64_t stair_fragments = (uint64_t)small.nfaces * SMALL_STAIR_PIXELS;
        ok = measure(draw_fill, false, NULL, workload_name(WORKLOAD_FILL_BACK_TO_FRONT), 0,
                     fill_fragments, reps, &m[0], &err) &&
             measure(draw_fill, true, NULL, "fill_counted", 0, fill_fragments, reps, &m[1],
                     &err) &&
             measure(small_staircases, false, &small, small.name, small.ntris, stair_fragments,
                     reps, &m[2], &err) &&
             measure(small_staircases, true, &small, "small_counted", small.ntris,
                     stair_fragments, reps, &m[3], &err);
        workload_free(&small);
    }
    if (!ok) {
        fprintf(stderr, "%s: error: %s\n", program, err.msg);
        return 1;
    }
    for (int k = 0; k < 4; k++)
        measure_print(stdout, &m[k]);
    return 0;
}
