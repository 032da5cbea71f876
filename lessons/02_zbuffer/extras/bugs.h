/* bugs.h: two classic z-buffer mistakes, reproduced on purpose (--bug).
 *
 * separate-buffers  every object gets a depth buffer of its own. An object
 *                   then only hides itself: the last object drawn covers
 *                   every object drawn before it, near or far. An object is
 *                   a set of faces joined by shared vertices (a cube, one
 *                   polygon of interpenetrate); objects are drawn in the order
 *                   of their first face.
 * clear-zero        the buffer is cleared to 0 instead of +infinity. Every
 *                   fragment has d > 0, so d < 0 never holds: nothing is drawn. */
#ifndef BUGS_H
#define BUGS_H

#include "harness/render.h"

/* --bug clear-zero: the lesson's draw_face, with the buffer cleared to 0. */
extern const Rasterizer CLEAR_ZERO_BUG;

/* object_of_face[i]: which object face i belongs to, numbered 0, 1, ... in
 * the order of each object's first face. Returns the number of objects, or
 * -1 when out of memory. */
int find_objects(const Mesh *m, int *object_of_face);

/* Draws order[0 .. n-1]; each run of entries with the same group[] value is
 * drawn into a fresh depth buffer of its own, as if the others did not exist.
 * Afterwards t->depth holds, per pixel, the depth of the face shown there. */
bool draw_in_own_buffers(Render *r, Target *t, const Rasterizer *rz, const int *order,
                         const int *group, int n, Error *err);

/* --bug separate-buffers: each object in a depth buffer of its own. */
bool draw_separate_buffers(Render *r, Target *t, const Rasterizer *rz, Error *err);

#endif
