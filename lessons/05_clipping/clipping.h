/* clipping.h: lesson 05's rasterizer as the pipeline sees it (clipping.c):
 * lesson 04's buffer of 1/d, each face clipped first (clip.h). Lessons 06 on
 * take clip.c, not this: their buffers have rasterizers of their own. */
#ifndef CLIPPING_H
#define CLIPPING_H

#include "clip.h"

extern const Rasterizer CLIPPING_ZBUFFER;

#endif
