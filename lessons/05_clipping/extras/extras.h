/* extras.h: what lesson 05 shows but does not teach, and does not hand on to
 * lesson 06 (docs/05_clipping.md, "Reading the code"):
 *
 *   --bug no-clip            divide every corner by its w, w <= 0 too (bugs.c)
 *   --compare-drop FILE      draw with lesson 04's rule (a face with a corner at
 *                            d <= near dropped whole) and with clipping, and
 *                            mark where they differ (common/harness/compare_naive.c) */
#ifndef EXTRAS_H
#define EXTRAS_H

#include "harness/lesson.h"

extern const Extras EXTRAS;

#endif
