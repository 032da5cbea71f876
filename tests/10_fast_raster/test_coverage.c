/* test_coverage.c: lesson 10 covers pixels by the series' fill rule, like
 * lessons 02 to 08 (tests/shared/coverage_suite.inc): its edge functions,
 * tiles and blocks give lesson 04's coverage. Run with overdraw counting on
 * (Target.overdraw: the suite's measure of coverage), which draws in plain C
 * on one thread; test_kernels.c shows the SIMD kernels give the same bits,
 * test_program.c the same pictures. Lesson 06's float32 buffer, reversed. */
#include "fast_raster.h"
#include "state.h"

static LessonState engine; /* no tile buffer */

#define SUITE_RASTERIZER FAST_ZBUFFER
#define SUITE_STATE (&engine)
#define SUITE_FINISH(t) fast_finish(t, &engine, NULL)
#include "../shared/coverage_suite.inc"

int main(void)
{
    engine = fast_raster(depth_setup(FLOAT32, REVERSED, SUITE_NEAR, SUITE_FAR), SIMD_NONE, 1, true);
    int status = run_coverage_suite("10_fast_raster");
    fast_raster_free(&engine.fast);
    return status;
}
