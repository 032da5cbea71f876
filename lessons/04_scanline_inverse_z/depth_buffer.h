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

void clear_depth(Target *t);                                 /* 1/d = 0 everywhere */
bool depth_test(Target *t, size_t i, int face, float inv_d); /* the nearer 1/d wins */
double stored_to_depth(const Target *t, float stored);      /* d = 1/stored, inf for 0 */
extern const Rasterizer SCANLINE_ZBUFFER; /* as the pipeline sees it: clear, draw_face, d */

#endif
