/* scanline.h: lesson 04, the z-buffer as 1990s software renderers wrote it:
 * the walk, whose spans test each fragment against the buffer (depth_buffer.h).
 *   rasterizer     a convex polygon, drawn whole: its two sides walked down
 *                  row by row, x and 1/d stepping by a constant per row, then
 *                  1/d by a constant per pixel along each span
 *   fill rule      row centre y + 0.5 in [top, bottom), pixel centre x + 0.5
 *                  in [left, right): lesson 03's top-left rule, scanline form
 *   coverage       lesson 03's, exactly: corners snapped to 1/256 pixel, edge
 *                  x kept exact (a whole pixel and a fraction, in integers) */
#ifndef SCANLINE_H
#define SCANLINE_H

#include <stdint.h>

#include "depth_buffer.h"
#include "rasterizer.h"

#define SUBPIXEL_BITS 8                   /* as GPUs do: 1/256 of a pixel */
#define SUBPIXEL_ONE (1 << SUBPIXEL_BITS) /* one pixel in fixed point */
#define SUBPIXEL_HALF (SUBPIXEL_ONE / 2)  /* half a pixel: pixel centres */

/* The largest |x| or |y| (pixels) draw_polygon takes: 2^29 sub-pixel units, so
 * edge_setup's products stay below 2^61. Polygons reaching further are cut first. */
#define SCANLINE_MAX_COORD ((double)(1 << 21))

/* One edge of the polygon, walked one scanline at a time. On the current row
 * the edge crosses the row centre at
 *     x_edge = x_pixel + 0.5 - rem / den        (pixels, exactly)
 * so x_pixel is the first pixel whose centre is at or right of the edge, and
 * rem / den in [0, 1) is how far that centre lies right of it. */
typedef struct {
    int64_t x_pixel;     /* first pixel centre >= x_edge on this row */
    int64_t rem, den;    /* 0 <= rem < den */
    int64_t step_pixel;  /* per scanline: x_pixel += step_pixel, */
    int64_t step_rem;    /*   rem -= step_rem, and one more pixel when rem < 0 */
    double inv_d;        /* 1/d where the edge crosses this row's centre */
    double inv_d_step;   /* d(1/d)/dy: its change per scanline */
    int y_end;           /* first row below the edge */
} Edge;

/* The steps, in the order scanline.c takes them (each is explained there). */
bool edge_setup(Edge *e, int64_t ax, int64_t ay, double inv_a, int64_t bx, int64_t by,
                double inv_b, int y_first);               /* false: no row to walk */
void edge_step(Edge *e);                                  /* one scanline down */
void draw_span(const Primitive *p, int y, const Edge *left, const Edge *right, double inv_far);
/* A convex polygon drawn whole; false: drawn as its triangles instead. */
bool draw_polygon(const Primitive *p, const ScreenVertex *v, int n, double far);
void draw_face(Target *t, LessonState *s, const ScreenFace *f, const DrawContext *ctx);

#endif
