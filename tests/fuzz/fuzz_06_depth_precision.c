/* fuzz_06_depth_precision.c: lesson 06's depth buffer in every format and
 * mapping (depth_buffer.c) against faces in clip space with any coordinates,
 * on screens of any size (make fuzz FUZZ=06). See fuzz_clip.h. */
#include "state.h"

#include "fuzz_depth.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    FuzzBytes b = {data, size};
    FuzzScene s;
    fuzz_scene(&s, &b);
    LessonState state = {.depth = fuzz_depth_setup(&s, &b, true)};
    Rasterizer rz = DEPTH_PRECISION_ZBUFFER;
    rz.state = &state;
    Target t;
    fuzz_target(&t, &s);
    fuzz_draw(&s, &rz, &t, NULL);
    target_free(&t);
    return 0;
}
