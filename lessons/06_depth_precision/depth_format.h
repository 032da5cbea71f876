/* depth_format.h: lesson 06, the depth buffer as a GPU keeps it
 * (docs/06_depth_precision.md).
 *
 *   stored value   window depth z_w in [0, 1], in a format:
 *                    unorm16, unorm24  the integer code round(z_w (2^bits - 1))
 *                    float32           z_w itself, a float
 *   mapping        standard  z_w = f/(f-n) (1 - n/d): 0 at near, 1 at far
 *                  reversed  z_w = n/(f-n) (f/d - 1): 1 at near, 0 at far;
 *                            with far = inf, z_w = n/d
 *                  log       z_w = log(d/n) / log(f/n): 0 at near, 1 at far
 *   cleared to     1 (standard, log) or 0 (reversed): the far plane
 *   a fragment     wins when its value < stored (standard, log), > stored
 *                  (reversed); a tie keeps the first one drawn
 * Standard and reversed are z_w = a + b/d, affine in 1/d, so affine on the
 * screen: in float32, as on a GPU, each corner's z_w = z_c / w_c (z_c = a w_c
 * + b, w_c = d), then each triangle's plane of z_w, evaluated at every pixel
 * centre the scanline covers. Log is not: its plane is of n/d (a = 0, b = n),
 * and each fragment writes the log, as a fragment program writing its depth
 * does. The lesson's state (state.h) holds the setup, chosen before clear_depth. */
#ifndef DEPTH_FORMAT_H
#define DEPTH_FORMAT_H

#include <stddef.h>

#include "rasterizer.h"

typedef enum { UNORM16, UNORM24, FLOAT32 } DepthFormat;
typedef enum { STANDARD, REVERSED, LOGARITHMIC } DepthMapping;

/* A triangle's z_w on the screen, as a GPU sets it up, in float32:
 * z_w = a0 + gx x + gy y at the centre of pixel (x, y). */
typedef struct {
    float a0, gx, gy;
} DepthPlane;

typedef struct DepthSetup {
    DepthFormat format;
    DepthMapping mapping;
    double near, far; /* far may be INFINITY with REVERSED */
    double a, b;      /* z_w = a + b / d; for LOGARITHMIC the plane's n/d */
    double log_range; /* log(f/n): LOGARITHMIC's z_w = -log(n/d) / log_range */
} DepthSetup;

/* A triangle being drawn (rasterizer.h): lesson 04's, and its plane of z_w. */
struct Primitive {
    Target *target;
    LessonState *state; /* the lesson's own (state.h): the buffer's setup, ... */
    int face;
    DepthPlane plane;   /* the triangle's z_w on the screen */
    float offset;       /* added to its z_w: 0, or lesson 07's depth bias */
};

/* The steps, in the order depth_buffer.c takes them (each is explained there). */
DepthSetup depth_setup(DepthFormat format, DepthMapping mapping, double near, double far);
double window_depth(const DepthSetup *s, double d);  /* z_w of view depth d */
double view_depth(const DepthSetup *s, double z_w);  /* and back */
float encode_depth(DepthFormat format, float z_w);   /* what the buffer stores */
double decode_depth(DepthFormat format, float stored);
double depth_quantum(DepthFormat format, double z_w); /* one step of z_w there */
double depth_step(const DepthSetup *s, double d);     /* ... and of d, in world units */
DepthPlane depth_plane(const DepthSetup *s, const ScreenVertex v[3]); /* a triangle's */
/* Each triangle with its plane; offset is added to every z_w (lesson 07's bias). */
void draw_triangles(Target *t, LessonState *s, const ScreenFace *f, const DrawContext *ctx,
                    float offset);
double stored_to_depth(const LessonState *s, float stored); /* a stored value back as d */

/* clear_depth, then every triangle clipped (clip.c) and drawn by lesson 04's
 * scanline into the buffer of z_w, its depth from its plane. */
extern const Rasterizer DEPTH_PRECISION_ZBUFFER;

#endif
