/* raster.c: lesson 03, perspective-correct depth (see raster.h and docs/03_perspective_z.md). */
#include "raster.h"

#include <math.h>

/* Before the first face: every pixel holds what any first fragment beats. */
void clear_depth(Target *t, LessonState *s)
{
    (void)s; /* none in this lesson (rasterizer.h) */
    size_t n = (size_t)t->width * (size_t)t->height;
    for (size_t i = 0; i < n; i++) {
        t->depth[i] = INFINITY;
        t->face[i] = NO_FACE;
    }
}

/* What interpolate_depth blends at a corner, worked out once per corner by
 * draw_triangle (lesson 02's coverage.c), not once per pixel. */
double corner_depth(ScreenVertex v)
{
    /* SOLUTION BEGIN: under perspective, which quantity of the corner is
     * linear on the screen? */
    return 1 / v.d;
    /* SOLUTION STUB
    return v.d; // lesson 02's d, for now
    */
    /* SOLUTION END */
}

/* Under perspective 1/d, not d, is linear on the screen: divide the plane
 * equation a x + b y + c z = e of a face by d, and 1/d comes out as an affine
 * function of x / d and y / d, which are affine in the screen position.
 * The corners' 1/d come in worked out (corner_depth), so a pixel pays one
 * division, not four.
 * Weights 0.5, 0.3, 0.2 on depths 2, 3, 4 give d = 2.5 (docs/03_perspective_z.md). */
double interpolate_depth(Barycentric w, double inv_d0, double inv_d1, double inv_d2)
{
    /* SOLUTION BEGIN: the depth d at the pixel centre. Barycentric weights
     * reproduce exactly what is linear on the screen: use them on that, then
     * turn the result back into a depth. */
    double inv_d = w.w0 * inv_d0 + w.w1 * inv_d1 + w.w2 * inv_d2;
    return 1 / inv_d;
    /* SOLUTION STUB
    return w.w0 * inv_d0 + w.w1 * inv_d1 + w.w2 * inv_d2; // lesson 02's blend, for now
    */
    /* SOLUTION END */
}

/* The z-buffer test: the fragment wins when it is nearer than what the pixel
 * holds, d < stored. A tie keeps the face drawn first. inline: draw_triangle
 * runs it for every fragment, where a call would cost as much as the test. */
inline bool depth_test(Target *t, size_t i, int face, float d)
{
    float stored = t->depth[i];
    bool passed = d < stored;
    target_record(t, i, face, d, stored, passed);
    if (passed) {
        t->depth[i] = d;
        t->face[i] = face;
    }
    return passed;
}

const Rasterizer ZBUFFER = {.clear = clear_depth, .draw_face = draw_face, .stored_to_depth = NULL};
