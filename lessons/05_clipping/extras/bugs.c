/* bugs.c: the no-clip bug (see bugs.h). */
#include "bugs.h"

#include <math.h>
#include <stdlib.h>

#include "clip.h"
#include "scanline.h"

/* Each corner divided as clip_to_screen divides it, w_c <= 0 or not, then the
 * face drawn as lesson 04 draws a face no plane cuts. */
static void draw_face_no_clip(Target *t, LessonState *s, const ScreenFace *f,
                              const DrawContext *ctx)
{
    if (!f->clip) {
        draw_face(t, s, f, ctx); /* a face made on the screen: nothing to divide */
        return;
    }
    ScreenVertex *v = malloc((size_t)f->n * sizeof *v);
    if (!v)
        return;
    for (int k = 0; k < f->n; k++) {
        v[k] = clip_to_screen(f->clip[k], t->width, t->height); /* the bug: w_c <= 0 too */
        v[k].d = fabs(v[k].d);
    }
    ScreenFace divided = *f;
    divided.v = v;
    divided.clip = NULL;
    draw_face(t, s, &divided, ctx);
    free(v);
}

/* clips: render_faces hands it every face not wholly behind the near plane. */
const Rasterizer NO_CLIP_BUG = {.clear = clear_depth, .draw_face = draw_face_no_clip,
                                .stored_to_depth = stored_to_depth, .clips = true};
