/* image.h: a picture in memory: 8-bit RGB, row 0 the top row (as in a PNG:
 * no flip anywhere). Reading and writing files is the harness's
 * (harness/image_io.h). */
#ifndef IMAGE_H
#define IMAGE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "error.h"

/* docs/conventions.md: images are 1 to 16384 pixels on a side. A picture
 * may carry a band of up to IMAGE_MAX_BAND rows under it (its legend,
 * harness/legend.h), so that a picture of the largest size keeps its
 * legend: such an image is that much taller (image_init_with_band). */
#define IMAGE_MAX_SIDE 16384
#define IMAGE_MAX_BAND 64

#define IMAGE_CHANNELS 3 /* r, g, b */

typedef struct { uint8_t r, g, b; } Rgb;

typedef struct {
    int width, height;
    uint8_t *rgb; /* width * height * 3 bytes, row-major, top row first */
} Image;

/* True when width x height is in range; otherwise false, with err set (if not NULL). */
bool image_size_ok(int width, int height, Error *err);
/* A black image. False (with err set) on a bad size or no memory. */
bool image_init(Image *im, int width, int height, Error *err);
/* The same, band rows taller (0 to IMAGE_MAX_BAND): width x (height + band),
 * width and height in range as for image_init. */
bool image_init_with_band(Image *im, int width, int height, int band, Error *err);
void image_free(Image *im);
void image_fill(Image *im, Rgb c);

static inline void image_set(Image *im, int x, int y, Rgb c)
{
    uint8_t *p = im->rgb + ((size_t)y * (size_t)im->width + (size_t)x) * IMAGE_CHANNELS;
    p[0] = c.r; p[1] = c.g; p[2] = c.b;
}

static inline Rgb image_get(const Image *im, int x, int y)
{
    const uint8_t *p = im->rgb + ((size_t)y * (size_t)im->width + (size_t)x) * IMAGE_CHANNELS;
    Rgb c = {p[0], p[1], p[2]};
    return c;
}

#endif
