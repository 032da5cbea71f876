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
#include <zlib.h>

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

/* A PNG is its signature, then chunks: IHDR (size, 8-bit RGB), IDAT (the
 * rows, each after a filter byte, compressed by zlib's deflate) and IEND.
 * A chunk is its length, its type, its data and the CRC-32 of type and
 * data, numbers big-endian. Each row takes the filter (PNG's five) whose
 * bytes, read as signed, sum smallest in size, the usual heuristic: a
 * smooth row becomes small differences that deflate well. Out of memory,
 * zlib says so (Z_MEM_ERROR) and the picture is not written. */
#define PNG_CHUNK 65536 /* compressed bytes per IDAT chunk */

static void put_u32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)(v >> 24), p[1] = (unsigned char)(v >> 16);
    p[2] = (unsigned char)(v >> 8), p[3] = (unsigned char)v;
}

static void write_chunk(AtomicFile *f, const char *type, const unsigned char *data, size_t n)
{
    unsigned char head[8], crc[4];
    put_u32(head, (uint32_t)n);
    memcpy(head + 4, type, 4);
    uLong sum = crc32(crc32(0L, head + 4, 4), data, (uInt)n);
    put_u32(crc, (uint32_t)sum);
    atomic_write(f, head, sizeof head);
    atomic_write(f, data, n);
    atomic_write(f, crc, sizeof crc);
}

