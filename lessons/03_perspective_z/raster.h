/* raster.h: lesson 03, perspective-correct depth.
 *
 * A triangle covers the pixels whose centres lie inside it. Inside is decided
 * by three edge functions, evaluated exactly in fixed point; a centre exactly
 * on an edge belongs to the triangle only if that edge is a top or a left edge.
 * The same three numbers, divided by the triangle's area, are the barycentric
 * weights of the pixel centre, and they interpolate the view depth d of the
 * corners. The depth buffer keeps, per pixel, the smallest d seen so far.
 *
 * Under perspective d is not linear on the screen, 1/d is: this lesson
 * interpolates depth by that rule (interpolate_depth, draw_triangle), where
 * lesson 02 blended d itself. */
#ifndef RASTER_H
#define RASTER_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "rasterizer.h"
#include "target.h"

#define SUBPIXEL_BITS 8                         /* as GPUs do: 1/256 of a pixel */
#define SUBPIXEL_ONE (1 << SUBPIXEL_BITS)       /* one pixel in fixed point */
#define SUBPIXEL_HALF (SUBPIXEL_ONE / 2)        /* half a pixel: pixel centres */

/* A point on the screen in fixed point: x = 256 means one pixel from the left. */
typedef struct { int64_t x, y; } FixedPoint;

/* The pixels a triangle may cover: x0..x1, y0..y1 inclusive; empty when x0 > x1 or y0 > y1. */
typedef struct { int x0, y0, x1, y1; } PixelBox;

/* The weights of the three corners at a point: w0 + w1 + w2 = 1. */
typedef struct { double w0, w1, w2; } Barycentric;

void clear_depth(Target *t, LessonState *s); /* s: none here (rasterizer.h) */
FixedPoint snap_to_fixed(ScreenVertex v);
FixedPoint pixel_centre(int x, int y);
int64_t edge_function(FixedPoint a, FixedPoint b, FixedPoint p);
bool is_top_left(FixedPoint a, FixedPoint b);
bool edge_covers(int64_t e, bool top_left);
PixelBox bounding_box(FixedPoint a, FixedPoint b, FixedPoint c, int width, int height);
Barycentric barycentric_weights(int64_t e0, int64_t e1, int64_t e2, double inv_area);
double interpolate_depth(Barycentric w, double inv_d0, double inv_d1, double inv_d2);
bool depth_test(Target *t, size_t i, int face, float d);
/* Corners inside the guard band (guard_band.h): draw_face sees to that. */
void draw_triangle(Target *t, ScreenVertex a, ScreenVertex b, ScreenVertex c, int face,
                   double far);
void draw_face(Target *t, LessonState *s, const ScreenFace *f, const DrawContext *ctx);

/* The lesson as the pipeline sees it: the buffer holds d, cleared to +infinity. */
extern const Rasterizer ZBUFFER;

#endif
