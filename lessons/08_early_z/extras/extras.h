/* extras.h: what lesson 08 shows but does not teach (docs/08_early_z.md):
 *   --z-mode, --sort, --bug early-z-with-discard: their words;
 *   --colour-out: the shader's picture; --shade-count-out: the heat map of
 *   how many times each pixel was shaded, with its legend. */
#ifndef EXTRAS_H
#define EXTRAS_H

#include "early_z.h"
#include "state.h"
#include "heat_map.h"
#include "shader.h"
#include "harness/lesson.h"

extern const Extras EXTRAS;

LessonState early_z_chosen(const Run *run); /* unorm24, standard; the mode, sort and bug */
const char *z_mode_name(ZMode mode);
const char *sort_name(SortOrder sort);


/* order[0 .. nfaces-1]: mesh order, or by the mean view depth d of each face's
 * corners, nearest first (front-to-back) or last (back-to-front). */
void sort_faces(const Render *r, SortOrder sort, int *order);
bool early_z_begin(LessonState *state, Run *run, Error *err); /* the run draws through it */
bool draw_scene(Run *run, Error *err); /* sorted, in one or two passes */
void early_z_free(EarlyZ *z);


#endif
