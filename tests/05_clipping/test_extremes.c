/* test_extremes.c: lesson 05's clipping z-buffer with coordinates out to 1e30,
 * faces around the screen many times over, degenerate faces and corners that
 * are not numbers, as lessons 02 and 03's. The tests are shared with the other
 * 3-D lessons: see tests/shared/extremes_suite.inc. */
#include "clipping.h"

#define EXTREMES_RASTERIZER CLIPPING_ZBUFFER
#include "../shared/extremes_suite.inc"

int main(void)
{
    return run_extremes_suite("05_clipping extremes");
}
