/* extras.h: what lesson 07 shows but does not teach (docs/07_depth_bias.md):
 *   --depth-format, --depth-mapping, --polygon-offset, --offset-clamp: their
 *   words; and after the picture, each decal's share of its pixels. */
#ifndef EXTRAS_H
#define EXTRAS_H

#include "bias_flags.h"
#include "depth_flags.h"
#include "harness/lesson.h"
#include "state.h"

extern const Extras EXTRAS;

LessonState depth_chosen(const Run *run); /* format, mapping, near, far and bias of the run */

#endif
