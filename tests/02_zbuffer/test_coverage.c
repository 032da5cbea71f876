/* test_coverage.c: lesson 02 covers pixels by the series' fill rule
 * (watertight meshes, the top-left rule, order independence, degenerate
 * input). The tests are shared with lessons 03 and 04: see
 * tests/shared/coverage_suite.inc. */
#include "raster.h"

#define SUITE_RASTERIZER ZBUFFER
#include "../shared/coverage_suite.inc"

int main(void)
{
    return run_coverage_suite("02_zbuffer coverage");
}
