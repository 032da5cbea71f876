/* extras.h: what lesson 08 shows but does not teach (docs/08_early_z.md):
 *   --z-mode, --sort, --bug early-z-with-discard: their words;
 *   --colour-out: the shader's picture; --shade-count-out: the heat map of
 *   how many times each pixel was shaded, with its legend. */
#ifndef EXTRAS_H
#define EXTRAS_H

#include "early_z.h"
#include "lesson.h"

extern const Extras EXTRAS;

EarlyZ early_z_chosen(const Run *run); /* unorm24, standard; the mode, sort and bug */
const char *z_mode_name(ZMode mode);
const char *sort_name(SortOrder sort);

#define HEAT_CLASSES 7 /* 0, 1, ..., 5 and 6 or more times shaded */
#define HEAT_LEGEND_HEIGHT 22 /* the band under the picture */
Rgb heat_colour(uint32_t times);
bool write_heat_map(const uint32_t *count, int width, int height, const char *path, Error *err);

#endif
