/* fuzz_05_clipping.c: lesson 05's clipping rasterizer (clipping.c, clip.c)
 * against faces in clip space with any coordinates, on screens of any size
 * (make fuzz FUZZ=05). See fuzz_clip.h. */
#include "clipping.h"

#include "fuzz_clip.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    FuzzBytes b = {data, size};
    FuzzScene s;
    fuzz_scene(&s, &b);
    Target t;
    fuzz_target(&t, &s);
    fuzz_draw(&s, &CLIPPING_ZBUFFER, &t, NULL);
    target_free(&t);
    return 0;
}
