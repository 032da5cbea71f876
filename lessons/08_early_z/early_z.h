/* early_z.h: lesson 08, early-Z and the depth pre-pass (docs/08_early_z.md).
 *
 *   cutout          a face in group `cutout` discards where cutout_keeps is false
 *   --z-mode late   shade every fragment, then test it
 *            early  test first, shade what passed; a cutout falls back to
 *                   late: its depth must not be written before its discard
 *            prepass pass 1 writes depth only (a cutout runs its cheap discard);
 *                   pass 2, depth writes off, shades where depth is equal
 *   --sort          none, front-to-back, back-to-front: by each face's mean d
 * The depth test is lesson 07's (depth_buffer.c), unchanged. */
#ifndef EARLY_Z_H
#define EARLY_Z_H

#include "depth_format.h"
#include "harness/lesson.h"

typedef enum { Z_LATE, Z_EARLY, Z_PREPASS } ZMode;
typedef enum { SORT_NONE, SORT_FRONT_TO_BACK, SORT_BACK_TO_FRONT } SortOrder;

typedef struct { /* the shader is shade_fragment (extras/shader.c) */
    DepthSetup depth; /* first: Target.depth_setup points here, so at the EarlyZ */
    ZMode mode; SortOrder sort;
    bool bug_discard; /* --bug early-z-with-discard: cutouts tested early too */
    int pass;         /* prepass: 1 depth only, 2 shading; else 0 */
    Rgb *colour;      /* the shader's picture (--colour-out) */
    uint32_t *shade_count; /* times each pixel was shaded (--shade-count-out) */
    float *saved_depth; int32_t *saved_face; uint32_t *saved_tests; /* before the face */
    unsigned long long tested, shaded, covered; /* depth tests, shader runs, pixels drawn */
    const Mesh *mesh; const Camera *camera;
    Rasterizer rasterizer; /* lesson 07's, drawing through extras' draw_shaded_face */
} EarlyZ;

bool cutout_keeps(int x, int y); /* the cheap part of a cutout's shader: kept or not */
/* A fragment of face at pixel i (x, y) after lesson 07's test: shaded or not. */
void fragment(EarlyZ *z, Target *t, size_t i, int x, int y, int face, bool cutout, Rgb lit);
bool draw_scene(Run *run, Error *err); /* sorted, in one or two passes */

#endif
