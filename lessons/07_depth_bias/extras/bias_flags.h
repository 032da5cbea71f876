/* bias_flags.h: the words of --polygon-offset and --offset-clamp
 * (bias_flags.c), which lessons 07 and 10 take: checked once the command
 * line is read, then the bias they choose for the faces in `decal`. */
#ifndef BIAS_FLAGS_H
#define BIAS_FLAGS_H

#include "depth_bias.h"
#include "harness/lesson.h"

/* offset "FACTOR,UNITS" and clamp (NULL: not given) are numbers. */
bool bias_flags_ok(const char *offset, const char *clamp, Error *err);
DepthBias bias_flags_chosen(const char *offset, const char *clamp, const Mesh *mesh);

#endif
