/* extras.h: what lesson 08 shows but does not teach (docs/08_early_z.md):
 *   --z-mode, --sort, --bug early-z-with-discard: their words;
 *   --colour-out: the shader's picture; --shade-count-out: the heat map of
 *   how many times each pixel was shaded, with its legend. */
#ifndef EXTRAS_H
#define EXTRAS_H

#include "early_z.h"
#include "heat_map.h"
#include "harness/lesson.h"

extern const Extras EXTRAS;

EarlyZ early_z_chosen(const Run *run); /* unorm24, standard; the mode, sort and bug */
const char *z_mode_name(ZMode mode);
const char *sort_name(SortOrder sort);

/* The fragment shader (shader.c): the face's flat colour lit (Lambert, from
 * its normal), darkened by up to 30% by SHADER_OCTAVES octaves of value noise. */
#define SHADER_OCTAVES 6
Rgb shade_fragment(Rgb lit, int x, int y);

/* order[0 .. nfaces-1]: mesh order, or by the mean view depth d of each face's
 * corners, nearest first (front-to-back) or last (back-to-front). */
void sort_faces(const Render *r, SortOrder sort, int *order);
/* Lesson 07's DEPTH_BIAS_ZBUFFER draws a face, each fragment it made handed to fragment(). */
void draw_shaded_face(Target *t, const ScreenFace *f, const DrawContext *ctx);
bool early_z_begin(EarlyZ *z, Run *run, Error *err); /* the run draws through z */
void early_z_free(EarlyZ *z);


#endif
