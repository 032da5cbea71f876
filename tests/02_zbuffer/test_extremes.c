/* test_extremes.c: lesson 02's z-buffer with coordinates out to 1e30, faces around the
 * screen many times over, degenerate faces and corners that are not numbers.
 * The tests are shared with the other 3-D lessons: see
 * tests/shared/extremes_suite.inc. */
#include "raster.h"

#define EXTREMES_RASTERIZER ZBUFFER
#include "../shared/extremes_suite.inc"

int main(void)
{
    return run_extremes_suite("02_zbuffer extremes");
}
