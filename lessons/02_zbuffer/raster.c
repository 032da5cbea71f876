/* raster.c: lesson 02, the z-buffer (see raster.h and docs/02_zbuffer.md). */
#include "raster.h"

#include <math.h>

/* Before the first face: every pixel holds what any first fragment beats. */
void clear_depth(Target *t, LessonState *s)
{
    (void)s; /* none in this lesson (rasterizer.h) */
    size_t n = (size_t)t->width * (size_t)t->height;
    for (size_t i = 0; i < n; i++) {
        /* SOLUTION BEGIN: the value every pixel of the depth buffer starts
         * with: it must lose to any fragment in front of the camera. */
        t->depth[i] = INFINITY;
        /* SOLUTION STUB
        t->depth[i] = 0.0f;
        */
        /* SOLUTION END */
        t->face[i] = NO_FACE;
    }
}

/* What interpolate_depth blends at a corner: d itself, the naive way. */
double corner_depth(ScreenVertex v)
{
    return v.d;
}

/* The naive way: d taken to be linear on the screen, as if it were. It is
 * not: under perspective 1/d is (lesson 03). */
double interpolate_depth(Barycentric w, double d0, double d1, double d2)
{
    /* SOLUTION BEGIN: the view depth d at the pixel centre. Barycentric
     * weights reproduce exactly whatever is linear on the screen, and this
     * lesson takes d itself to be (lesson 03 says why it is not quite). */
    return w.w0 * d0 + w.w1 * d1 + w.w2 * d2;
    /* SOLUTION STUB
    (void)w; (void)d0; (void)d1; (void)d2;
    return 0.0;
    */
    /* SOLUTION END */
}

/* The z-buffer test: the fragment wins when it is nearer than what the pixel
 * holds. A tie keeps the face drawn first. inline: draw_triangle
 * runs it for every fragment, where a call would cost as much as the test. */
inline bool depth_test(Target *t, size_t i, int face, float d)
{
    float stored = t->depth[i];
    /* SOLUTION BEGIN: the z-buffer test: does the fragment win pixel i?
     * It must be nearer than what the pixel holds (in this buffer, which
     * way is nearer?), and a tie keeps the face drawn first. */
    bool passed = d < stored;
    /* SOLUTION STUB
    bool passed = false;
    */
    /* SOLUTION END */
    target_record(t, i, face, d, stored, passed);
    /* SOLUTION BEGIN: a fragment that wins leaves its depth and face there. */
    if (passed) {
        t->depth[i] = d;
        t->face[i] = face;
    }
    /* SOLUTION END */
    return passed;
}

const Rasterizer ZBUFFER = {.clear = clear_depth, .draw_face = draw_face, .stored_to_depth = NULL};
