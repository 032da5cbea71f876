/* heat_map.h: --shade-count-out, how many times each pixel was shaded, as a
 * picture with its legend (lesson 08's extras; lesson 09 inherits them). */
#ifndef HEAT_MAP_H
#define HEAT_MAP_H

#include <stdint.h>

#include "harness/image_io.h"

#define HEAT_CLASSES 7        /* 0, 1, ..., 5 and 6 or more times shaded */
#define HEAT_LEGEND_HEIGHT 22 /* the band under the picture */

Rgb heat_colour(uint32_t times);
/* The picture, then a band: "shaded:" and one swatch and number per class;
 * wider than width when the legend needs it (harness/legend.h). */
bool write_heat_map(const uint32_t *count, int width, int height, const char *path, Error *err);

#endif
