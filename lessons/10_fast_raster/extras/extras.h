/* extras.h: what lesson 10 shows but does not teach (docs/10_fast_raster.md):
 * the words of its flags: --simd, --threads, and lesson 07's --depth-format,
 * --depth-mapping, --polygon-offset, --offset-clamp. */
#ifndef EXTRAS_H
#define EXTRAS_H

#include "bias_flags.h"
#include "depth_flags.h"
#include "fast_raster.h"
#include "hierarchical_z.h"
#include "harness/lesson.h"
#include "state.h"

extern const Extras EXTRAS;

/* The run's engine: SIMD, threads, counting, and its depth buffer. */
LessonState fast_chosen(const Run *run);
const char *simd_name(Simd simd);
void print_engine(const Target *t, const LessonState *s); /* how the picture was drawn */

#endif