static int paeth(int a, int b, int c) /* the neighbour nearest a + b - c */
{
    int p = a + b - c, pa = abs(p - a), pb = abs(p - b), pc = abs(p - c);
    return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

/* Row `row` (n bytes; `up` the row above, or zeros) filtered by filter k
 * into o (n bytes): each byte less its prediction from a (the byte one
 * pixel left, 0 in the first pixel), b (above) and c (above left). A
 * picture's rows are most of the time spent writing it: one loop per
 * filter, the first pixel apart, in runs of CHUNK bytes, which compilers
 * turn into vector instructions at -O2. */
#define CHUNK 64
#define EACH_BYTE(v) /* o[j] = v, for j from i to n - 1 */                             \
    do {                                                                                \
        for (; i + CHUNK <= n; i += CHUNK)                                              \
            for (size_t c = 0; c < CHUNK; c++) { /* a count the compiler sees */        \
                size_t j = i + c;                                                       \
                o[j] = (uint8_t)(v);                                                    \
            }                                                                           \
        for (size_t j = i; j < n; j++)                                                  \
            o[j] = (uint8_t)(v);                                                        \
    } while (0)

static void filter_with(int k, const uint8_t *row, const uint8_t *up, size_t n,
                        uint8_t *restrict o)
{
    size_t i = n < IMAGE_CHANNELS ? n : IMAGE_CHANNELS, l = IMAGE_CHANNELS;
    for (size_t j = 0; j < i; j++) /* a = c = 0 */
        o[j] = (uint8_t)(row[j] - (k == 0 || k == 1 ? 0 : k == 3 ? up[j] / 2 : up[j]));
    switch (k) { /* a = row[j - l], b = up[j], c = up[j - l] */
    case 0: memcpy(o + i, row + i, n - i); break;
    case 1: EACH_BYTE(row[j] - row[j - l]); break;
    case 2: EACH_BYTE(row[j] - up[j]); break;
    case 3: EACH_BYTE(row[j] - (row[j - l] + up[j]) / 2); break;
    default: EACH_BYTE(row[j] - paeth(row[j - l], up[j], up[j - l]));
    }
}

/* The sum of o's n bytes, each read as signed, in size. */
static unsigned long size_of(const uint8_t *o, size_t n)
{
    unsigned long size = 0;
    size_t i = 0;
    for (; i + CHUNK <= n; i += CHUNK) {
        unsigned run = 0;
        for (size_t c = 0; c < CHUNK; c++)
            run += (unsigned)abs((int8_t)o[i + c]);
        size += run;
    }
    for (; i < n; i++)
        size += (unsigned)abs((int8_t)o[i]);
    return size;
}

/* Row `row` filtered by each filter into out[k] (filter byte first); the
 * index of the smallest. */
static int filter_row(const uint8_t *row, const uint8_t *up, size_t n, uint8_t *out[5])
{
    int best = 0;
    unsigned long best_sum = ULONG_MAX;
    for (int k = 0; k < 5; k++) {
        out[k][0] = (uint8_t)k;
        filter_with(k, row, up, n, out[k] + 1);
        unsigned long sum = size_of(out[k] + 1, n);
        if (sum < best_sum)
            best_sum = sum, best = k;
    }
    return best;
}

/* Deflates what z holds (flush: Z_NO_FLUSH or, last, Z_FINISH) into the
 * chunk buffer, writing it as an IDAT chunk each time it is full and, at
 * Z_FINISH, what is left. The chunks so depend on the deflated stream alone,
 * not on when zlib hands its bytes out. False: zlib ran out of memory. */
static bool deflate_into(AtomicFile *f, z_stream *z, unsigned char *chunk, int flush)
{
    int status;
    do {
        status = deflate(z, flush);
        if (status == Z_STREAM_ERROR || status == Z_MEM_ERROR)
            return false;
        if (z->avail_out == 0 || (flush == Z_FINISH && status == Z_STREAM_END)) {
            if (z->avail_out < PNG_CHUNK)
                write_chunk(f, "IDAT", chunk, PNG_CHUNK - z->avail_out);
            z->next_out = chunk, z->avail_out = PNG_CHUNK;
        }
    } while (z->avail_in > 0 || (flush == Z_FINISH && status != Z_STREAM_END));
    return true;
}

static bool encode_png(AtomicFile *f, const Image *im)
{
    static const unsigned char SIGNATURE[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    unsigned char ihdr[13] = {0};
    put_u32(ihdr, (uint32_t)im->width);
    put_u32(ihdr + 4, (uint32_t)im->height);
    ihdr[8] = 8, ihdr[9] = 2; /* 8 bits, RGB; deflate, adaptive filters, no interlace */
    atomic_write(f, SIGNATURE, sizeof SIGNATURE);
    write_chunk(f, "IHDR", ihdr, sizeof ihdr);

    size_t n = (size_t)im->width * IMAGE_CHANNELS;
    uint8_t *work = malloc(6 * (n + 1) + PNG_CHUNK); /* five filtered rows, zeros, a chunk */
    z_stream z = {0};
    bool ok = work && deflateInit(&z, Z_DEFAULT_COMPRESSION) == Z_OK;
    if (!ok) {
        free(work);
        return false;
    }
    uint8_t *out[5], *zeros = work + 5 * (n + 1), *chunk = zeros + n + 1;
    for (int k = 0; k < 5; k++)
        out[k] = work + (size_t)k * (n + 1);
    memset(zeros, 0, n + 1);
    z.next_out = chunk, z.avail_out = PNG_CHUNK;
    for (int y = 0; ok && y < im->height; y++) {
        const uint8_t *row = im->rgb + (size_t)y * n;
        int k = filter_row(row, y > 0 ? row - n : zeros, n, out);
        z.next_in = out[k], z.avail_in = (uInt)(n + 1);
        ok = deflate_into(f, &z, chunk, Z_NO_FLUSH);
    }
    ok = ok && deflate_into(f, &z, chunk, Z_FINISH);
    deflateEnd(&z);
    free(work);
    static const unsigned char none[1] = {0};
    if (ok)
        write_chunk(f, "IEND", none, 0);
    return ok;
}

bool image_write_png(const Image *im, const char *path, Error *err)
{
    /* A picture with a band under it may be IMAGE_MAX_BAND rows taller. */
    int picture_height = im->height > IMAGE_MAX_SIDE ? im->height - IMAGE_MAX_BAND : im->height;
    if (!im->rgb || !image_size_ok(im->width, picture_height, NULL))
        return error_set(err, "cannot write %s: the image is empty", path);
    AtomicFile f;
    if (!atomic_open(&f, path, err))
        return false;
    /* Row 0 is the top row in memory and in a PNG: no flip. */
    if (!encode_png(&f, im)) {
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
