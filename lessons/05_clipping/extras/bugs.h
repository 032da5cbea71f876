/* bugs.h: the classic mistake of a renderer without clipping, on purpose (--bug).
 *
 * no-clip  every corner is divided by its w_c, whatever its sign. A corner
 *          behind the eye (w_c < 0) lands on the other side of the screen
 *          centre, mirrored through it, and one just behind the eye (w_c
 *          near 0) lands very far away: a face that reaches behind the eye
 *          is stretched across the screen. (A face wholly behind the near
 *          plane is still dropped by render_faces, as for any rasterizer
 *          that clips; handed over, it would be drawn mirrored, as if it
 *          were in front: the page's exercise 4.) The rasterizer is handed
 *          |w_c| as the depth (its 1/d must be positive to be drawn at all);
 *          a corner exactly at w_c = 0 divides to infinity, and its face is
 *          not drawn. */
#ifndef BUGS_H
#define BUGS_H

#include "harness/render.h"

extern const Rasterizer NO_CLIP_BUG;

#endif
