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
 *   id     for people: face i takes ID_PALETTE[i % 17], 17 colours far
 *          apart (CIELAB distance >= 39 between any two, >= 59 between
 *          consecutive ones, all far from black) in an order where consecutive
 *          faces differ most; 17 is prime, so a grid of faces whose rows are
 *          2^k long does not line up equal colours. Background black.
 *          Colours repeat every 17 faces: tools read exact faces from
 *          --id-out (face_id_image) instead.
 *   depth  depth_to_grey (image.h) of the view depth d: the nearest drawn
 *          depth white, the farthest dark grey, linear in 1/d between them;
 *          background DEPTH_BACKGROUND. */
#ifndef SHADE_H
#define SHADE_H

#include <stdint.h>

#include "camera.h"
#include "error.h"
#include "image_io.h"
#include "mesh_build.h"

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
/* --shade id's colour of a face: ID_PALETTE[face % ID_PALETTE_SIZE]. */
#define ID_PALETTE_SIZE 17
Rgb face_shade_id_colour(int face);
/* face + 1 in 24 bits, big-endian: face 0 is (0, 0, 1), face 256 is (0, 1, 1).
 * The colours of --id-out (docs/conventions.md). */
Rgb face_id_colour(int face);
/* The inverse: the face index a pixel of an id picture shows, NO_FACE for black. */
int32_t id_colour_face(Rgb c);
/* The most faces an id picture can tell apart: face 16777214 is white,
 * face 16777215 would wrap to black, the background. */
#define FACE_ID_MAX_FACES 0xFFFFFF
/* True when every face of a mesh of nfaces faces has its own id colour;
 * false, err set, otherwise (--id-out refuses such a mesh before drawing). */
bool face_ids_fit(int nfaces, Error *err);

/* out (initialised here) gets one colour per pixel of face[] (width x height):
 * flat or id colours. For SHADE_DEPTH pass the view depth in view_depth
 * (ignored otherwise; may be NULL then). */
bool shade_image(const Mesh *m, const Camera *camera, const int32_t *face,
                 const float *view_depth, int width, int height, ShadeMode mode,
                 Image *out, Error *err);

/* The --id-out picture: face_id_colour of each pixel of face[], black where
 * NO_FACE. out is initialised here. */
bool face_id_image(const int32_t *face, int width, int height, Image *out, Error *err);

#endif
