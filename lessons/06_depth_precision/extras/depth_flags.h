/* depth_flags.h: the words of --depth-format and --depth-mapping
 * (depth_flags.c), which lessons 06, 07 and 10 take: checked once the
 * command line is read, then the buffer's setup they choose. */
#ifndef DEPTH_FLAGS_H
#define DEPTH_FLAGS_H

#include "depth_format.h"
#include "harness/lesson.h"

const char *format_name(DepthFormat format);
const char *mapping_name(DepthMapping mapping);
/* format and mapping (NULL: not given) are names; --far inf needs reversed;
 * log only where log_ok (lesson 06: lessons 07-10 need the plane of z_w).
 * False, err set: a usage error. Reversed: the run's rule says larger is nearer. */
bool depth_flags_ok(Run *run, const char *format, const char *mapping, bool log_ok, Error *err);
DepthSetup depth_flags_setup(const Run *run, const char *format, const char *mapping);

#endif
