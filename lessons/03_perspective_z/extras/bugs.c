/* bugs.c: the negated-w bug (see bugs.h). */
#include "bugs.h"

#include <math.h>

#include "raster.h"

/* Each triangle of the face, with -d at its corners, through the right rule.
 * 1/d blended and inverted gives exactly -(the right d): the bug changes the
 * sign of every value the depth test sees, and nothing else. */
static void draw_face_negated_w(Target *t, LessonState *s, const ScreenFace *f,
                                const DrawContext *ctx)
{
    if (!screen_face_is_finite(f))
        return; /* as draw_face: a corner that is not a number draws nothing */
    for (int k = 0; k < f->n - 2; k++) {
        ScreenVertex v[3];
        for (int j = 0; j < 3; j++) {
            v[j] = f->v[f->tris[k].c[j]];
            v[j].d = -v[j].d; /* the bug: -d where d belongs */
        }
        ScreenFace tri = screen_triangle(v, f->face);
        draw_face(t, s, &tri, ctx);
    }
}

static double negated_to_depth(const LessonState *s, float stored)
{
    (void)s;
    return -(double)stored;
}

const Rasterizer NEGATED_W_BUG = {.clear = clear_depth, .draw_face = draw_face_negated_w,
                                  .stored_to_depth = negated_to_depth};
