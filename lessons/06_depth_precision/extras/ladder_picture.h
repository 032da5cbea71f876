/* ladder_picture.h: --ladder-out, the ladder (harness/ladder.h) as --shade
 * flat draws it, labelled: each band's d beside its plates (above the top
 * row, below the bottom one), and a key in a band under the picture: the
 * colour of the back plate winning, the failure, and of the front plate. */
#ifndef LADDER_PICTURE_H
#define LADDER_PICTURE_H

#include "harness/render.h"

bool write_ladder_picture(const Render *r, const Target *t, const Rasterizer *rz,
                          const char *path, Error *err);

#endif
