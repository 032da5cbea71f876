/* test_bench_workloads.c: `make bench` times lesson 02's real rasterizer: every
 * workload of tests/bench/ makes the calls of draw_face render_faces makes. See
 * tests/shared/bench_workloads_suite.inc. */
#include "raster.h"

#define SUITE_RASTERIZER ZBUFFER
#include "../shared/bench_workloads_suite.inc"

int main(void)
{
    return run_bench_workloads_suite("02_zbuffer bench workloads");
}
