/* depth_buffer.h: lesson 06's buffer, which lesson 04's scanline.c tests each
 * fragment against: z_w in a format (depth_format.h: what it stores, its clear,
 * which fragment wins), taken from the triangle's plane, not the walk's 1/d. */
#ifndef DEPTH_BUFFER_H
#define DEPTH_BUFFER_H

#include "depth_format.h"

void clear_depth(Target *t);                                 /* the far plane everywhere */
bool depth_test(Target *t, size_t i, int face, float inv_d); /* z_w from the plane, not inv_d */

#endif
