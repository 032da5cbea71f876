/* clipping.c: lesson 05's rasterizer as the pipeline sees it (clipping.h). */
#include "clipping.h"

#include "scanline.h"

/* The lesson's buffer (scanline.h: its clear and its stored value as d), each
 * face clipped first. */
static void draw_face_clipped(Target *t, LessonState *s, const ScreenFace *f,
                              const DrawContext *ctx)
{
    Primitive p = {.target = t, .state = s, .face = f->face};
    draw_clipped_face(&p, f, ctx);
}

const Rasterizer CLIPPING_ZBUFFER = {
    .clear = clear_depth, .draw_face = draw_face_clipped, .stored_to_depth = stored_to_depth,
    .clips = true,
};
