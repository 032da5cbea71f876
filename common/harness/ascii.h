/* ascii.h: --ascii, the depth buffer printed as characters, one per pixel, as
 * the z-buffer texts of the 1990s drew it:
 *
 *     depth buffer 8x3, digit = d itself (all values are whole numbers 0-9); '.' = empty
 *     ...55...
 *     ..5555..
 *     .555555.
 *
 * The first line is the legend; then one line per row of pixels, top row first.
 *   - When every stored value is a whole number from 0 to 9, each pixel shows
 *     its value itself, as above.
 *   - Otherwise the range of stored values is cut into ten equal steps, and a
 *     pixel shows the step its value falls in: 0 = nearest, 9 = farthest, by
 *     the lesson's rule (depth_rule.h), so lesson 04's stored 1/d prints its
 *     largest value as 0. The legend gives both ends of the range:
 *         depth buffer 40x20, stored d in ten steps: 0 = nearest (d=4.25) ..
 *         9 = farthest (d=7.5); '.' = empty          (one line)
 *     step = floor(10 * (v - nearest) / (farthest - nearest)), 10 counted as 9.
 *   - '.' is a pixel nothing was drawn into.
 * Text this size is read by eye: buffers wider than ASCII_MAX_WIDTH or taller
 * than ASCII_MAX_HEIGHT are refused when the command line is read (cli.c). */
#ifndef ASCII_H
#define ASCII_H

#include <stdio.h>

#include "depth_rule.h"

#define ASCII_MAX_WIDTH 120
#define ASCII_MAX_HEIGHT 60
#define ASCII_EMPTY '.'

/* values: width * height stored values, top row first; NAN where nothing was
 * drawn. Lesson 01 prints its one row with height 1. */
void ascii_print(FILE *out, const float *values, int width, int height, const DepthRule *rule);

#endif
