/* extras.h: what lesson 09 shows but does not teach (docs/09_hierarchical_z.md):
 *   --tile, --hiz-update, --hiz-out (the tile buffer as a picture), and
 *   lesson 08's flags, shader, heat map and plumbing (fragments.c). */
#ifndef EXTRAS_H
#define EXTRAS_H

#include "early_z.h"
#include "heat_map.h"
#include "hierarchical_z.h"
#include "harness/lesson.h"

extern const Extras EXTRAS;

EarlyZ early_z_chosen(const Run *run); /* unorm24, standard; the mode, sort and bug */
int tile_chosen(const Run *run);   /* --tile, 8 when not given */
bool exact_chosen(const Run *run); /* --hiz-update exact */
const char *z_mode_name(ZMode mode);
const char *sort_name(SortOrder sort);

/* The fragment shader (shader.c): the face's flat colour lit (Lambert, from
 * its normal), darkened by up to 30% by SHADER_OCTAVES octaves of value noise. */
#define SHADER_OCTAVES 6
Rgb shade_fragment(Rgb lit, int x, int y);

/* order[0 .. nfaces-1]: mesh order, or by the mean view depth d of each face's
 * corners, nearest first (front-to-back) or last (back-to-front). */
void sort_faces(const Render *r, SortOrder sort, int *order);
/* HIERARCHICAL_ZBUFFER draws a face, each fragment it tested handed to fragment(). */
void draw_shaded_face(Target *t, const ScreenFace *f, const DrawContext *ctx);
bool early_z_begin(EarlyZ *z, Run *run, Error *err); /* the run draws through z */
void early_z_free(EarlyZ *z);


#define HIZ_LEGEND_HEIGHT 22 /* --hiz-out, each tile in the grey of its farthest d */
bool write_hiz_picture(const Target *t, const char *path, Error *err);

#endif
