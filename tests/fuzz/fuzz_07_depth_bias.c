/* fuzz_07_depth_bias.c: lesson 07's depth bias (depth_bias.c) on the faces
 * in `decal`, any factor, units and clamp, in every format and mapping,
 * against faces in clip space with any coordinates, on screens of any size
 * (make fuzz FUZZ=07). See fuzz_clip.h. */
#include "state.h"

#include "fuzz_depth.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    FuzzBytes b = {data, size};
    FuzzScene s;
    fuzz_scene(&s, &b);
    LessonState state = {.depth = fuzz_depth_setup(&s, &b, false), .bias = fuzz_bias(&s, &b)};
    Rasterizer rz = DEPTH_BIAS_ZBUFFER;
    rz.state = &state;
    Target t;
    fuzz_target(&t, &s);
    fuzz_draw(&s, &rz, &t, NULL);
    target_free(&t);
    return 0;
}
