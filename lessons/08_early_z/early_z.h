/* early_z.h: lesson 08, early-Z and the depth pre-pass (docs/08_early_z.md).
 *
 *   cutout          a face in group `cutout` discards where cutout_keeps is false
 *   --z-mode late   shade every fragment, then test it
 *            early  test first, shade what passed; a cutout falls back to
 *                   late: its depth must not be written before its discard
 *            prepass pass 1 writes depth only (a cutout runs its cheap discard);
 *                   pass 2, depth writes off, shades where depth is equal
 *   --sort          none, front-to-back, back-to-front: by each face's mean d
 * Each fragment of a span comes to fragment(); the depth test is lesson
 * 06's (depth_buffer.c), unchanged. */
#ifndef EARLY_Z_H
#define EARLY_Z_H

#include "depth_buffer.h"
#include "image.h"

typedef enum { Z_LATE, Z_EARLY, Z_PREPASS } ZMode;
typedef enum { SORT_NONE, SORT_FRONT_TO_BACK, SORT_BACK_TO_FRONT } SortOrder;

typedef struct { /* the shader is shade_fragment (extras/shader.c) */
    ZMode mode; SortOrder sort;
    bool bug_discard; /* --bug early-z-with-discard: cutouts tested early too */
    int pass;         /* prepass: 1 depth only, 2 shading; else 0 */
    Rgb *colour;      /* the shader's picture (--colour-out) */
    uint32_t *shade_count; /* times each pixel was shaded (--shade-count-out) */
    const bool *cutout; const Rgb *lit; /* per face: in `cutout`; its colour, lit */
    unsigned long long tested, shaded, covered; /* depth tests, shader runs, pixels drawn */
} EarlyZ;

bool cutout_keeps(int x, int y); /* the cheap part of a cutout's shader: kept or not */
/* Face f is in `cutout`; none is without the per-face inputs (a depth-only draw). */
static inline bool is_cutout(const EarlyZ *z, int f) { return z->cutout && z->cutout[f]; }

#endif
