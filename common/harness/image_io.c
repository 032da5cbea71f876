/* image_io.c: see image_io.h.
 *
 * Every writer builds its bytes into an AtomicFile (file.h), so a failed write
 * never leaves a truncated picture behind. Multi-byte numbers are written one
 * byte at a time in the order the format asks for, so the files are the same
 * on any machine. */
#include "image_io.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <stb_image.h>
#include <stb_image_write.h>

#include "file.h"

const Rgb DEPTH_BACKGROUND = {24, 32, 64}; /* dark blue: no grey looks like it */

/* depth_to_grey: the nearest depth is white, the farthest a dark grey that
 * still stands out from black and from the background; 1/d is linear between. */
#define GREY_NEAR 255
#define GREY_FAR 48

/* PFM: "Pf" is one grey channel; a negative scale means little-endian. */
#define PFM_HEADER_MAX 128
#define PGM16_MAX_VALUE 65535

/* ---- PNG ---- */

/* stb_image_write hands its output over in pieces: append each to the file. */
static void write_to_atomic_file(void *context, void *data, int size)
{
    atomic_write(context, data, (size_t)size);
}

bool image_write_png(const Image *im, const char *path, Error *err)
{
    if (!im->rgb || !image_size_ok(im->width, im->height, NULL))
        return error_set(err, "cannot write %s: the image is empty", path);
    AtomicFile f;
    if (!atomic_open(&f, path, err))
        return false;
    /* Row 0 is the top row in memory and in a PNG: no flip. */
    int row_bytes = im->width * IMAGE_CHANNELS;
    if (!stbi_write_png_to_func(write_to_atomic_file, &f, im->width, im->height,
                                IMAGE_CHANNELS, im->rgb, row_bytes)) {
        atomic_abort(&f);
        return error_set(err, "cannot write %s: out of memory while encoding the PNG", path);
    }
    return atomic_commit(&f, err);
}

