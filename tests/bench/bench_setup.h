/* bench_setup.h: for a lesson whose rasterizer needs more than a target to
 * draw (lesson 10: its depth buffer's format and its threads), the benchmark
 * (bench.c, built with -DBENCH_SETUP) draws each workload once per
 * configuration of the lesson's bench_setup file, in a row of its own. */
#ifndef BENCH_SETUP_H
#define BENCH_SETUP_H

#include <stdbool.h>

#include "rasterizer.h"

/* How many configurations the lesson is timed in. */
int bench_configs(void);

/* The lesson's state for configuration k, drawing into t; puts the row's
 * name in name (e.g. "10_fast_raster_1t") and whether its time is the wall
 * clock (threads working together) rather than this thread's CPU time.
 * NULL: out of memory. */
LessonState *bench_configure(Target *t, int k, char *name, int size, bool *wall_clock);

#endif
