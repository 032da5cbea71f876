/* extras.h: what lesson 03 shows but does not teach, and does not hand on to
 * lesson 04 (docs/03_perspective_z.md, its start):
 *
 *   --depth-interp naive     draw with lesson 02's rule, d linear (naive.c)
 *   --compare-naive FILE     draw with both rules, mark where they differ
 *                            (common/harness/compare_naive.c)
 *   --bug negated-w          store -d where d belongs (bugs.c) */
#ifndef EXTRAS_H
#define EXTRAS_H

#include "harness/lesson.h"

extern const Extras EXTRAS;

#endif
