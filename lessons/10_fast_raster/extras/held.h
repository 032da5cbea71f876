/* held.h: lesson 10's faces held back for the threads to set up (held.c),
 * and what engine.c shares with it. */
#ifndef HELD_H
#define HELD_H

#include "engine.h"

void set_up_face(Target *t, LessonState *s, const ScreenFace *f, const DrawContext *ctx); /* now */
bool hold_face(Target *t, LessonState *s, const ScreenFace *f, const DrawContext *ctx);
void held_free(FastRaster *fr);
void bins_free(Bins *b);
/* Room for need items of size bytes in *items, of *cap; false (nothing changed) without. */
bool grow_array(void **items, size_t *cap, size_t need, size_t size);

#endif
