/* hiz_picture.c: --hiz-out, the tile buffer as a picture (extras.h). Every
 * pixel of a tile shows the tile's farthest value as a view depth d, in the
 * greys of --shade depth (near bright, linear in 1/d); a tile whose value
 * is still the far plane (a pixel not drawn, or a bound never brought
 * nearer) shows the depth pictures' background. The
 * last column and row of each tile are darker, so the tiles show. Under
 * the picture, a legend: the ramp from the nearest d to the farthest. */
#include "extras.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "harness/font.h"
#include "harness/legend.h"

static Rgb darker(Rgb c)
{
    return (Rgb){(uint8_t)(c.r * 3 / 4), (uint8_t)(c.g * 3 / 4), (uint8_t)(c.b * 3 / 4)};
}

/* Pixel (x, y) is in the last column or row of its tile: drawn darker, so
 * that the tiles show (not when they are 1 or 2 pixels). */
static bool tile_edge(const HierarchicalZ *h, int x, int y)
{
    return h->tile > 2 && (x % h->tile == h->tile - 1 || y % h->tile == h->tile - 1);
}

/* picture (freed here) with its legend under it, written to path. */
static bool write_with_legend(Image *picture, void (*draw)(LegendBand *b, const void *ctx),
                              const void *ctx, const char *path, Error *err)
{
    Image im;
    bool ok = image_with_legend(&im, picture, HIZ_LEGEND_HEIGHT, draw, ctx, err);
    image_free(picture);
    if (!ok)
        return false;
    ok = render_make_parent_dirs(path, err) && image_write_png(&im, path, err);
    image_free(&im);
    return ok;
}

/* The legend band: "tile's farthest d:", a ramp labelled at both ends, then
 * a swatch of the background, "far plane". ctx: the range, {dmin, dmax}. */
static void draw_legend(LegendBand *b, const void *ctx)
{
    const double *range = ctx, dmin = range[0], dmax = range[1];
    Rgb white = {255, 255, 255}, ramp[100];
    char text[64];
    legend_text(b, "tile's farthest d:", white);
    legend_gap(b, 6);
    snprintf(text, sizeof text, "%.3g", dmin);
    legend_text(b, text, white);
    legend_gap(b, 4);
    float d[100];
    Image strip = {.width = 100, .height = 1, .rgb = NULL};
    Error err;
    bool ok = image_init(&strip, 100, 1, &err);
    for (int k = 0; ok && k < 100; k++) /* 100 steps even in 1/d, as the greys go */
        d[k] = (float)(1.0 / (1.0 / dmin + (1.0 / dmax - 1.0 / dmin) * k / 99.0));
    if (ok)
        depth_to_grey_between(d, dmin, dmax, &strip);
    for (int k = 0; k < 100; k++)
        ramp[k] = ok ? image_get(&strip, k, 0) : DEPTH_BACKGROUND;
    image_free(&strip);
    legend_ramp(b, ramp, 100, FONT_GLYPH_HEIGHT + 4);
    legend_gap(b, 4);
    snprintf(text, sizeof text, "%.3g", dmax);
    legend_text(b, text, white);
    legend_gap(b, 12);
    legend_swatch(b, DEPTH_BACKGROUND, 10, FONT_GLYPH_HEIGHT + 4, false);
    legend_gap(b, 4);
    legend_text(b, "far plane (a pixel not drawn)", white);
}

bool write_hiz_picture(const Target *t, const LessonState *s, const char *path, Error *err)
{
    const HierarchicalZ *h = s->hiz;
    int w = t->width, hgt = t->height;
    float *d = malloc((size_t)w * (size_t)hgt * sizeof *d);
    Image tiles;
    if (!d)
        return error_set(err, "out of memory for the tile picture");
    double dmin = INFINITY, dmax = 0;
    for (int y = 0; y < hgt; y++)
        for (int x = 0; x < w; x++) {
            int k = y / h->tile * h->tiles_x + x / h->tile;
            d[(size_t)y * (size_t)w + (size_t)x] = (float)stored_to_depth(s, h->far[k]);
        }
    for (size_t i = 0; i < (size_t)w * (size_t)hgt; i++)
        if (isfinite(d[i]))
            dmin = fmin(dmin, d[i]), dmax = fmax(dmax, d[i]);
    if (!isfinite(dmin))
        dmin = dmax = 1;
    bool ok = image_init(&tiles, w, hgt, err);
    if (ok)
        depth_to_grey_between(d, dmin, dmax, &tiles);
    free(d);
    if (!ok)
        return false;
    for (int y = 0; y < hgt; y++)
        for (int x = 0; x < w; x++) {
            Rgb c = image_get(&tiles, x, y);
            bool edge = tile_edge(h, x, y);
            image_set(&tiles, x, y, edge ? darker(c) : c);
        }
    double range[2] = {dmin, dmax};
    return write_with_legend(&tiles, draw_legend, range, path, err);
}

/* --skip-out: tiles by how many triangles they skipped, 1, 2+, 4+, ... 64+. */
#define SKIP_CLASSES 7
static const Rgb SKIP_COLOUR[SKIP_CLASSES] = {
    {255, 250, 170}, {250, 190, 40}, {240, 120, 30}, {215, 50, 40},
    {170, 30, 110},  {110, 40, 170}, {40, 60, 200},
};

static int skip_class(unsigned n) /* n > 0: floor(log2 n), at most the last class */
{
    int c = 0;
    while (n > 1 && c < SKIP_CLASSES - 1)
        n /= 2, c++;
    return c;
}

static void draw_skip_legend(LegendBand *b, const void *ctx)
{
    Rgb white = {255, 255, 255};
    (void)ctx;
    legend_text(b, "triangles a tile skipped:", white);
    legend_gap(b, 6);
    for (int k = 0; k < SKIP_CLASSES; k++) {
        char label[8];
        snprintf(label, sizeof label, k ? "%d+" : "%d", 1 << k);
        legend_swatch(b, SKIP_COLOUR[k], 10, 10, false);
        legend_gap(b, 3);
        legend_text(b, label, white);
        legend_gap(b, 8);
    }
    legend_text(b, "(untinted: none)", white);
}

/* The picture in flat colours; over a tile that skipped any triangle, its
 * class's colour at two thirds, and its last column and row darker. */
bool write_skip_picture(const Render *r, const Target *t, const LessonState *s, const char *path,
                        Error *err)
{
    const HierarchicalZ *h = s->hiz;
    Image pic;
    if (!shade_image(&r->mesh, &r->camera, t->face, NULL, t->width, t->height, SHADE_FLAT, &pic,
                     err))
        return false;
    for (int y = 0; y < t->height; y++)
        for (int x = 0; x < t->width; x++) {
            unsigned n = h->skipped_at[y / h->tile * h->tiles_x + x / h->tile];
            if (n == 0)
                continue;
            Rgb c = image_get(&pic, x, y), k = SKIP_COLOUR[skip_class(n)];
            Rgb mix = {(uint8_t)((c.r + 2 * k.r) / 3), (uint8_t)((c.g + 2 * k.g) / 3),
                       (uint8_t)((c.b + 2 * k.b) / 3)};
            bool edge = tile_edge(h, x, y);
            image_set(&pic, x, y, edge ? darker(mix) : mix);
        }
    return write_with_legend(&pic, draw_skip_legend, NULL, path, err);
}
