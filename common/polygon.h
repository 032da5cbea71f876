/* polygon.h: a face drawn as convex polygons (lesson 04 on). A convex face
 * goes to the lesson's draw_polygon whole, cut to the guard band first when it
 * reaches beyond it (guard_band.h); any other, or one draw_polygon refuses, as
 * its triangles. */
#ifndef POLYGON_H
#define POLYGON_H

#include <stdbool.h>

#include "rasterizer.h"

/* Draws the convex polygon v[0 .. n-1] of p; false, drawing nothing, when it
 * cannot (then its triangles are drawn instead). */
typedef bool (*DrawPolygonFn)(const Primitive *p, const ScreenVertex *v, int n, double far);

/* Convex once snapped to 1/subpixel_one pixel: one left and one right side.
 * *turn > 0 when it goes clockwise on the screen (y down). */
bool convex_on_screen(const ScreenVertex *v, int n, int subpixel_one, int *turn);

void draw_face_as_polygons(const Primitive *p, const ScreenFace *f, const DrawContext *ctx,
                           DrawPolygonFn draw_polygon);

#endif
