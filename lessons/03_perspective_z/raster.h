/* raster.h: lesson 03, perspective-correct depth.
 *
 * A triangle covers the pixels whose centres lie inside it (coverage.h); the
 * barycentric weights of each such pixel centre interpolate the view depth d
 * of the corners. The depth buffer keeps, per pixel, the smallest d seen so far.
 *
 * Under perspective d is not linear on the screen, 1/d is: this lesson
 * interpolates depth by that rule (corner_depth, interpolate_depth), where
 * lesson 02 blended d itself. */
#ifndef RASTER_H
#define RASTER_H

#include <stdbool.h>
#include <stddef.h>

#include "coverage.h"
#include "guard_band.h"
#include "rasterizer.h"
#include "target.h"

/* What this lesson takes to be linear on the screen (lesson 02 took d).
 * A triangle cut at the guard band gets its new corners' d by the same rule. */
/* SOLUTION BEGIN: which quantity is linear on the screen under perspective
 * (common/guard_band.h names both choices)? The corners a cut makes must get
 * their depth by the rule the pixels use. */
#define DEPTH_LINEARITY LINEAR_INV_D
/* SOLUTION STUB
#define DEPTH_LINEARITY LINEAR_D // lesson 02's choice, for now
*/
/* SOLUTION END */

void clear_depth(Target *t, LessonState *s); /* s: none here (rasterizer.h) */
double corner_depth(ScreenVertex v); /* what interpolate_depth blends at a corner: 1/d */
double interpolate_depth(Barycentric w, double inv_d0, double inv_d1, double inv_d2);
bool depth_test(Target *t, size_t i, int face, float d);
/* Corners inside the guard band (guard_band.h): draw_face sees to that. */
void draw_triangle(Target *t, ScreenVertex a, ScreenVertex b, ScreenVertex c, int face,
                   double far);
void draw_face(Target *t, LessonState *s, const ScreenFace *f, const DrawContext *ctx);

/* The lesson as the pipeline sees it: the buffer holds d, cleared to +infinity. */
extern const Rasterizer ZBUFFER;

#endif
