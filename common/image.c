/* image.c: see image.h. */
#include "image.h"

#include <stdlib.h>

bool image_size_ok(int width, int height, Error *err)
{
    if (width >= 1 && width <= IMAGE_MAX_SIDE && height >= 1 && height <= IMAGE_MAX_SIDE)
        return true;
    if (err)
        error_set(err, "image size %dx%d is out of range (1 to %d)", width, height, IMAGE_MAX_SIDE);
    return false;
}

bool image_init_with_band(Image *im, int width, int height, int band, Error *err)
{
    im->width = 0;
    im->height = 0;
    im->rgb = NULL;
    if (!image_size_ok(width, height, err))
        return false;
    if (band < 0 || band > IMAGE_MAX_BAND)
        return error_set(err, "a band of %d rows under a picture is out of range (0 to %d)",
                         band, IMAGE_MAX_BAND);
    /* At most 16384 * (16384 + 64) pixels: the count fits a size_t, and
     * calloc checks the multiplication by 3 itself. */
    size_t pixels = (size_t)width * (size_t)(height + band);
    im->rgb = calloc(pixels, IMAGE_CHANNELS);
    if (!im->rgb)
        return error_set(err, "out of memory for a %dx%d image", width, height + band);
    im->width = width;
    im->height = height + band;
    return true;
}

bool image_init(Image *im, int width, int height, Error *err)
{
    return image_init_with_band(im, width, height, 0, err);
}

void image_free(Image *im)
{
    free(im->rgb);
    im->rgb = NULL;
    im->width = 0;
    im->height = 0;
}

void image_fill(Image *im, Rgb c)
{
    for (int y = 0; y < im->height; y++)
        for (int x = 0; x < im->width; x++)
            image_set(im, x, y, c);
}
