/* guard_band.h: keeping screen coordinates small enough for fixed point.
 *
 * The rasterizers snap vertices to fixed point with 8 sub-pixel bits and
 * evaluate edge functions E = dx * py - dy * px in 64-bit integers. That is
 * exact only while the numbers fit: a vertex that projects a million pixels
 * off screen (it sits just in front of the near plane) would overflow it,
 * and walking its bounding box would cost more than the screen.
 *
 * So a polygon that leaves the guard band, the rectangle
 *     [-GUARD_BAND, width + GUARD_BAND] x [-GUARD_BAND, height + GUARD_BAND],
 * is first clipped against it (Sutherland-Hodgman, in screen space). Inside
 * it every |coordinate| < 2^20 + 2^14 < 2^21 pixels, so < 2^29 in fixed point;
 * a difference of two is < 2^30, a product of two differences < 2^60, and an
 * edge function, a difference of two products, < 2^61: int64_t never overflows.
 *
 * The band's edges lie 2^20 pixels off screen, so the cut only moves edges
 * where no pixel centre is. New vertices get their depth by the lesson's own
 * rule for what is linear on the screen (d in lesson 02, 1/d in 03 and 04),
 * so a clipped polygon has the same depth at every pixel as the whole one.
 * A polygon entirely inside the band is copied unchanged. */
#ifndef GUARD_BAND_H
#define GUARD_BAND_H

#include <stdbool.h>

#include "camera.h"

#define GUARD_BAND (1 << 20) /* pixels beyond each side of the screen */

/* Clipping an n-gon against 4 lines adds at most 4 vertices. */
#define GUARD_BAND_MAX_OUT(n) ((n) + 4)

typedef enum {
    LINEAR_D,     /* d is linear in screen space (lesson 02) */
    LINEAR_INV_D  /* 1/d is linear in screen space */
} DepthLinearity;

/* True when every vertex lies inside the guard band of a width x height screen. */
bool guard_band_contains(const ScreenVertex *v, int n, int width, int height);

/* Clips the convex polygon in[0 .. n-1] (a triangle, or a face whose convex
 * flag is set; finite coordinates, d > 0) against the guard band into out,
 * which holds GUARD_BAND_MAX_OUT(n) vertices. Returns the number of vertices
 * of the result: n when it was inside already (out is a copy), 0 when nothing
 * is left (it is far off screen, n < 3, or a corner's x, y or d is not a
 * finite number), and 0 too when rounding folded it into a polygon that is no
 * longer convex, which only edges with both ends beyond 2^53 pixels can do. */
int guard_band_clip(const ScreenVertex *in, int n, int width, int height,
                    DepthLinearity linear, ScreenVertex *out);

#endif
