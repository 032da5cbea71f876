/* fuzz_02_zbuffer.c: lesson 02's rasterizer (raster.c) against faces with any
 * coordinates on screens of any size (make fuzz FUZZ=02). See fuzz_raster.h. */
#include "raster.h"

#include "fuzz_raster.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    return fuzz_rasterizer(&ZBUFFER, data, size);
}
