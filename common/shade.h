/* shade.h: the colour of each pixel, resolved after drawing from the face
 * that won it (target.h: the rasterizer writes no colour).
 *
 *   flat   base colour of the face times a Lambert term:
 *            colour = base * (SHADE_AMBIENT + SHADE_DIFFUSE * |n . l|)
 *          n: the face's normal in view space (Newell's, polygon_normal),
 *          l: a fixed light in view space, above, left of and behind the
 *          viewer. |n . l| because both windings are drawn: a face lit from
 *          behind is as bright as from the front. Base colour: the face's
 *          material Kd, else a fixed palette indexed by face. Background: a
 *          dark grey-blue, so that a black face still shows.
 *   id     face + 1 as a 24-bit big-endian number (R is the high byte);
 *          background black (docs/conventions.md).
 *   depth  depth_to_grey (image.h) of the view depth d. */
#ifndef SHADE_H
#define SHADE_H

#include <stdint.h>

#include "camera.h"
#include "error.h"
#include "image.h"
#include "mesh.h"

/* What a pixel's colour shows (--shade flat|id|depth): the three modes above. */
typedef enum { SHADE_FLAT, SHADE_ID, SHADE_DEPTH } ShadeMode;

#define SHADE_AMBIENT 0.25
#define SHADE_DIFFUSE 0.75

extern const Rgb FLAT_BACKGROUND; /* (24, 28, 40) */
extern const Rgb ID_BACKGROUND;   /* black: no face */

/* The face's colour before lighting: material Kd, else palette[face % size]. */
Rgb face_base_colour(const Mesh *m, int face);
/* The face's flat-shaded colour as seen by camera. */
Rgb face_flat_colour(const Mesh *m, const Camera *camera, int face);
/* face + 1 in 24 bits, big-endian: face 0 is (0, 0, 1), face 256 is (0, 1, 1). */
Rgb face_id_colour(int face);
/* The inverse: the face index a pixel of an id picture shows, NO_FACE for black. */
int32_t id_colour_face(Rgb c);

/* out (initialised here) gets one colour per pixel of face[] (width x height):
 * flat or id colours. For SHADE_DEPTH pass the view depth in view_depth
 * (ignored otherwise; may be NULL then). */
bool shade_image(const Mesh *m, const Camera *camera, const int32_t *face,
                 const float *view_depth, int width, int height, ShadeMode mode,
                 Image *out, Error *err);

#endif
