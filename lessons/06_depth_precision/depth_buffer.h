/* depth_buffer.h: lesson 06's buffer, which lesson 04's scanline.c tests each
 * fragment against: z_w in a format (depth_format.h: what it stores, its clear,
 * which fragment wins), taken from the triangle's plane, not the walk's 1/d. */
#ifndef DEPTH_BUFFER_H
#define DEPTH_BUFFER_H

#include "depth_format.h"

void clear_depth(Target *t, LessonState *s);                    /* the far plane everywhere */
float fragment_depth(const Primitive *p, int x, int y);         /* its z_w, stored */
bool depth_test(const Primitive *p, int x, int y, float inv_d); /* that against the buffer */

/* The fragment step, each pixel a span covers: the depth test alone (08: and a shader). */
static inline void fragment(const Primitive *p, int x, int y, float v) { depth_test(p, x, y, v); }

#endif
