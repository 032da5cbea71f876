/* magnify: a small picture scaled up so that single pixels can be seen.
 *
 *   magnify IN.png OUT.png SCALE [X0,Y0,X1,Y1 ...]
 *
 * Every pixel becomes a SCALE x SCALE block (nearest neighbour), with a thin
 * grey border and a dot at its centre, the point where it is sampled. Each
 * X0,Y0,X1,Y1 draws the segment between those two points, given in pixels of
 * IN (e.g. 1.5,0.5 is the centre of pixel (1, 0)): the true edges of the
 * triangles, over the pixels the rasterizer chose for them.
 * Exit status: 0 written, 1 could not read or write, 2 bad usage. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness/cli.h"
#include "error.h"
#include "harness/file.h"
#include "harness/image_io.h"

#define PROGRAM "magnify"
#define SCALE_MAX 64
#define OUT_SIDE_MAX 8192
#define MAX_SEGMENTS 32

static const Rgb BORDER = {90, 90, 90};
static const Rgb CENTRE_DOT = {255, 255, 255};
static const Rgb EDGE_LINE = {255, 255, 255};
#define DOT_RADIUS 0.09  /* of a pixel */
#define LINE_HALF_WIDTH 0.6 /* of an output pixel */

static int usage_error(const char *msg)
{
    fprintf(stderr, PROGRAM ": error: %s (usage: " PROGRAM " IN.png OUT.png SCALE "
                    "[X0,Y0,X1,Y1 ...])\n", msg);
    return EXIT_USAGE;
}

/* Distance from point p to segment a-b. */
static double segment_distance(double px, double py, const double s[4])
{
    double dx = s[2] - s[0], dy = s[3] - s[1];
    double len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((px - s[0]) * dx + (py - s[1]) * dy) / len2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    double qx = s[0] + t * dx - px, qy = s[1] + t * dy - py;
    return sqrt(qx * qx + qy * qy);
}

static Rgb magnified_pixel(const Image *in, int scale, int x, int y, double (*seg)[4],
                           int nseg)
{
    int sx = x / scale, sy = y / scale, fx = x % scale, fy = y % scale;
    /* Position of this output pixel's centre, in pixels of the input. */
    double px = (x + 0.5) / scale, py = (y + 0.5) / scale;
    for (int k = 0; k < nseg; k++)
        if (segment_distance(px, py, seg[k]) * scale <= LINE_HALF_WIDTH)
            return EDGE_LINE;
    double cx = px - (sx + 0.5), cy = py - (sy + 0.5);
    if (cx * cx + cy * cy <= DOT_RADIUS * DOT_RADIUS)
        return CENTRE_DOT;
    if (fx == 0 || fy == 0)
        return BORDER;
    return image_get(in, sx, sy);
}

int main(int argc, char **argv)
{
    signals_begin(PROGRAM); /* a signal from now on prints one line */
    if (argc >= 2 && strcmp(argv[1], "--help") == 0) {
        printf("usage: " PROGRAM " IN.png OUT.png SCALE [X0,Y0,X1,Y1 ...]\n"
               "Scales a picture up with pixel borders, centre dots and segments.\n");
        return EXIT_OK;
    }
    if (argc < 4)
        return usage_error("too few arguments");
    Error err;
    long scale;
    if (!parse_int("SCALE", argv[3], 2, SCALE_MAX, &scale, &err))
        return usage_error(err.msg);
    int nseg = argc - 4;
    if (nseg > MAX_SEGMENTS)
        return usage_error("too many segments");
    double seg[MAX_SEGMENTS][4];
    for (int k = 0; k < nseg; k++) {
        char *end;
        const char *p = argv[4 + k];
        for (int c = 0; c < 4; c++) {
            seg[k][c] = strtod(p, &end);
            if (end == p || !isfinite(seg[k][c]) || *end != (c < 3 ? ',' : '\0'))
                return usage_error("a segment is X0,Y0,X1,Y1: four numbers");
            p = end + 1;
        }
    }

    if (same_file(argv[1], argv[2])) /* by any name: the input stays as it was */
        return usage_error("OUT.png names the file IN.png: the picture would replace its input");
    Image in, out;
    if (!image_read_png(&in, argv[1], &err))
        return error_report(PROGRAM, &err, EXIT_RUN_FAILED);
    if (in.width * scale > OUT_SIDE_MAX || in.height * scale > OUT_SIDE_MAX) {
        image_free(&in);
        return usage_error("the magnified picture would be too large");
    }
    if (!image_init(&out, in.width * (int)scale, in.height * (int)scale, &err)) {
        image_free(&in);
        return error_report(PROGRAM, &err, EXIT_RUN_FAILED);
    }
    for (int y = 0; y < out.height; y++)
        for (int x = 0; x < out.width; x++)
            image_set(&out, x, y, magnified_pixel(&in, (int)scale, x, y, seg, nseg));
    bool ok = image_write_png(&out, argv[2], &err);
    image_free(&in);
    image_free(&out);
    return ok ? EXIT_OK : error_report(PROGRAM, &err, EXIT_RUN_FAILED);
}
