/* bar_chart: a grouped bar chart of measured times, for the pages.
 *
 *   bar_chart IN.csv OUT.png "Y AXIS LABEL"
 *
 * IN.csv: a header line "group,series 1,series 2,..." (up to 8 series), then
 * one line per group (up to 12): its label ('|' breaks it into lines, two
 * fit below the axis), then one number (>= 0) per
 * series. Each group is a cluster of bars along the x axis, one bar per
 * series in the series' colour (the legend names them); the y axis starts at
 * 0, with ticks and grid lines. Exit status: 0 written, 1 could not read or
 * write, 2 bad usage or a bad CSV. docs/10_fast_raster.md's steps chart is
 * drawn from docs/data/10_steps.csv (tools/make-doc-images.sh). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "harness/file.h"
#include "harness/font.h"
#include "harness/image_io.h"

#define PROGRAM "bar_chart"
#define MAX_SERIES 8
#define MAX_GROUPS 12
#define MAX_NAME 40
#define WIDTH 1280
#define HEIGHT 540
#define SCALE 2 /* the 5 x 7 font at twice its size */
#define LEFT 96
#define RIGHT 24
#define TOP 96
#define BOTTOM 64

static const Rgb BACKGROUND = {250, 250, 250}, INK = {30, 30, 30}, GRID = {215, 215, 215};
static const Rgb SERIES[MAX_SERIES] = {{31, 119, 180}, {255, 127, 14}, {44, 160, 44},
                                       {214, 39, 40},  {148, 103, 189}, {140, 86, 75},
                                       {227, 119, 194}, {127, 127, 127}};

typedef struct {
    char series[MAX_SERIES][MAX_NAME], group[MAX_GROUPS][MAX_NAME];
    double value[MAX_GROUPS][MAX_SERIES];
    int nseries, ngroups;
} Chart;

static void box(Image *im, int x0, int y0, int x1, int y1, Rgb c)
{
    for (int y = y0 < 0 ? 0 : y0; y < y1 && y < im->height; y++)
        for (int x = x0 < 0 ? 0 : x0; x < x1 && x < im->width; x++)
            image_set(im, x, y, c);
}

/* text at SCALE times the font's size, its top-left at (x, y); centred on x
 * when centre. Each font pixel becomes a SCALE x SCALE square. */
static void label(Image *im, int x, int y, const char *text, bool centre, Rgb c)
{
    int w = text_width(text), h = FONT_LINE_HEIGHT;
    uint8_t pixels[MAX_NAME * 2 * FONT_ADVANCE * FONT_LINE_HEIGHT * 3];
    if (w <= 0 || (size_t)w * (size_t)h * 3 > sizeof pixels)
        return;
    memset(pixels, 0, sizeof pixels);
    Image small = {w, h, pixels};
    draw_text(&small, 0, 0, text, (Rgb){255, 255, 255});
    x -= centre ? w * SCALE / 2 : 0;
    for (int j = 0; j < h; j++)
        for (int i = 0; i < w; i++)
            if (image_get(&small, i, j).r)
                box(im, x + i * SCALE, y + j * SCALE, x + (i + 1) * SCALE, y + (j + 1) * SCALE, c);
}

/* Splits line at commas into at most max fields of MAX_NAME - 1 characters. */
static int fields(char *line, char out[][MAX_NAME], int max)
{
    int n = 0;
    for (char *f = strtok(line, ",\r\n"); f && n < max; f = strtok(NULL, ",\r\n"))
        snprintf(out[n++], MAX_NAME, "%s", f);
    return n;
}

static bool read_chart(const char *path, Chart *c, Error *err)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return error_set(err, "cannot read '%s'", path);
    char line[1024], cell[MAX_SERIES + 1][MAX_NAME];
    bool ok = fgets(line, sizeof line, f) != NULL;
    c->nseries = ok ? fields(line, cell, MAX_SERIES + 1) - 1 : 0;
    for (int s = 0; s < c->nseries; s++)
        memcpy(c->series[s], cell[s + 1], MAX_NAME);
    ok = ok && c->nseries > 0;
    for (c->ngroups = 0; ok && fgets(line, sizeof line, f);) {
        if (fields(line, cell, MAX_SERIES + 1) != c->nseries + 1 || c->ngroups == MAX_GROUPS) {
            ok = false;
            break;
        }
        memcpy(c->group[c->ngroups], cell[0], MAX_NAME);
        for (int s = 0; s < c->nseries && ok; s++) {
            char *end;
            double v = strtod(cell[s + 1], &end);
            ok = *end == '\0' && isfinite(v) && v >= 0;
            c->value[c->ngroups][s] = v;
        }
        c->ngroups++;
    }
    fclose(f);
    if (!ok || c->ngroups == 0)
        return error_set(err, "'%s' is not a chart: a header 'group,series,...' (1 to %d "
                              "series), then 1 to %d lines 'label,number,...'", path,
                         MAX_SERIES, MAX_GROUPS);
    return true;
}

