/* naive.h: lesson 02's rule, kept beside lesson 03's to show where it fails.
 *
 * The same triangles, pixels, fill rule and depth test as raster.c, but the
 * depth of a pixel is blended from the corners' d itself, as if d were linear
 * on the screen: d = w0 d0 + w1 d1 + w2 d2. Weights 0.5, 0.3, 0.2 on depths
 * 2, 3, 4 give 2.7, where the right rule gives 2.5 (--depth-interp naive,
 * --compare-naive). */
#ifndef NAIVE_H
#define NAIVE_H

#include "raster.h"

double interpolate_depth_naive(Barycentric w, double d0, double d1, double d2);

extern const Rasterizer ZBUFFER_NAIVE;

#endif
