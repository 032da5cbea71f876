/* extras.h: what lesson 10 shows but does not teach (docs/10_fast_raster.md):
 * the words of its flags: --simd, --threads, and lesson 07's --depth-format,
 * --depth-mapping, --polygon-offset, --offset-clamp. */
#ifndef EXTRAS_H
#define EXTRAS_H

#include "harness/lesson.h"
#include "state.h"

extern const Extras EXTRAS;
/* The run's engine: SIMD, threads, counting, and its depth buffer. */
LessonState fast_chosen(const Run *run);
void print_engine(const Target *t, const LessonState *s); /* how the picture was drawn */

#endif
