/* fuzz_03_perspective_z.c: lesson 03's rasterizer (raster.c) against faces
 * with any coordinates on screens of any size (make fuzz FUZZ=03). Each input
 * is drawn three times: with the right rule (1/d linear), with lesson 02's
 * naive rule (--depth-interp naive) and with the negated-w bug (--bug). See
 * fuzz_raster.h. */
#include "bugs.h"
#include "naive.h"
#include "raster.h"

#include "fuzz_raster.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_rasterizer(&ZBUFFER, data, size);
    fuzz_rasterizer(&ZBUFFER_NAIVE, data, size);
    return fuzz_rasterizer(&NEGATED_W_BUG, data, size);
}
