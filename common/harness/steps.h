/* steps.h: --steps DIR, frames of the buffer filling in.
 *
 * Step 0 is the cleared buffer; step K is the state after the K-th face (or
 * segment) was drawn. Each step is two pictures in DIR, numbered with four
 * digits so that they sort in drawing order:
 *
 *     DIR/step_0000.png  DIR/step_0000_depth.png     cleared
 *     DIR/step_0001.png  DIR/step_0001_depth.png     after the first face
 *     ...
 *
 * step_K.png is the picture as --out would show it at that moment;
 * step_K_depth.png is the depth buffer as grey, near bright and far dark, on a
 * scale fixed for the whole run (so that a face keeps its grey from frame to
 * frame); in lesson 01 it is the y-buffer strip.
 *
 * Every step is two files: a mesh of more than STEPS_MAX_FACES faces is
 * refused, rather than filling a directory with hundreds of thousands. */
#ifndef STEPS_H
#define STEPS_H

#include <stdbool.h>

#include "error.h"
#include "image_io.h"

#define STEPS_MAX_FACES 2000

/* Writes DIR/step_NNNN.png and DIR/step_NNNN_depth.png, creating DIR first if
 * it is missing. */
bool steps_write(const char *dir, int step, const Image *picture, const Image *depth, Error *err);

#endif
