/* depth_buffer.c: the buffer of 1/d that scanline.c's spans test (depth_buffer.h). */
#include "scanline.h"
#include <math.h>

/* Every pixel to 1/d = 0, a surface infinitely far: nothing drawn yet. */
void clear_depth(Target *t, LessonState *s)
{
    (void)s; /* no state of its own */
    size_t n = (size_t)t->width * (size_t)t->height;
    for (size_t i = 0; i < n; i++) {
        t->depth[i] = CLEARED_INV_DEPTH;
        t->face[i] = NO_FACE;
    }
}

/* The depth test of one fragment of p at pixel (x, y), on a buffer of 1/d. */
inline bool depth_test(const Primitive *p, int x, int y, float inv_d)
{
    Target *t = p->target;
    size_t i = (size_t)y * (size_t)t->width + (size_t)x;
    float stored = t->depth[i];
    /* SOLUTION BEGIN: does the fragment win pixel i? This buffer holds 1/d,
     * not d: which way is nearer now? A tie keeps the fragment drawn first. */
    bool passed = inv_d > stored;
    /* SOLUTION STUB
    bool passed = false;
    */
    /* SOLUTION END */
    target_record(t, i, p->face, inv_d, stored, passed);
    /* SOLUTION BEGIN: a fragment that wins leaves its 1/d and face there. */
    if (passed) {
        t->depth[i] = inv_d;
        t->face[i] = p->face;
    }
    /* SOLUTION END */
    return passed;
}

/* A stored 1/d back as the view depth d; 0 (nothing drawn) is infinitely far. */
double stored_to_depth(const LessonState *s, float stored)
{
    (void)s; /* 1/d needs nothing else */
    return stored > 0 ? 1.0 / stored : INFINITY;
}

const Rasterizer SCANLINE_ZBUFFER = {
    .clear = clear_depth, .draw_face = draw_face, .stored_to_depth = stored_to_depth,
};