/* A tick step of 1, 2 or 5 times a power of ten: about 5 ticks up to top. */
static double tick_step(double top)
{
    double p = pow(10, floor(log10(top / 5))), steps[] = {1, 2, 5, 10};
    for (int k = 0; k < 4; k++)
        if (top / (steps[k] * p) <= 6)
            return steps[k] * p;
    return 10 * p;
}

static void draw_chart(Image *im, const Chart *c, const char *y_label)
{
    image_fill(im, BACKGROUND);
    double top = 0;
    for (int g = 0; g < c->ngroups; g++)
        for (int s = 0; s < c->nseries; s++)
            top = c->value[g][s] > top ? c->value[g][s] : top;
    double step = tick_step(top > 0 ? top : 1);
    top = ceil((top > 0 ? top : 1) / step) * step;
    int plot_h = HEIGHT - TOP - BOTTOM, plot_w = WIDTH - LEFT - RIGHT;
    char text[64];
    for (double v = 0; v <= top + step / 2; v += step) { /* ticks and grid */
        int y = TOP + plot_h - (int)lround(v / top * plot_h);
        box(im, LEFT, y, WIDTH - RIGHT, y + 1, GRID);
        snprintf(text, sizeof text, "%g", v);
        label(im, LEFT - 8 - text_width(text) * SCALE, y - FONT_GLYPH_HEIGHT, text, false, INK);
    }
    label(im, LEFT, TOP - 30, y_label, false, INK);
    double group_w = (double)plot_w / c->ngroups, bar_w = group_w * 0.8 / c->nseries;
    for (int g = 0; g < c->ngroups; g++) {
        double x0 = LEFT + g * group_w + group_w * 0.1;
        for (int s = 0; s < c->nseries; s++) {
            int h = (int)lround(c->value[g][s] / top * plot_h);
            box(im, (int)lround(x0 + s * bar_w), TOP + plot_h - h,
                (int)lround(x0 + (s + 1) * bar_w) - 1, TOP + plot_h, SERIES[s]);
        }
        const char *name = c->group[g]; /* its lines, split at each '|' */
        for (int y = TOP + plot_h + 12; *name; y += (FONT_LINE_HEIGHT + 2) * SCALE) {
            char line[MAX_NAME];
            int n = (int)strcspn(name, "|");
            snprintf(line, sizeof line, "%.*s", n, name);
            label(im, (int)lround(LEFT + (g + 0.5) * group_w), y, line, true, INK);
            name += n + (name[n] == '|');
        }
    }
    box(im, LEFT, TOP, LEFT + 2, TOP + plot_h, INK); /* the axes */
    box(im, LEFT, TOP + plot_h, WIDTH - RIGHT, TOP + plot_h + 2, INK);
    for (int s = 0, x = LEFT; s < c->nseries; s++) { /* the legend, above */
        box(im, x, 16, x + 18, 34, SERIES[s]);
        label(im, x + 24, 18, c->series[s], false, INK);
        x += 24 + text_width(c->series[s]) * SCALE + 28;
    }
}

int main(int argc, char **argv)
{
    signals_begin(PROGRAM); /* a signal from now on prints one line */
    if (argc == 2 && strcmp(argv[1], "--help") == 0) {
        printf("usage: " PROGRAM " IN.csv OUT.png \"Y AXIS LABEL\"\n"
               "Draws IN.csv (a header 'group,series,...', then 'label,number,...' lines)\n"
               "as grouped bars with a legend into OUT.png (%d x %d).\n", WIDTH, HEIGHT);
        return EXIT_OK;
    }
    if (argc != 4) {
        fprintf(stderr, PROGRAM ": error: expected IN.csv OUT.png \"Y AXIS LABEL\"\n");
        return EXIT_USAGE;
    }
    if (same_file(argv[1], argv[2])) { /* by any name: the input stays as it was */
        fprintf(stderr, PROGRAM ": error: OUT.png names the file IN.csv: the chart would "
                        "replace its input\n");
        return EXIT_USAGE;
    }
    Chart c;
    Image im;
    Error err;
    if (!read_chart(argv[1], &c, &err))
        return error_report(PROGRAM, &err, EXIT_USAGE);
    if (!image_init(&im, WIDTH, HEIGHT, &err))
        return error_report(PROGRAM, &err, EXIT_RUN_FAILED);
    draw_chart(&im, &c, argv[3]);
    bool ok = image_write_png(&im, argv[2], &err);
    image_free(&im);
    return ok ? EXIT_OK : error_report(PROGRAM, &err, EXIT_RUN_FAILED);
}
