/* painter.h: the painter's algorithm, to see it fail.
 *
 * Sort the faces by mean depth, draw them back to front, and let each one paint
 * over whatever is there: no depth buffer. Where faces overlap cyclically
 * (scene triangles3) no order is right, and the picture is wrong. */
#ifndef PAINTER_H
#define PAINTER_H

#include "harness/render.h"

/* order[0 .. nfaces-1]: faces by mean view depth of their corners, farthest
 * first; equal means keep mesh order. */
void painter_order(const Render *r, int *order);

/* Draws every face back to front with no depth test between faces. */
bool draw_painter(Render *r, Target *t, const Rasterizer *rz, Error *err);

#endif
