/* early_z.h: lesson 08, early-Z and the depth pre-pass (docs/08_early_z.md).
 *
 *   fragment shader   the face's Lambert colour (from its normal) times a
 *                     procedural pattern of SHADER_OCTAVES octaves of value
 *                     noise at the pixel: a real cost per fragment
 *   cutout            a face in group `cutout` discards the fragments where
 *                     cutout_keeps says no (holes in a fence, in leaves)
 *   --z-mode late     shade every fragment, then test it (and write)
 *            early    test first, shade only the fragments that pass;
 *                     a cutout face falls back to late: its discard is only
 *                     known once shaded, and its depth must not be written
 *                     before that
 *            prepass  pass 1 writes depth only (a cutout runs its cheap
 *                     discard test there); pass 2 draws again with an equal
 *                     test and shades what is equal: each covered pixel once
 *   --sort            the faces in mesh order, or by the view depth of their
 *                     centre (the mean d of their corners) front to back or
 *                     back to front
 * The depth test itself is lesson 07's (depth_buffer.c), unchanged. */
#ifndef EARLY_Z_H
#define EARLY_Z_H

#include <stdbool.h>
#include <stdint.h>

#include "depth_format.h"
#include "lesson.h"

#define SHADER_OCTAVES 6 /* the pattern's cost: one noise lookup per octave */

typedef enum { Z_LATE, Z_EARLY, Z_PREPASS } ZMode;
typedef enum { SORT_NONE, SORT_FRONT_TO_BACK, SORT_BACK_TO_FRONT } SortOrder;

typedef struct {
    uint64_t tested, shaded, covered; /* depth tests, shader runs, pixels drawn */
} ShadeCounts;

typedef struct {
    DepthSetup depth;  /* first: Target.depth_setup points here, and so at this */
    ZMode mode;
    SortOrder sort;
    bool bug_discard;  /* --bug early-z-with-discard: cutouts tested early too */
    int pass;          /* prepass: 1 depth only, 2 shading; else 0 */
    const Mesh *mesh;
    const Camera *camera;
    Rgb *colour;           /* the shader's picture (--colour-out) */
    uint32_t *shade_count; /* times each pixel was shaded (--shade-count-out) */
    float *saved_depth;    /* a face's box of the buffers, before it is drawn */
    int32_t *saved_face;
    uint32_t *saved_tests;
    ShadeCounts counts;
    Rasterizer rasterizer; /* lesson 07's, with draw_shaded_face */
} EarlyZ;

/* The steps, in the order early_z.c takes them. */
bool cutout_keeps(int x, int y);                 /* the cheap part: discard or not */
Rgb shade_fragment(Rgb lit, int x, int y);       /* the costly part: the colour */
void sort_faces(const Render *r, SortOrder sort, int *order); /* order[0 .. nfaces-1] */
void draw_shaded_face(Target *t, const ScreenFace *f, const DrawContext *ctx);
bool draw_scene(Run *run, Error *err);           /* sorted, in one or two passes */

bool early_z_begin(EarlyZ *z, Run *run, Error *err); /* the run draws through z */
void early_z_free(EarlyZ *z);

#endif
