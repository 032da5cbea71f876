/* fuzz_04_scanline_inverse_z.c: lesson 04's scanline rasterizer (scanline.c)
 * against faces with any coordinates on screens of any size (make fuzz
 * FUZZ=04). See fuzz_raster.h. */
#include "scanline.h"

#include "fuzz_raster.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    return fuzz_rasterizer(&SCANLINE_ZBUFFER, data, size);
}
