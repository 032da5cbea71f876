/* test_coverage.c: lesson 07 covers pixels by the series' fill rule, like
 * lessons 02 to 06 (tests/shared/coverage_suite.inc): the bias moves what a
 * decal stores, not which pixels a face covers. Run with lesson 06's float32
 * buffer, reversed, far at 1000, and no face offset (the suite's faces are in
 * no group). */
#include "depth_format.h"
#include "state.h"

static LessonState suite_state;

#define SUITE_RASTERIZER DEPTH_PRECISION_ZBUFFER
#define SUITE_STATE (&suite_state)
#include "../shared/coverage_suite.inc"

int main(void)
{
    suite_state.depth = depth_setup(FLOAT32, REVERSED, SUITE_NEAR, SUITE_FAR);
    return run_coverage_suite("07_depth_bias");
}
