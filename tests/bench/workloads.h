/* workloads.h: what the benchmark draws, built the same way every time.
 *
 * Each workload is a list of faces, every corner given in clip space (what
 * Mesa's llvmpipe receives, tests/gpu/bench_llvmpipe.c), and the buffer size
 * to draw them into. A frame (workload_draw) is the work a GPU does from
 * there: every corner divided by w_c and put on the screen, then each face
 * handed to the lesson's draw_face, with its clip-space corners to a lesson
 * that clips, as render_faces hands them. The tests (test_bench_workloads.c)
 * draw the same faces through render_faces, the lesson program's own path,
 * and check that both leave the same depth buffer. Random numbers come from a fixed
 * seed and our own generator, so every machine draws the same triangles.
 *
 *   small               100,000 right triangles, legs 10 px, 1024x1024
 *   medium              10,000 right triangles, legs 100 px, 1024x1024
 *   fill_back_to_front  64 screen-sized layers of 2 triangles each, at
 *                       constant depth, nearest last: every fragment passes
 *   fill_front_to_back  the same layers, nearest first: after the first
 *                       layer every fragment fails
 *   mesh                a torus knot of 200,000 triangles seen by the knot
 *                       scene's camera at 1920x1080
 *   city                the built-in scene city (a wall drawn first, 510
 *                       small buildings behind it) by its camera, 1024x768:
 *                       most fragments are hidden (lesson 09)
 *
 * The first four are laid out on the screen: each corner (x, y, d) is made a
 * clip-space corner as a camera with WORKLOAD_NEAR and WORKLOAD_FAR would
 * put it there, and the frame's divide brings it back. Every corner's view
 * depth d is uniform in [WORKLOAD_D_MIN, WORKLOAD_D_MAX] (the fill layers
 * space their depths evenly over that range). */
#ifndef WORKLOADS_H
#define WORKLOADS_H

#include <stdbool.h>
#include <stdint.h>

#include "error.h"
#include "harness/render.h"
#include "target.h"

#define WORKLOAD_D_MIN 1.0
#define WORKLOAD_D_MAX 100.0
/* The planes handed to draw_face for the screen-space workloads: every d of
 * [1, 100] lies between them, so no face is dropped and no fragment discarded. */
#define WORKLOAD_NEAR 0.5
#define WORKLOAD_FAR 1000.0

#define SMALL_COUNT 100000
#define SMALL_LEG 10.0 /* pixels: 50 square pixels per triangle */
#define MEDIUM_COUNT 10000
#define MEDIUM_LEG 100.0
#define FILL_LAYERS 64

/* The mesh workload: a (2,3) torus knot of MESH_RINGS x MESH_SIDES quads,
 * 2 triangles each: 4,000 x 25 x 2 = 200,000 triangles. */
#define MESH_RINGS 4000
#define MESH_SIDES 25
#define MESH_TUBE_RADIUS 0.35
#define MESH_WIDTH 1920
#define MESH_HEIGHT 1080
#define CITY_WIDTH 1024
#define CITY_HEIGHT 768

typedef enum {
    WORKLOAD_SMALL,
    WORKLOAD_MEDIUM,
    WORKLOAD_FILL_BACK_TO_FRONT,
    WORKLOAD_FILL_FRONT_TO_BACK,
    WORKLOAD_MESH,
    WORKLOAD_CITY,
    WORKLOAD_COUNT
} WorkloadKind;

typedef struct {
    WorkloadKind kind;
    const char *name;     /* "small", ...: the benchmark's table and results.csv */
    int width, height;    /* the buffer */
    DrawContext ctx;      /* near and far, as render_faces would pass them */
    int nfaces;
    ScreenFace *faces;    /* in drawing order; they point into verts or render */
    long ntris;           /* triangles in all faces: n - 2 per face */
    ScreenVertex *verts;  /* the screen-space workloads: 3 corners per triangle */
    Vec4 *verts_clip;     /* ... and the same in clip space */
    Render render;        /* the mesh workload: mesh, camera, projected corners */
    bool has_render;
} Workload;

#define WORKLOAD_MAX_CORNERS 64 /* of a face: the knot's and city's have 3 or 4 */

const char *workload_name(WorkloadKind kind);

/* Builds workload kind. False (err set) when out of memory or the mesh could
 * not be built; nothing needs freeing then. */
bool workload_build(Workload *w, WorkloadKind kind, Error *err);
void workload_free(Workload *w);

/* One frame of w: every face, in order, its corners divided (camera_divide)
 * and put on t, straight into the lesson's draw_face, with its clip-space
 * corners if the lesson clips: no drop test, nothing but the pipeline from
 * clip space on. t must be w's size. */
void workload_draw(Workload *w, Target *t, const Rasterizer *rz);

/* A 64-bit FNV-1a hash of the depth buffer's bytes: two buffers with the same
 * checksum hold the same values (barring a 1 in 2^64 accident). */
uint64_t depth_checksum(const Target *t);

#endif
