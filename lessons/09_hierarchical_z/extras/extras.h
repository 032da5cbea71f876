/* extras.h: what lesson 09 shows but does not teach (docs/09_hierarchical_z.md):
 *   --tile, --hiz-update, --hiz-out (the tile buffer as a picture), --skip-out
 *   (where the tiles skipped triangles, written by the default run too), and
 *   lesson 08's flags, shader, heat map and plumbing (fragments.c). */
#ifndef EXTRAS_H
#define EXTRAS_H

#include "early_z.h"
#include "heat_map.h"
#include "shader.h"
#include "hierarchical_z.h"
#include "state.h"
#include "harness/lesson.h"

extern const Extras EXTRAS;

LessonState early_z_chosen(const Run *run); /* unorm24, standard; the mode, sort and bug */
int tile_chosen(const Run *run);   /* --tile, 8 when not given */
bool exact_chosen(const Run *run); /* --hiz-update exact */
const char *z_mode_name(ZMode mode);
const char *sort_name(SortOrder sort);


/* order[0 .. nfaces-1]: mesh order, or by the mean view depth d of each face's
 * corners, nearest first (front-to-back) or last (back-to-front). */
void sort_faces(const Render *r, SortOrder sort, int *order);
bool early_z_begin(LessonState *state, Run *run, Error *err); /* the run draws through it */
bool draw_scene(Run *run, Error *err); /* sorted, in one or two passes */
void early_z_free(EarlyZ *z);


#define HIZ_LEGEND_HEIGHT 22 /* --hiz-out, each tile in the grey of its farthest d */
bool write_hiz_picture(const Target *t, const LessonState *s, const char *path, Error *err);
/* --skip-out: the picture (flat colours), each tile tinted by the triangles it skipped. */
bool write_skip_picture(const Render *r, const Target *t, const LessonState *s, const char *path,
                        Error *err);

#endif
