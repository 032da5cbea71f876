/* rasterizer.c: see rasterizer.h. */
#include "rasterizer.h"

#include <math.h>

bool screen_face_is_finite(const ScreenFace *f)
{
    for (int k = 0; k < f->n; k++)
        if (!isfinite(f->v[k].x) || !isfinite(f->v[k].y) || !isfinite(f->v[k].d))
            return false;
    return true;
}

ScreenFace screen_triangle(const ScreenVertex v[3], int face)
{
    static const Tri first = {{0, 1, 2}};
    ScreenFace f = {.face = face, .n = 3, .v = v, .tris = &first, .convex = true};
    return f;
}
