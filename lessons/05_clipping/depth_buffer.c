/* depth_buffer.c: the buffer of 1/d that scanline.c's spans test (scanline.h). */
#include "scanline.h"
#include <math.h>

/* Every pixel to 1/d = 0, a surface infinitely far: nothing drawn yet. */
void clear_depth(Target *t)
{
    size_t n = (size_t)t->width * (size_t)t->height;
    for (size_t i = 0; i < n; i++) {
        t->depth[i] = CLEARED_INV_DEPTH;
        t->face[i] = NO_FACE;
    }
}

/* The depth test of one fragment at pixel i, on a buffer of 1/d. */
inline bool depth_test(Target *t, size_t i, int face, float inv_d)
{
    float stored = t->depth[i];
    bool passed = inv_d > stored;
    target_record(t, i, face, inv_d, stored, passed);
    if (passed) {
        t->depth[i] = inv_d;
        t->face[i] = face;
    }
    return passed;
}

/* A stored 1/d back as the view depth d; 0 (nothing drawn) is infinitely far. */
static double stored_to_depth(const Target *t, float stored)
{
    (void)t; /* 1/d needs nothing else */
    return stored > 0 ? 1.0 / stored : INFINITY;
}

/* Front object detection: the view depth of the nearest surface at (x, y). */
double nearest_distance_at(const Target *t, int x, int y)
{
    return stored_to_depth(t, t->depth[(size_t)y * (size_t)t->width + (size_t)x]);
}

const Rasterizer SCANLINE_ZBUFFER = {
    .clear = clear_depth, .draw_face = draw_face, .stored_to_depth = stored_to_depth,
};
