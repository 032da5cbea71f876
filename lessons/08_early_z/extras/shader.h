/* shader.h: lesson 08's fragment shader (shader.c), shown but not taught:
 * the face's flat colour lit (Lambert, from its normal), darkened by up to
 * 30% by SHADER_OCTAVES octaves of value noise at the pixel. */
#ifndef SHADER_H
#define SHADER_H

#include "image.h"

#define SHADER_OCTAVES 6
Rgb shade_fragment(Rgb lit, int x, int y);

#endif
