/* raster.h: lesson 02, the z-buffer.
 *
 * A triangle covers the pixels whose centres lie inside it (coverage.h); the
 * barycentric weights of each such pixel centre interpolate the view depth d
 * of the corners. The depth buffer keeps, per pixel, the smallest d seen so far.
 *
 * This lesson interpolates d itself linearly on the screen: the naive way,
 * wrong under perspective. Lesson 03 takes 1/d to be linear instead, and
 * changes only that: interpolate_depth blends the corners' 1/d and inverts
 * the result, corner_depth gives it each corner's 1/d, and
 * the guard band cuts a triangle by the same rule (DEPTH_LINEARITY). */
#ifndef RASTER_H
#define RASTER_H

#include <stdbool.h>
#include <stddef.h>

#include "coverage.h"
#include "guard_band.h"
#include "rasterizer.h"
#include "target.h"

/* What this lesson takes to be linear on the screen: d itself (the naive way).
 * A triangle cut at the guard band gets its new corners' d by the same rule. */
#define DEPTH_LINEARITY LINEAR_D

void clear_depth(Target *t, LessonState *s); /* s: none here (rasterizer.h) */
double corner_depth(ScreenVertex v); /* what interpolate_depth blends at a corner: d */
double interpolate_depth(Barycentric w, double d0, double d1, double d2);
bool depth_test(Target *t, size_t i, int face, float d);
/* Corners inside the guard band (guard_band.h): draw_face sees to that. */
void draw_triangle(Target *t, ScreenVertex a, ScreenVertex b, ScreenVertex c, int face,
                   double far);
void draw_face(Target *t, LessonState *s, const ScreenFace *f, const DrawContext *ctx);

/* The lesson as the pipeline sees it: the buffer holds d, cleared to +infinity. */
extern const Rasterizer ZBUFFER;

#endif
