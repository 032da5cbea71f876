/* test_coverage.c: lesson 03 covers pixels by the series' fill rule
 * (watertight meshes, the top-left rule, order independence, degenerate
 * input), exactly as lesson 02 does: the lesson changes how depth is
 * interpolated, never which pixels a triangle covers. The tests are shared
 * with lessons 02 and 04: see tests/shared/coverage_suite.inc. */
#include "raster.h"

#define SUITE_RASTERIZER ZBUFFER
#include "../shared/coverage_suite.inc"

int main(void)
{
    return run_coverage_suite("03_perspective_z coverage");
}
