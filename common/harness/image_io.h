/* image_io.h: the pictures a lesson writes and a test reads.
 *
 *  - PNG write (zlib's deflate) and read (stb_image, any PNG converted to RGB).
 *  - PFM: a float image, grey, little-endian, scale -1.0, rows bottom to top as
 *    the format says. The lessons write view depth d this way (--depth-out).
 *  - PGM: 16-bit binary P5, big-endian as the format says (--overdraw-out).
 *  - depth_to_grey: near bright, far dark (linear in 1/d), background in its own colour.
 *  - image_compare: counts, largest channel difference, bounding box, diff picture.
 *
 * Every writer is atomic (file.h): the bytes go to a temporary file in the same
 * directory, which is renamed over the target only once complete. */
#ifndef IMAGE_IO_H
#define IMAGE_IO_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "error.h"
#include "image.h"

bool image_write_png(const Image *im, const char *path, Error *err);
/* Reads a PNG (only a PNG: the signature is checked) from a regular file. The
 * size in its header is checked before anything is decoded; a truncated or
 * malformed file is refused, the message naming the reason. im is
 * initialised here. */
bool image_read_png(Image *im, const char *path, Error *err);
/* The same, refusing (before decoding) a PNG that is not want_width x
 * want_height: "ref.png is 64x48 but the picture is 800x600". */
bool image_read_png_sized(Image *im, const char *path, int want_width, int want_height,
                          Error *err);
/* The same from bytes in memory; name is for messages. want_width <= 0: any size. */
bool image_decode_png(Image *im, const unsigned char *bytes, size_t len, const char *name,
                      int want_width, int want_height, Error *err);

/* values: width * height floats, top row first in memory (flipped on write). */
bool write_pfm(const float *values, int width, int height, const char *path, Error *err);
/* Reads a grey PFM written by write_pfm (or any grey PFM, either endianness).
 * *values (top row first, like write_pfm's) is allocated here: free() it. */
bool read_pfm(float **values, int *width, int *height, const char *path, Error *err);

/* counts: width * height values, clamped to 65535 on write. */
bool write_pgm16(const uint32_t *counts, int width, int height, const char *path, Error *err);

/* The background colour of depth pictures: it is no grey, so "nothing was
 * drawn here" never looks like "something very far away". */
extern const Rgb DEPTH_BACKGROUND;

/* depth: view depths d, +infinity (or any non-finite value) for background.
 * The finite range [dmin, dmax] of the buffer maps to grey 255 (near) .. 48 (far),
 * linear in 1/d: t = (1/dmin - 1/d) / (1/dmin - 1/dmax), grey = 255 - 207 t,
 * as a perspective camera sees depth (near things get most of the greys).
 * A d <= 0 (no camera draws one) takes the nearest grey. */
void depth_to_grey(const float *depth, Image *out);
/* The same on a range given by the caller (--steps keeps one scale for every
 * frame); a finite d outside [dmin, dmax] takes the grey of the nearer end. */
void depth_to_grey_between(const float *depth, double dmin, double dmax, Image *out);

typedef struct {
    long differing;        /* pixels where any channel differs by more than the tolerance */
    int max_channel_diff;  /* largest |a - b| over all channels and pixels */
    int x0, y0, x1, y1;    /* bounding box of the differing pixels, inclusive; -1 when none */
} ImageDiff;

/* a and b must have the same size (checked: false with err set otherwise).
 * A pixel differs when one of its channels differs by more than channel_tolerance.
 * diff (may be NULL) becomes a picture of the comparison: matching pixels are
 * b dimmed to a quarter, differing pixels magenta. diff is initialised here
 * (free it with image_free); it is left empty when false is returned. */
bool image_compare(const Image *a, const Image *b, int channel_tolerance,
                   ImageDiff *result, Image *diff, Error *err);

#endif
