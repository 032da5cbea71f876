/* clip.h: lesson 05, clipping at the near and far planes in clip space,
 * before the divide, as a GPU does (docs/05_clipping.md).
 *
 *   clip space   (x_c, y_c, z_c, w_c) = P V (x, y, z, 1), P gluPerspective's:
 *                w_c = d, the view depth
 *   inside       the near plane when z_c >= -w_c, the far plane when z_c <= w_c
 *   clipping     Sutherland-Hodgman, one plane after the other; a new corner
 *                is interpolated linearly in clip space, where that is exact
 *   then         the divide by w_c (> 0 once the near plane has cut), the
 *                viewport, and lesson 04's scanline into the lesson's buffer
 * x and y are not clipped: the guard band (guard_band.h) does that job. */
#ifndef CLIP_H
#define CLIP_H

#include "rasterizer.h"

#define CLIP_MAX_IN 64            /* a face with more corners is clipped as its triangles */
/* A plane cuts a convex polygon into one with at most one corner more: 4 n
 * corners are room to spare for both planes. */
#define CLIP_MAX_OUT(n) (4 * (n))

typedef enum { NEAR_PLANE, FAR_PLANE } ClipPlane;

/* The steps, in the order clip.c takes them (each is explained there). */
double plane_distance(Vec4 p, ClipPlane plane);                  /* >= 0: inside */
Vec4 plane_crossing(Vec4 in, double d_in, Vec4 out, double d_out); /* on the plane */
int clip_to_plane(const Vec4 *in, int n, ClipPlane plane, Vec4 *out);
int clip_polygon(const Vec4 *in, int n, Vec4 *out);              /* near, then far */
ScreenVertex clip_to_screen(Vec4 c, int width, int height);      /* divide, viewport */
void draw_clipped_face(const Primitive *p, const ScreenFace *f, const DrawContext *ctx);

#endif
