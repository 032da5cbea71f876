/* legend.c: see legend.h. */
#include "legend.h"

#include "font.h"

#define LEGEND_MARGIN 4                /* pixels left of the first item and right of the last */
static const Rgb BAND = {48, 48, 48};  /* the band's grey */
static const Rgb FRAME = {150, 150, 150};

static void set(LegendBand *b, int x, int y, Rgb c)
{
    if (b->im && x >= 0 && y >= 0 && x < b->im->width && y < b->im->height)
        image_set(b->im, x, y, c);
}

void legend_text(LegendBand *b, const char *text, Rgb colour)
{
    if (b->im)
        draw_text(b->im, b->x, b->text_top, text, colour);
    b->x += text_width(text);
}

void legend_swatch(LegendBand *b, Rgb fill, int width, int height, bool framed)
{
    int top = b->text_top - 2;
    for (int dy = 0; dy < height; dy++)
        for (int dx = 0; dx < width; dx++) {
            bool edge = dx == 0 || dy == 0 || dx == width - 1 || dy == height - 1;
            set(b, b->x + dx, top + dy, framed && edge ? FRAME : fill);
        }
    b->x += width;
}

void legend_ramp(LegendBand *b, const Rgb *colours, int n, int height)
{
    for (int k = 0; k < n; k++)
        for (int dy = 0; dy < height; dy++)
            set(b, b->x + k, b->text_top - 2 + dy, colours[k]);
    b->x += n;
}

void legend_gap(LegendBand *b, int pixels)
{
    b->x += pixels;
}

bool image_with_legend(Image *out, const Image *picture, int band_height,
                       void (*draw)(LegendBand *b, const void *ctx), const void *ctx,
                       Error *err)
{
    int text_top = picture->height + (band_height - FONT_GLYPH_HEIGHT) / 2;
    LegendBand measure = {NULL, LEGEND_MARGIN, text_top};
    draw(&measure, ctx);
    int width = measure.x + LEGEND_MARGIN > picture->width ? measure.x + LEGEND_MARGIN
                                                           : picture->width;
    if (!image_init_with_band(out, width, picture->height, band_height, err))
        return false;
    image_fill(out, BAND);
    for (int y = 0; y < picture->height; y++)
        for (int x = 0; x < picture->width; x++)
            image_set(out, x, y, image_get(picture, x, y));
    LegendBand band = {out, LEGEND_MARGIN, text_top};
    draw(&band, ctx);
    return true;
}