/* The eight bytes every PNG file starts with. */
static const unsigned char PNG_SIGNATURE[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
/* A PNG of 16384 x 16384 pixels that does not compress at all is under 1 GiB. */
#define PNG_MAX_BYTES ((size_t)1 << 30)

/* stb_image's reasons are terse ("outofmem", "bad zlib header") and may quote
 * bytes of the file ("\n\x8c PNG chunk not known"): say them in words where
 * they have some, print a byte that is not printable ASCII as '?', and never
 * print "(null)". */
#define REASON_MAX 64
static const char *decode_failure(char out[REASON_MAX])
{
    const char *why = stbi_failure_reason();
    if (!why)
        return "the decoder gave no reason";
    if (strcmp(why, "outofmem") == 0)
        return "out of memory";
    size_t n = 0;
    for (; why[n] && n < REASON_MAX - 1; n++)
        out[n] = why[n] >= 0x20 && why[n] < 0x7f ? why[n] : '?';
    out[n] = '\0';
    return out;
}

bool image_decode_png(Image *im, const unsigned char *bytes, size_t len, const char *name,
                      int want_width, int want_height, Error *err)
{
    im->width = 0;
    im->height = 0;
    im->rgb = NULL;
    if (len < sizeof PNG_SIGNATURE || memcmp(bytes, PNG_SIGNATURE, sizeof PNG_SIGNATURE) != 0)
        return error_set(err, "cannot read %s: not a readable PNG (no PNG signature: not a "
                              "PNG file)", name);
    if (len > INT_MAX)
        return error_set(err, "cannot read %s: it is larger than %d bytes", name, INT_MAX);
    /* The size from the header, before anything is decoded: a small file may
     * claim a huge picture (a decompression bomb). */
    char reason[REASON_MAX];
    int width, height, channels_in_file;
    if (!stbi_info_from_memory(bytes, (int)len, &width, &height, &channels_in_file))
        return error_set(err, "cannot read %s: not a readable PNG (%s)", name,
                         decode_failure(reason));
    if (!image_size_ok(width, height, NULL))
        return error_set(err, "cannot read %s: image size %dx%d is out of range (1 to %d)",
                         name, width, height, IMAGE_MAX_SIDE);
    if (want_width > 0 && (width != want_width || height != want_height))
        return error_set(err, "%s is %dx%d but the picture is %dx%d", name, width, height,
                         want_width, want_height);
    /* Asking for 3 channels converts grey, palette and alpha PNGs to RGB. */
    int w, h;
    unsigned char *pixels = stbi_load_from_memory(bytes, (int)len, &w, &h, &channels_in_file,
                                                  IMAGE_CHANNELS);
    if (!pixels)
        return error_set(err, "cannot read %s: not a readable PNG (%s)", name,
                         decode_failure(reason));
    bool ok = true;
    if (w != width || h != height)
        ok = error_set(err, "cannot read %s: not a readable PNG (its size changed while "
                            "decoding)", name);
    else if (image_init(im, width, height, err))
        memcpy(im->rgb, pixels, (size_t)width * (size_t)height * IMAGE_CHANNELS);
    else
        ok = false;
    stbi_image_free(pixels);
    return ok;
}

bool image_read_png_sized(Image *im, const char *path, int want_width, int want_height,
                          Error *err)
{
    im->width = 0;
    im->height = 0;
    im->rgb = NULL;
    char *data;
    size_t len;
    if (!read_file(path, PNG_MAX_BYTES, &data, &len, err))
        return false;
    bool ok = image_decode_png(im, (const unsigned char *)data, len, path, want_width,
                               want_height, err);
    free(data);
    return ok;
}

bool image_read_png(Image *im, const char *path, Error *err)
{
    return image_read_png_sized(im, path, 0, 0, err);
}

/* ---- PFM ---- */

static void put_float_le(uint8_t *out, float v)
{
    uint32_t bits;
    memcpy(&bits, &v, sizeof bits);
    out[0] = (uint8_t)(bits & 0xff);
    out[1] = (uint8_t)((bits >> 8) & 0xff);
    out[2] = (uint8_t)((bits >> 16) & 0xff);
    out[3] = (uint8_t)(bits >> 24);
}

static float get_float(const uint8_t *in, bool little_endian)
{
    uint32_t bits = little_endian
        ? (uint32_t)in[0] | (uint32_t)in[1] << 8 | (uint32_t)in[2] << 16 | (uint32_t)in[3] << 24
        : (uint32_t)in[3] | (uint32_t)in[2] << 8 | (uint32_t)in[1] << 16 | (uint32_t)in[0] << 24;
    float v;
    memcpy(&v, &bits, sizeof v);
    return v;
}

bool write_pfm(const float *values, int width, int height, const char *path, Error *err)
{
    if (!image_size_ok(width, height, err))
        return false;
    size_t row_bytes = (size_t)width * sizeof(float);
    uint8_t *row = malloc(row_bytes);
    if (!row)
        return error_set(err, "cannot write %s: out of memory", path);
    AtomicFile f;
    if (!atomic_open(&f, path, err)) {
        free(row);
        return false;
    }
    char header[PFM_HEADER_MAX];
    int n = snprintf(header, sizeof header, "Pf\n%d %d\n-1.0\n", width, height);
    atomic_write(&f, header, (size_t)n);
    /* The PFM format stores the bottom row first. */
    for (int y = height - 1; y >= 0; y--) {
        const float *src = values + (size_t)y * (size_t)width;
        for (int x = 0; x < width; x++)
            put_float_le(row + (size_t)x * sizeof(float), src[x]);
        atomic_write(&f, row, row_bytes);
    }
    free(row);
    return atomic_commit(&f, err);
}

static bool is_pnm_space(char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

/* Reads a positive decimal number after optional white space; false if none. */
static bool parse_side(const char **p, const char *end, int *out)
{
    while (*p < end && is_pnm_space(**p))
        (*p)++;
    long v = 0;
    const char *start = *p;
    while (*p < end && **p >= '0' && **p <= '9' && v <= IMAGE_MAX_SIDE) {
        v = v * 10 + (**p - '0');
        (*p)++;
    }
    if (*p == start)
        return false;
    *out = v > IMAGE_MAX_SIDE ? IMAGE_MAX_SIDE + 1 : (int)v;
    return true;
}

bool read_pfm(float **values, int *width, int *height, const char *path, Error *err)
{
    *values = NULL;
    *width = 0;
    *height = 0;
    char *data;
    size_t len;
    size_t max_bytes = PFM_HEADER_MAX +
        (size_t)IMAGE_MAX_SIDE * (size_t)IMAGE_MAX_SIDE * sizeof(float);
    if (!read_file(path, max_bytes, &data, &len, err))
        return false;
    const char *end = data + len;
    const char *p = data;
    int w = 0, h = 0;
    bool ok = true;
    if (len < 2 || data[0] != 'P' || (data[1] != 'f' && data[1] != 'F')) {
        ok = error_set(err, "cannot read %s: not a PFM file (it should start with \"Pf\")", path);
    } else if (data[1] == 'F') {
        ok = error_set(err, "cannot read %s: a colour PFM (\"PF\"); only grey (\"Pf\") is read", path);
    } else {
        p += 2;
        if (!parse_side(&p, end, &w) || !parse_side(&p, end, &h))
            ok = error_set(err, "cannot read %s: bad PFM header (width and height expected)", path);
        else if (!image_size_ok(w, h, NULL))
            ok = error_set(err, "cannot read %s: image size %dx%d is out of range (1 to %d)",
                           path, w, h, IMAGE_MAX_SIDE);
    }
    /* The scale: its sign gives the byte order; its size is ignored (depths
     * are stored as they are). One white-space byte then ends the header. */
    double scale = 0.0;
    if (ok) {
        char *after;
        scale = strtod(p, &after);
        if (after == p || !isfinite(scale) || scale == 0.0 || after >= end ||
            !is_pnm_space(*after))
            ok = error_set(err, "cannot read %s: bad PFM header (scale expected after the size)", path);
        else
            p = after + 1;
    }
    size_t pixels = (size_t)w * (size_t)h;
    if (ok && (size_t)(end - p) != pixels * sizeof(float))
        ok = error_set(err, "cannot read %s: %dx%d floats need %zu bytes of pixels, the file has %zu",
                       path, w, h, pixels * sizeof(float), (size_t)(end - p));
    float *out = NULL;
    if (ok && !(out = malloc(pixels * sizeof(float))))
        ok = error_set(err, "cannot read %s: out of memory", path);
    if (ok) {
        bool little_endian = scale < 0.0;
        const uint8_t *in = (const uint8_t *)p;
        for (int y = h - 1; y >= 0; y--) /* bottom row first in the file */
            for (int x = 0; x < w; x++, in += sizeof(float))
                out[(size_t)y * (size_t)w + (size_t)x] = get_float(in, little_endian);
        *values = out;
        *width = w;
        *height = h;
    }
    free(data);
    return ok;
}

/* ---- PGM ---- */

bool write_pgm16(const uint32_t *counts, int width, int height, const char *path, Error *err)
{
    if (!image_size_ok(width, height, err))
        return false;
    size_t row_bytes = (size_t)width * 2;
    uint8_t *row = malloc(row_bytes);
    if (!row)
        return error_set(err, "cannot write %s: out of memory", path);
    AtomicFile f;
    if (!atomic_open(&f, path, err)) {
        free(row);
        return false;
    }
    char header[PFM_HEADER_MAX];
    int n = snprintf(header, sizeof header, "P5\n%d %d\n%d\n", width, height, PGM16_MAX_VALUE);
    atomic_write(&f, header, (size_t)n);
    /* PGM stores the top row first; 16-bit samples are big-endian. */
    for (int y = 0; y < height; y++) {
        const uint32_t *src = counts + (size_t)y * (size_t)width;
        for (int x = 0; x < width; x++) {
            uint32_t v = src[x] > PGM16_MAX_VALUE ? PGM16_MAX_VALUE : src[x];
            row[2 * (size_t)x] = (uint8_t)(v >> 8);
            row[2 * (size_t)x + 1] = (uint8_t)(v & 0xff);
        }
        atomic_write(&f, row, row_bytes);
    }
    free(row);
    return atomic_commit(&f, err);
}

/* ---- depth pictures ---- */

void depth_to_grey(const float *depth, Image *out)
{
    size_t pixels = (size_t)out->width * (size_t)out->height;
    double dmin = INFINITY, dmax = -INFINITY;
    for (size_t i = 0; i < pixels; i++) {
        if (isfinite(depth[i])) {
            dmin = fmin(dmin, depth[i]);
            dmax = fmax(dmax, depth[i]);
        }
    }
    depth_to_grey_between(depth, dmin, dmax, out);
}

void depth_to_grey_between(const float *depth, double dmin, double dmax, Image *out)
{
    size_t pixels = (size_t)out->width * (size_t)out->height;
    /* grey = 255 + (48 - 255) * t, rounded to nearest, with t linear in 1/d:
     *   t = (1/dmin - 1/d) / (1/dmin - 1/dmax) = (d - dmin) / (dmax - dmin) * dmax / d
     * (the second form divides by neither dmin nor a small difference of
     * reciprocals). A scene that reaches far keeps its near half readable:
     * linear in d, a corridor would be almost all near-white. */
    double range = dmax - dmin;
    for (size_t i = 0; i < pixels; i++) {
        uint8_t *p = out->rgb + i * IMAGE_CHANNELS;
        if (!isfinite(depth[i])) {
            p[0] = DEPTH_BACKGROUND.r;
            p[1] = DEPTH_BACKGROUND.g;
            p[2] = DEPTH_BACKGROUND.b;
            continue;
        }
        double d = depth[i];
        double t = range > 0.0 && d > 0.0 ? (d - dmin) / range * (dmax / d) : 0.0;
        t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t; /* outside a given range: its nearer end */
        uint8_t grey = (uint8_t)lround(GREY_NEAR + (GREY_FAR - GREY_NEAR) * t);
        p[0] = p[1] = p[2] = grey;
    }
}

/* ---- comparison ---- */

static const Rgb DIFF_MARK = {255, 0, 255}; /* magenta: rare in the lessons' pictures */
#define DIFF_DIM 4                           /* matching pixels are shown at 1/4 */

bool image_compare(const Image *a, const Image *b, int channel_tolerance,
                   ImageDiff *result, Image *diff, Error *err)
{
    if (diff) {
        diff->width = 0;
        diff->height = 0;
        diff->rgb = NULL;
    }
    if (a->width != b->width || a->height != b->height)
        return error_set(err, "images differ in size: %dx%d and %dx%d",
                         a->width, a->height, b->width, b->height);
    if (diff && !image_init(diff, b->width, b->height, err))
        return false;

    ImageDiff r = {.differing = 0, .max_channel_diff = 0,
                   .x0 = -1, .y0 = -1, .x1 = -1, .y1 = -1}; /* no box yet */
    for (int y = 0; y < a->height; y++) {
        for (int x = 0; x < a->width; x++) {
            Rgb ca = image_get(a, x, y), cb = image_get(b, x, y);
            int d = abs(ca.r - cb.r);
            d = d > abs(ca.g - cb.g) ? d : abs(ca.g - cb.g);
            d = d > abs(ca.b - cb.b) ? d : abs(ca.b - cb.b);
            if (d > r.max_channel_diff)
                r.max_channel_diff = d;
            bool differs = d > channel_tolerance;
            if (differs) {
                if (r.differing == 0) {
                    r.x0 = r.x1 = x;
                    r.y0 = r.y1 = y;
                }
                r.x0 = x < r.x0 ? x : r.x0;
                r.x1 = x > r.x1 ? x : r.x1;
                r.y1 = y; /* rows are visited top to bottom */
                r.differing++;
            }
            if (diff) {
                Rgb dim = {(uint8_t)(cb.r / DIFF_DIM), (uint8_t)(cb.g / DIFF_DIM),
                           (uint8_t)(cb.b / DIFF_DIM)};
                image_set(diff, x, y, differs ? DIFF_MARK : dim);
            }
        }
    }
    if (result)
        *result = r;
    return true;
}
