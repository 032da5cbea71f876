/* extras.h: what lesson 07 shows but does not teach (docs/07_depth_bias.md):
 *
 *   --depth-format F, --depth-mapping M   lesson 06's words, read into a DepthSetup
 *   --polygon-offset FACTOR,UNITS         and --offset-clamp C: read into its bias
 *   every decal's share of its pixels     after the picture: each face in `decal`,
 *                                         the pixels it wins of those it should win */
#ifndef EXTRAS_H
#define EXTRAS_H

#include "depth_format.h"
#include "lesson.h"

extern const Extras EXTRAS;

DepthSetup depth_chosen(const Run *run); /* format, mapping, near, far and bias of the run */
const char *format_name(DepthFormat format);
const char *mapping_name(DepthMapping mapping);

#endif
