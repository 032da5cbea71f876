/* coverage.h: lesson 02, which pixels a triangle covers (docs/02_zbuffer.md):
 * those whose centre is inside its three edge functions, evaluated exactly in
 * fixed point; a centre exactly on an edge is inside only if that edge is a
 * top or a left edge. The same numbers over the area are barycentric weights. */
#ifndef COVERAGE_H
#define COVERAGE_H

#include <stdbool.h>
#include <stdint.h>

#include "rasterizer.h"

#define SUBPIXEL_BITS 8                         /* as GPUs do: 1/256 of a pixel */
#define SUBPIXEL_ONE (1 << SUBPIXEL_BITS)       /* one pixel in fixed point */
#define SUBPIXEL_HALF (SUBPIXEL_ONE / 2)        /* half a pixel: pixel centres */

/* A point on the screen in fixed point: x = 256 means one pixel from the left. */
typedef struct { int64_t x, y; } FixedPoint;

/* The pixels a triangle may cover: x0..x1, y0..y1 inclusive; empty when x0 > x1 or y0 > y1. */
typedef struct { int x0, y0, x1, y1; } PixelBox;

/* The weights of the three corners at a point: w0 + w1 + w2 = 1. */
typedef struct { double w0, w1, w2; } Barycentric;

/* An edge function walked over the bounding box. E(a, b, p) is linear in p:
 * one pixel right adds -(b.y - a.y) * 256, one row down (b.x - a.x) * 256: an
 * addition per edge and pixel, exactly the integers edge_function gives. */
typedef struct {
    int64_t row_start; /* E at the centre of the box's first pixel on this row */
    int64_t step_x;    /* added per pixel to the right */
    int64_t step_y;    /* added per row down */
    bool top_left;     /* a centre exactly on the edge is inside (edge_covers) */
} EdgeStepper;

FixedPoint snap_to_fixed(ScreenVertex v);
FixedPoint pixel_centre(int x, int y);
int64_t edge_function(FixedPoint a, FixedPoint b, FixedPoint p);
bool is_top_left(FixedPoint a, FixedPoint b);
bool edge_covers(int64_t e, bool top_left);
PixelBox bounding_box(FixedPoint a, FixedPoint b, FixedPoint c, int width, int height);
Barycentric barycentric_weights(int64_t e0, int64_t e1, int64_t e2, double inv_area);
EdgeStepper edge_stepper(FixedPoint a, FixedPoint b, FixedPoint first_centre);

#endif
