/* modes.h: lesson 08's words for its flags (modes.c), which extras.c of
 * lessons 08 and 09 reads: the mode, sort and bug flags checked, then the
 * state they choose; the shader's picture, --colour-out. */
#ifndef MODES_H
#define MODES_H

#include "extras.h"

bool early_z_flags_ok(Run *run, const char *mode, const char *sort, const char *bug, Error *err);
LessonState early_z_state(const Run *run, const char *mode, const char *sort, const char *bug);
bool write_colour(const EarlyZ *z, int width, int height, const char *path, Error *err);

#endif
