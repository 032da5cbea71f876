/* depth_buffer.h: lesson 04's buffer, which scanline.c's spans test.
 *   stored value   1/d, the reciprocal of the view depth
 *   cleared to     0, which means "infinitely far"
 *   a fragment     wins when its 1/d > stored (ties keep the first one drawn) */
#ifndef DEPTH_BUFFER_H
#define DEPTH_BUFFER_H

#include "rasterizer.h"
#include "target.h"

/* Nothing drawn yet: 1/d = 0 is infinitely far; every surface (1/d > 0) is nearer. */
#define CLEARED_INV_DEPTH 0.0f

/* A face being drawn (rasterizer.h); no state here (NULL). Lesson 06 adds more. */
struct Primitive { Target *target; LessonState *state; int face; };

void clear_depth(Target *t, LessonState *s);                 /* 1/d = 0 everywhere */
bool depth_test(const Primitive *p, int x, int y, float inv_d); /* the nearer 1/d wins */
double stored_to_depth(const LessonState *s, float stored);  /* d = 1/stored, inf for 0 */
extern const Rasterizer SCANLINE_ZBUFFER; /* as the pipeline sees it: clear, draw_face, d */
/* The fragment step, each pixel a span covers: the depth test alone (08: and a shader). */
static inline void fragment(const Primitive *p, int x, int y, float v) { depth_test(p, x, y, v); }

#endif
