/* fuzz_08_early_z.c: lesson 08's fragment step (early_z.c) in late and
 * early mode, faces in `cutout` discarding their holes, on lesson 07's
 * biased buffer in every format and mapping, against faces in clip space
 * with any coordinates, on screens of any size (make fuzz FUZZ=08). See
 * fuzz_clip.h; besides, the fragment step counts every depth test, and a
 * pixel a face holds was shaded. */
#include "state.h"

#include "fuzz_depth.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    FuzzBytes b = {data, size};
    FuzzScene s;
    fuzz_scene(&s, &b);
    LessonState state = {.depth = fuzz_depth_setup(&s, &b, false), .bias = fuzz_bias(&s, &b)};
    EarlyZ *z = &state.early_z;
    uint8_t mode = fuzz_u8(&b);
    z->mode = mode & 1 ? Z_EARLY : Z_LATE;
    size_t n = (size_t)s.width * (size_t)s.height;
    bool cutout[FUZZ_MAX_FACES];
    Rgb lit[FUZZ_MAX_FACES];
    for (int f = 0; f < s.nfaces; f++)
        cutout[f] = (s.flags[f] & FUZZ_CUTOUT) != 0, lit[f] = (Rgb){(uint8_t)(40 * f), 90, 200};
    z->cutout = cutout, z->lit = lit;
    z->colour = calloc(n, sizeof *z->colour);
    z->shade_count = calloc(n, sizeof *z->shade_count);
    fuzz_check(z->colour && z->shade_count, "the shader's buffers");
    Rasterizer rz = DEPTH_BIAS_ZBUFFER;
    rz.state = &state;
    Target t;
    fuzz_target(&t, &s);
    fuzz_draw(&s, &rz, &t, NULL);
    for (size_t i = 0; i < n; i++)
        fuzz_check(t.face[i] == NO_FACE || z->shade_count[i] > 0,
                   "a pixel a face holds was shaded (in either mode, a fragment that passes is)");
    fuzz_check(z->tested == t.stats.tested, "the fragment step counts every depth test");
    free(z->colour);
    free(z->shade_count);
    target_free(&t);
    return 0;
}
