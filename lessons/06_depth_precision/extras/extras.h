/* extras.h: what lesson 06 shows but does not teach (docs/06_depth_precision.md):
 *   --depth-format F, --depth-mapping M   their words, read into a DepthSetup
 *   --far inf                             with --depth-mapping reversed only
 *   --precision-plot FILE                 the depth step against distance (plot.c)
 *   on the ladder scene                   the wrong fraction per band (ladder.h)
 *   --ladder-out FILE                     its picture, each band's d and a key */
#ifndef EXTRAS_H
#define EXTRAS_H

#include "depth_flags.h"
#include "depth_format.h"
#include "harness/lesson.h"

extern const Extras EXTRAS;

DepthSetup depth_chosen(const Run *run); /* the format, mapping, near and far of the run */

#endif
