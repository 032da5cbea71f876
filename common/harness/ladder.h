/* ladder.h: the "ladder" scene (lesson 06) and how to score a picture of it.
 *
 * Pairs of parallel plates LADDER_GAP apart in view depth, one pair per
 * distance band (d = 1, 3, 10, 30, 100, 300), facing the camera and tilted a
 * little, so that depth varies across each plate. In each band the back
 * plate (face 2k) is drawn first and the front plate (face 2k + 1) second,
 * on the same rays, the back one a little smaller: a depth buffer that can
 * tell them apart shows only the front plate. Where it cannot, both store
 * the same value, the tie keeps the first drawn, and the back plate shows
 * through. The wrong fraction of a band is back / (back + front) pixels.
 *
 * The camera: eye at the origin looking down -Z, fovy 45, near 0.1, far 1000. */
#ifndef LADDER_H
#define LADDER_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "error.h"
#include "mesh_build.h"

#define LADDER_BANDS 6
#define LADDER_GAP 0.05 /* metres (world units) between front and back plate */

/* The view depth of each band's front plate at its centre. */
extern const double LADDER_DISTANCE[LADDER_BANDS];

bool ladder_build(Mesh *m, Error *err);

typedef struct {
    long front[LADDER_BANDS], back[LADDER_BANDS]; /* pixels won, per band */
} LadderScore;

/* From the face buffer (face index per pixel, NO_FACE = -1 where none). */
void ladder_score_faces(const int32_t *face, size_t n, LadderScore *s);
/* From an --id-out picture (face + 1 as a 24-bit number per pixel): any
 * renderer's picture of the ladder, a GPU's too. False with err set when
 * the file cannot be read. */
bool ladder_score_id_png(const char *path, LadderScore *s, Error *err);
/* back / (back + front) of band k; 0 when the band drew nothing. */
double ladder_wrong_fraction(const LadderScore *s, int k);

#endif
