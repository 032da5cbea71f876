/* polygon.h: a face drawn as convex polygons, for a rasterizer that fills a
 * convex polygon whole (lesson 04 on).
 *
 * draw_face_as_polygons hands the lesson's draw_polygon the face itself when
 * the face is convex, cut to the guard band first when it reaches beyond it
 * (guard_band.h); a face that is not convex, or that draw_polygon refuses
 * (not convex on the screen once snapped, too many corners), goes as its
 * triangles instead. A face with a corner that is not a finite number in
 * front of the camera draws nothing. */
#ifndef POLYGON_H
#define POLYGON_H

#include <stdbool.h>

#include "rasterizer.h"

/* Draws the convex polygon v[0 .. n-1]; false, drawing nothing, when it
 * cannot (then its triangles are drawn instead). */
typedef bool (*DrawPolygonFn)(Target *t, const ScreenVertex *v, int n, int face, double far);

/* Convex on the screen once its corners are snapped to 1/subpixel_one of a
 * pixel (rounded to nearest, as the rasterizers snap): every turn has the
 * same sign (or none), and y changes direction at most twice going round, so
 * the polygon is one loop with one left side and one right side. *turn gets
 * the sign of the turns: > 0 when it goes clockwise on the screen (y down).
 * Corners finite, |x|, |y| < 2^21 pixels. */
bool convex_on_screen(const ScreenVertex *v, int n, int subpixel_one, int *turn);

void draw_face_as_polygons(Target *t, const ScreenFace *f, const DrawContext *ctx,
                           DrawPolygonFn draw_polygon);

#endif
