/* modes.h: lesson 08's words for its flags (modes.c), which extras.c of
 * lessons 08 and 09 reads: the mode, sort and bug flags checked, then the
 * state they choose; the shader's picture, --colour-out. */
#ifndef MODES_H
#define MODES_H

#include "extras.h"

/* Lesson 08's flags, as the entries of a table of flags indexed by a lesson's
 * FLAG_Z_MODE, FLAG_SORT, FLAG_BUG, FLAG_COLOUR_OUT and FLAG_HEAT_OUT. */
#define EARLY_Z_FLAGS                                                                          \
    [FLAG_Z_MODE] = {"--z-mode", "M", "late (shade, then test), early (the default: test, "    \
                                      "then shade what passed) or prepass (depth first, then " \
                                      "shade where equal)"},                                   \
    [FLAG_SORT] = {"--sort", "S", "none (mesh order, the default), front-to-back or "          \
                                  "back-to-front, by the view depth of each face's centre"},   \
    [FLAG_BUG] = {"--bug", "NAME", "make a classic mistake: early-z-with-discard"},            \
    [FLAG_COLOUR_OUT] = {"--colour-out", "FILE.png", "the picture the fragment shader wrote", \
                         .output = true},                                                      \
    [FLAG_HEAT_OUT] = {"--shade-count-out", "FILE.png",                                        \
                       "heat map of how many times each pixel was shaded, with a legend",      \
                       .output = true}

bool early_z_flags_ok(Run *run, const char *mode, const char *sort, const char *bug, Error *err);
LessonState early_z_state(const Run *run, const char *mode, const char *sort, const char *bug);
bool write_colour(const EarlyZ *z, int width, int height, const char *path, Error *err);

#endif
