/* bugs.h: a classic z-buffer mistake, reproduced on purpose (--bug).
 *
 * negated-w  every corner hands the rasterizer -d where d belongs: the view
 *            space z, which is -d because the camera looks down -Z, or a
 *            clip-space w negated by a sign slip. The buffer then holds -d,
 *            cleared to +infinity and kept when smaller, so the *farthest*
 *            surface wins every pixel: far surfaces cover near ones. (With
 *            every value negative, the far plane discards nothing either.) */
#ifndef BUGS_H
#define BUGS_H

#include "harness/render.h"

/* Draws like ZBUFFER with every corner's d negated; the buffer holds -d, and
 * --depth-out turns it back into d, the depth of the face that is shown. */
extern const Rasterizer NEGATED_W_BUG;

#endif
