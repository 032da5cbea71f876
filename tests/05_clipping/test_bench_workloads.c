/* test_bench_workloads.c: `make bench` times lesson 05's real rasterizer: every
 * workload of tests/bench/ makes the calls of draw_face render_faces makes. See
 * tests/shared/bench_workloads_suite.inc. */
#include "clipping.h"

#define SUITE_RASTERIZER CLIPPING_ZBUFFER
#include "../shared/bench_workloads_suite.inc"

int main(void)
{
    return run_bench_workloads_suite("05_clipping bench workloads");
}
