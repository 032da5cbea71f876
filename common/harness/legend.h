/* legend.h: the band under a picture that holds its legend, laid out left to
 * right: labels, swatches, ramps. A legend is drawn by one function of the
 * writer's, called twice: once to measure it (the band's im is NULL: only x
 * moves), then into the band. The picture is made as wide as its legend
 * needs, so a narrow picture keeps a legend that can be read, and nothing
 * of the legend is drawn outside the image or over the picture. */
#ifndef LEGEND_H
#define LEGEND_H

#include "image_io.h"

typedef struct {
    Image *im;    /* NULL while measuring */
    int x;        /* where the next item starts */
    int text_top; /* the labels' top row; swatches start 2 rows above it */
} LegendBand;

void legend_text(LegendBand *b, const char *text, Rgb colour);
/* A box of width x height pixels, with a grey frame if framed. */
void legend_swatch(LegendBand *b, Rgb fill, int width, int height, bool framed);
/* n columns, one colour each, height pixels tall. */
void legend_ramp(LegendBand *b, const Rgb *colours, int n, int height);
void legend_gap(LegendBand *b, int pixels);

/* out: picture with a band of band_height rows (at most IMAGE_MAX_BAND)
 * under it, its legend drawn by draw(band, ctx); as wide as the picture or
 * as the legend (and a margin), whichever is wider; what the picture does
 * not cover is the band's grey. A picture of the largest height keeps its
 * band: out is then taller than IMAGE_MAX_SIDE (image.h). */
bool image_with_legend(Image *out, const Image *picture, int band_height,
                       void (*draw)(LegendBand *b, const void *ctx), const void *ctx,
                       Error *err);

#endif
