/* gl.h: Mesa's llvmpipe through EGL (surfaceless: no window, no display
 * server) and OpenGL 4.5 core, set up to draw as the lessons do: the GPU
 * reference (gpu_reference.c) and the benchmark's llvmpipe rows
 * (bench_llvmpipe.c) share it.
 *
 *   gpu_open      EGL display and context; llvmpipe unless the environment
 *                 names another driver (GALLIUM_DRIVER, LIBGL_ALWAYS_SOFTWARE)
 *   gpu_prepare   the shaders, a framebuffer of RGBA8 colour and the chosen
 *                 depth format, the vertices, and the depth test:
 *                 standard  glClipControl(.., GL_ZERO_TO_ONE), cleared to 1,
 *                           LESS (the caller puts z_c = f (w_c - n) / (f - n))
 *                 reversed  glClipControl(.., GL_ZERO_TO_ONE), cleared to 0,
 *                           GREATER (the caller puts z_c = n (f - w_c) / (f - n))
 *                 gl        OpenGL's default range: z_w = (z_c / w_c + 1) / 2,
 *                           gluPerspective's z_c, cleared to 1, LESS
 *                 a tie keeps the fragment drawn first, as in the lessons
 *   gpu_draw      clear, draw every triangle, glFinish: the seconds it took
 *   gpu_draw_offset  the same, with glPolygonOffset(factor, units) (and
 *                 glPolygonOffsetClamp when clamp is not 0) enabled
 *                 (GL_POLYGON_OFFSET_FILL) on the triangles marked biased
 *   gpu_close
 * The fragment shader writes face + 1 as 24-bit RGB: --id-out's colours. */
#ifndef GPU_GL_H
#define GPU_GL_H

#include <stdbool.h>
#include <stdint.h>

#include "error.h"

typedef enum { DEPTH_UNORM16, DEPTH_UNORM24, DEPTH_FLOAT32 } DepthFormat;
extern const char *const FORMAT_NAMES[3];

typedef enum { MAP_STANDARD, MAP_REVERSED, MAP_GL } DepthMapping;
extern const char *const MAPPING_NAMES[3];

/* How the lessons' y-down rows are put on OpenGL's y-up window:
 *   flip-y       y_c negated (by the caller); framebuffer row r is the lessons' row r
 *   upper-left   glClipControl(GL_UPPER_LEFT): the same rows, by the origin
 *   both         both: the picture upside down in memory, rows read back reversed
 *   rows         neither: rows read back reversed
 * All four give the same picture; they differ in which way a tie on a
 * horizontal edge goes: llvmpipe's rule is top-left in its memory rows, so
 * flip-y and both give the lessons' rule (docs/tools.md). */
typedef enum { ORIENT_FLIP_Y, ORIENT_UPPER_LEFT, ORIENT_BOTH, ORIENT_ROWS } Orientation;
extern const char *const ORIENT_NAMES[4];

typedef struct {
    DepthFormat format;
    DepthMapping mapping;
    Orientation orient;
} GpuSetup;

/* The triangles, 3 vertices each, in drawing order. */
typedef struct {
    float *pos;  /* 4 per vertex */
    int32_t *id; /* the face, 1 per vertex */
    int n;       /* vertices, 3 per triangle */
} Vertices;

typedef struct {
    void *display, *context; /* EGLDisplay, EGLContext */
    unsigned fbo, colour, depth, program, vao, buffers[2];
} Gpu;

bool gpu_open(Gpu *gpu, Error *err);
bool gpu_prepare(Gpu *gpu, const GpuSetup *s, int width, int height, const Vertices *v,
                 Error *err);
double gpu_draw(int nverts);
/* The polygon offset of lesson 07: what it applies to, and how much. */
typedef struct {
    const bool *biased; /* per triangle: offset it (in drawing order) */
    double factor, units, clamp;
} GpuOffset;
/* False with err set when a clamp is asked for and the GL has no
 * glPolygonOffsetClamp (GL 4.6, ARB_ or EXT_polygon_offset_clamp). */
bool gpu_draw_offset(int nverts, const GpuOffset *o, double *seconds, Error *err);
void gpu_close(Gpu *gpu);

/* Seconds of the wall clock: llvmpipe draws in threads of its own. */
double wall_seconds(void);

#endif
