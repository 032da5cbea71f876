/* test_coverage.c: lesson 06 covers pixels by the series' fill rule, like
 * lessons 02 to 05 (tests/shared/coverage_suite.inc): its buffer changes what
 * is stored, not which pixels a face covers. Run with a float32 buffer,
 * reversed, far at 1000: the suite's faces lie between d = 0.1 and 1000. */
#include "depth_format.h"
#include "state.h"

static LessonState suite_state;

#define SUITE_RASTERIZER DEPTH_PRECISION_ZBUFFER
#define SUITE_STATE (&suite_state)
#include "../shared/coverage_suite.inc"

int main(void)
{
    suite_state.depth = depth_setup(FLOAT32, REVERSED, SUITE_NEAR, SUITE_FAR);
    return run_coverage_suite("06_depth_precision");
}
