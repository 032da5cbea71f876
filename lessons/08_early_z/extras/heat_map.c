/* heat_map.c: --shade-count-out (heat_map.h). */
#include "heat_map.h"

#include <stdio.h>

#include "harness/legend.h"
#include "harness/render.h"

static const Rgb HEAT[HEAT_CLASSES] = {
    {0, 0, 0},      {40, 90, 200},  {60, 170, 80},   {235, 205, 40},
    {240, 120, 30}, {205, 35, 40},  {255, 255, 255},
};

Rgb heat_colour(uint32_t times)
{
    return HEAT[times < HEAT_CLASSES - 1 ? times : HEAT_CLASSES - 1];
}

/* "shaded:", then per class a framed swatch and its number. */
static void heat_legend(LegendBand *b, const void *ctx)
{
    Rgb white = {255, 255, 255};
    (void)ctx;
    legend_text(b, "shaded:", white);
    legend_gap(b, 6);
    for (int k = 0; k < HEAT_CLASSES; k++) {
        char label[8];
        snprintf(label, sizeof label, k == HEAT_CLASSES - 1 ? "%d+" : "%d", k);
        legend_swatch(b, HEAT[k], 10, 10, true); /* a grey frame: black shows on the band */
        legend_gap(b, 3);
        legend_text(b, label, white);
        legend_gap(b, 8);
    }
}

bool write_heat_map(const uint32_t *count, int width, int height, const char *path, Error *err)
{
    Image heat, im;
    if (!image_init(&heat, width, height, err))
        return false;
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++)
            image_set(&heat, x, y, heat_colour(count[(size_t)y * (size_t)width + (size_t)x]));
    bool ok = image_with_legend(&im, &heat, HEAT_LEGEND_HEIGHT, heat_legend, NULL, err);
    image_free(&heat);
    if (!ok)
        return false;
    ok = render_make_parent_dirs(path, err) && image_write_png(&im, path, err);
    image_free(&im);
    return ok;
}
