/* raster.h: lesson 03, perspective-correct depth.
 *
 * A triangle covers the pixels whose centres lie inside it (coverage.h); the
 * barycentric weights of each such pixel centre interpolate the view depth d
 * of the corners. The depth buffer keeps, per pixel, the smallest d seen so far.
 *
 * Under perspective d is not linear on the screen, 1/d is: this lesson
 * interpolates depth by that rule (interpolate_depth, draw_triangle), where
 * lesson 02 blended d itself. */
#ifndef RASTER_H
#define RASTER_H

#include <stdbool.h>
#include <stddef.h>

#include "coverage.h"
#include "rasterizer.h"
#include "target.h"

void clear_depth(Target *t, LessonState *s); /* s: none here (rasterizer.h) */
double interpolate_depth(Barycentric w, double inv_d0, double inv_d1, double inv_d2);
bool depth_test(Target *t, size_t i, int face, float d);
/* Corners inside the guard band (guard_band.h): draw_face sees to that. */
void draw_triangle(Target *t, ScreenVertex a, ScreenVertex b, ScreenVertex c, int face,
                   double far);
void draw_face(Target *t, LessonState *s, const ScreenFace *f, const DrawContext *ctx);

/* The lesson as the pipeline sees it: the buffer holds d, cleared to +infinity. */
extern const Rasterizer ZBUFFER;

#endif
