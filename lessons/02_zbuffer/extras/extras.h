/* extras.h: what lesson 02 shows but does not teach, and does not hand on to
 * lesson 03 (docs/02_zbuffer.md, "Reading the code"):
 *
 *   --painter                draw back to front by mean depth, no depth buffer (painter.c)
 *   --bug separate-buffers   one depth buffer per object (bugs.c)
 *   --bug clear-zero         the buffer cleared to 0, so nothing passes (bugs.c) */
#ifndef EXTRAS_H
#define EXTRAS_H

#include "harness/lesson.h"

extern const Extras EXTRAS;

#endif
