/* ladder_picture.c: --ladder-out (ladder_picture.h). */
#include "ladder_picture.h"

#include <stdio.h>

#include "harness/font.h"
#include "harness/ladder.h"
#include "harness/legend.h"
#include "harness/shade.h"

#define LADDER_LEGEND_HEIGHT 22 /* the band under the picture, as under a heat map */
#define LABEL_GAP 4             /* pixels between a band's plates and its label */
#define LARGE_LABELS 480        /* rows from which the labels are drawn twice as large */

static const Rgb WHITE = {255, 255, 255};

typedef struct {
    int x0, y0, x1, y1; /* inclusive */
} Box;

/* The box of the pixels band k's two plates won; false when they won none. */
static bool band_box(const Target *t, int k, Box *box)
{
    bool any = false;
    for (int y = 0; y < t->height; y++)
        for (int x = 0; x < t->width; x++) {
            int32_t f = t->face[(size_t)y * (size_t)t->width + (size_t)x];
            if (f != 2 * k && f != 2 * k + 1)
                continue;
            if (!any)
                *box = (Box){x, y, x, y};
            box->x0 = x < box->x0 ? x : box->x0;
            box->x1 = x > box->x1 ? x : box->x1;
            box->y1 = y; /* rows come in order */
            any = true;
        }
    return any;
}

/* "d = D" centred over the band's plates (top row) or under them (bottom
 * row), kept inside the picture, on the background's colour; at twice the
 * font's size on a picture of LARGE_LABELS rows or more, so it reads there. */
static bool label_band(Image *im, const Box *box, int k, Error *err)
{
    char text[24];
    snprintf(text, sizeof text, "d = %g", LADDER_DISTANCE[k]);
    Image label;
    if (!image_init(&label, text_width(text) + 2, FONT_GLYPH_HEIGHT + 2, err))
        return false;
    image_fill(&label, FLAT_BACKGROUND); /* a margin of one pixel around the glyphs */
    draw_text(&label, 1, 1, text, WHITE);
    int s = im->height >= LARGE_LABELS ? 2 : 1, w = s * label.width, h = s * label.height;
    int x = (box->x0 + box->x1 + 1 - w) / 2;
    int y = k < LADDER_BANDS / 2 ? box->y0 - LABEL_GAP - h : box->y1 + 1 + LABEL_GAP;
    y = y + h > im->height ? im->height - h : y;
    y = y < 0 ? 0 : y;
    for (int dy = 0; dy < h; dy++)
        for (int dx = 0; dx < w; dx++)
            if (x + dx >= 0 && x + dx < im->width && y + dy < im->height)
                image_set(im, x + dx, y + dy, image_get(&label, dx / s, dy / s));
    image_free(&label);
    return true;
}

typedef struct {
    Rgb back, front; /* the plates' colours, band 0's */
} Key;

static void draw_key(LegendBand *b, const void *ctx)
{
    const Key *key = ctx;
    legend_swatch(b, key->back, 10, 10, true);
    legend_gap(b, 4);
    legend_text(b, "back plate wins: a failure", WHITE);
    legend_gap(b, 14);
    legend_swatch(b, key->front, 10, 10, true);
    legend_gap(b, 4);
    legend_text(b, "front plate wins", WHITE);
}

bool write_ladder_picture(const Render *r, const Target *t, const Rasterizer *rz,
                          const char *path, Error *err)
{
    Image pic, im;
    if (!render_image(r, t, rz, SHADE_FLAT, &pic, err))
        return false;
    for (int k = 0; k < LADDER_BANDS; k++) {
        Box box;
        if (band_box(t, k, &box) && !label_band(&pic, &box, k, err)) {
            image_free(&pic);
            return false;
        }
    }
    Key key = {face_flat_colour(&r->mesh, &r->camera, 0),
               face_flat_colour(&r->mesh, &r->camera, 1)};
    bool ok = image_with_legend(&im, &pic, LADDER_LEGEND_HEIGHT, draw_key, &key, err);
    image_free(&pic);
    if (!ok)
        return false;
    ok = render_make_parent_dirs(path, err) && image_write_png(&im, path, err);
    image_free(&im);
    return ok;
}
