/* scanline.h: lesson 04's, cut to what lesson 09 keeps (and lesson 10
 * after it). The rasterizer that replaces lesson 04's scanline.c finds a
 * polygon's pixels with edge functions and steps no 1/d, so lesson 04's
 * walk (Edge, edge_setup, edge_step, draw_span, draw_face) is not here.
 *   fill rule      lesson 03's top-left rule
 *   coverage       lesson 03's, exactly: corners snapped to 1/256 pixel */
#ifndef SCANLINE_H
#define SCANLINE_H

#include "depth_buffer.h"

#define SUBPIXEL_BITS 8                   /* as GPUs do: 1/256 of a pixel */
#define SUBPIXEL_ONE (1 << SUBPIXEL_BITS) /* one pixel in fixed point */
#define SUBPIXEL_HALF (SUBPIXEL_ONE / 2)  /* half a pixel: pixel centres */

/* The largest |x| or |y| (pixels) draw_polygon takes: 2^29 sub-pixel units, so
 * that a product of two differences stays below 2^61. Polygons reaching
 * further are cut first. */
#define SCANLINE_MAX_COORD ((double)(1 << 21))

/* A convex polygon; false, drawing nothing: drawn as its triangles instead. */
bool draw_polygon(const Primitive *p, const ScreenVertex *v, int n, double far);

#endif
