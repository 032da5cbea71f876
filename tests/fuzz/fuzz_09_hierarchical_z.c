/* fuzz_09_hierarchical_z.c: lesson 09's tile buffer (hierarchical_z.c,
 * tiles.c), tiles of 1 to 16 pixels, kept by bounds or exactly, on lesson
 * 08's fragment step and lesson 07's buffer, against faces in clip space
 * with any coordinates, on screens of any size (make fuzz FUZZ=09). See
 * fuzz_clip.h; besides, the tile buffer changes no pixel: the depth and
 * face buffers are those drawn without it, to the bit. */
#include "state.h"

#include "fuzz_depth.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    FuzzBytes b = {data, size};
    FuzzScene s;
    fuzz_scene(&s, &b);
    LessonState state = {.depth = fuzz_depth_setup(&s, &b, false), .bias = fuzz_bias(&s, &b)};
    bool cutout[FUZZ_MAX_FACES];
    for (int f = 0; f < s.nfaces; f++)
        cutout[f] = (s.flags[f] & FUZZ_CUTOUT) != 0;
    state.early_z = (EarlyZ){.pass = 1, .cutout = cutout}; /* depth only, cutouts discard */
    uint8_t pick = fuzz_u8(&b);
    Rasterizer rz = HIERARCHICAL_ZBUFFER;
    rz.state = &state;
    Target with, without;
    fuzz_target(&with, &s);
    fuzz_target(&without, &s);
    fuzz_draw(&s, &rz, &without, NULL); /* no tile buffer: state.hiz is NULL */
    HierarchicalZ h = {0};
    Error err;
    fuzz_check(hiz_begin(&h, &with, 1 + pick % 16, &err), "hiz_begin");
    h.exact = pick & 0x10, h.count_skipped = pick & 0x20;
    state.hiz = &h;
    fuzz_draw(&s, &rz, &with, NULL);
    fuzz_check(fuzz_same_buffers(&with, &without), "the tile buffer changes no pixel");
    unsigned long long at_tiles = 0;
    for (int k = 0; k < h.tiles_x * h.tiles_y; k++)
        at_tiles += h.skipped_at[k];
    fuzz_check(at_tiles == h.tiles_skipped, "each skip counted at its tile");
    hiz_free(&h);
    target_free(&with);
    target_free(&without);
    return 0;
}
