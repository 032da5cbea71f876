/* depth_bias.h: lesson 07, depth bias (docs/07_depth_bias.md). A face in
 * `decal` adds o = m FACTOR + r UNITS to its z_w, m its steepest slope on
 * the screen, r one step of the format there; lesson 06's buffer
 * (depth_format.h) is unchanged. */
#ifndef DEPTH_BIAS_H
#define DEPTH_BIAS_H

#include "depth_format.h"

typedef struct {
    double factor, units, clamp; /* --polygon-offset FACTOR,UNITS, --offset-clamp */
    const Mesh *mesh;            /* whose faces in `decal` get it; NULL: none */
} DepthBias;

/* The steps, in the order depth_bias.c takes them: m, r and o of a face. */
double depth_slope(const DepthPlane *p);
double resolvable_difference(const DepthSetup *s, const ScreenVertex *v, int n);
double polygon_offset(const DepthBias *bias, double m, double r);

/* Lesson 06's DEPTH_PRECISION_ZBUFFER, but a face in `decal` drawn with its o. */
extern const Rasterizer DEPTH_BIAS_ZBUFFER;

#endif
