/* measure.h: timing a piece of drawing several times, and one line of results.
 *
 * A run is BENCH_WARMUP untimed repetitions (caches, page faults, CPU clock
 * settling), then BENCH_REPS timed ones. Before each repetition the counts
 * are reset, untimed; a repetition is a frame, clear included (bench.c).
 * The result is the median time and the spread (fastest and slowest
 * repetition).
 *
 * The warm-up draws with counting on (Target.counting, target.h): the
 * fragments tested come from it. The timed repetitions draw with counting
 * off, as a lesson asked for no count would: no overdraw[], no totals, no
 * --trace check (docs/performance.md, "What counting costs").
 *
 * Each bench binary prints one CSV line per workload (measure_print), the
 * columns of MEASURE_CSV_HEADER; tests/bench/run-bench.sh turns the lines of
 * every binary into the table. */
#ifndef MEASURE_H
#define MEASURE_H

#include <stdint.h>
#include <stdio.h>

#include "rasterizer.h"
#include "workloads.h"

#define BENCH_WARMUP 1
#define BENCH_REPS 11

#define MEASURE_CSV_HEADER \
    "lesson,workload,width,height,reps,triangles,fragments,median_s,min_s,max_s,checksum"

typedef struct {
    const char *lesson, *workload;
    int width, height;
    int reps;
    long triangles;       /* drawn per repetition */
    uint64_t fragments;   /* tested per repetition (Target.stats.tested of the warm-up) */
    double median_s, min_s, max_s;
    uint64_t checksum;    /* of the depth buffer after one repetition */
} Measurement;

/* Seconds of CPU time this thread has used. Not the wall clock: on a busy
 * machine the time other programs get would count as ours. */
double now_seconds(void);
/* Seconds of the wall clock: for threads working together (lesson 10's
 * rows with more than one), whose CPU times add up. */
double now_wall_seconds(void);

/* Back to the state target_init leaves: depth = clear, no face, no counts
 * (a frame clears again, timed: this one makes the counts start at zero). */
void target_reset(Target *t, const Rasterizer *rz);

/* Median, minimum and maximum of times[0 .. n-1] (n >= 1; sorts times). */
void summarise_times(double *times, int n, double *median, double *min, double *max);

void measure_print(FILE *out, const Measurement *m);

#define MAX_REPS 100 /* --reps N: 1 to MAX_REPS */

/* A bench binary's command line, [--reps N] [WORKLOAD ...]: reps (BENCH_REPS
 * when not given) and which workloads to run (chosen[k]; all when *any is
 * false). Returns 0, or 2 after one error line on stderr. */
int bench_parse_args(int argc, char **argv, const char *program, int *reps,
                     bool chosen[WORKLOAD_COUNT], bool *any);
/* A command line of [--reps N] alone (bench_limit, bench_round_trip): the same,
 * without workloads. */
int bench_parse_reps(int argc, char **argv, const char *program, int *reps);

#endif
