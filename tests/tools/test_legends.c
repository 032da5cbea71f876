/* test_legends.c: a picture with a legend band under it (harness/legend.h)
 * is as wide as its legend needs, whatever the size of the render.
 *
 * Lesson 06 writes the ladder labelled (--ladder-out), lessons 08 and 09 a
 * heat map (--shade-count-out) and lesson 09 the tile buffer (--hiz-out)
 * and its skips (--skip-out), each with a band of 22 rows under the picture.
 * At 8 x 8 pixels the legend used to be drawn past the end of the image's
 * rows (a heap overflow) and, up to a width of about 240, over the picture.
 * Now, for each:
 *   - at 8 x 8 the run succeeds, the picture is 8 + 22 rows tall and wider
 *     than 8 columns; right of the render's 8 columns, above the band, is
 *     the band's grey: nothing of the legend lies over the picture;
 *   - at the default 800 x 600 the legend fits: the picture is 800 wide;
 *   - at the largest height, 16384, the run succeeds and the picture keeps
 *     its band, 16384 + 22 rows (it used to fail, "image size 800x16406 is
 *     out of range", status 1, and so did lesson 09's default run, which
 *     writes the skip picture). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness/image_io.h"
#include "test_support.h"

#define BAND 22
#define LEGEND_MIN_WIDTH 150 /* each legend is wider than this */

typedef struct {
    const char *lesson, *flag;
} LegendOutput;

static const LegendOutput OUTPUTS[] = {
    {"06_depth_precision", "--ladder-out"},
    {"08_early_z", "--shade-count-out"},
    {"09_hierarchical_z", "--shade-count-out"},
    {"09_hierarchical_z", "--hiz-out"},
    {"09_hierarchical_z", "--skip-out"},
};

static Image run_and_read(const LegendOutput *o, const char *size, const char *dir)
{
    Path picture = in_dir(dir, "legend.png"), out = in_dir(dir, "out.png");
    const char *w = size ? "--width" : NULL;
    const char *args[] = {o->flag, picture.path, "--out", out.path, w, size, "--height", size, NULL};
    RunResult r = run_program(o->lesson, args);
    if (r.status != 0)
        fail_msg("%s %s at %s: status %d\n%s", o->lesson, o->flag, size ? size : "its size",
                 r.status, r.err);
    run_result_free(&r);
    Image im;
    Error err;
    if (!image_read_png(&im, picture.path, &err))
        fail_msg("%s %s: %s", o->lesson, o->flag, err.msg);
    return im;
}

static void a_narrow_picture_gets_its_whole_legend_beside_it(void **state)
{
    (void)state;
    for (size_t k = 0; k < sizeof OUTPUTS / sizeof OUTPUTS[0]; k++) {
        const LegendOutput *o = &OUTPUTS[k];
        Image im = run_and_read(o, "8", test_dir("legend_narrow"));
        if (im.height != 8 + BAND || im.width < LEGEND_MIN_WIDTH)
            fail_msg("%s %s at 8 x 8: %d x %d, wanted at least %d x %d", o->lesson, o->flag,
                     im.width, im.height, LEGEND_MIN_WIDTH, 8 + BAND);
        for (int y = 0; y < 8; y++)
            for (int x = 8; x < im.width; x++) {
                Rgb c = image_get(&im, x, y);
                if (c.r != 48 || c.g != 48 || c.b != 48)
                    fail_msg("%s %s at 8 x 8: pixel (%d, %d), beside the picture, is "
                             "(%d, %d, %d), not the band's grey", o->lesson, o->flag, x, y, c.r,
                             c.g, c.b);
            }
        image_free(&im);
    }
}

static void the_legend_fits_a_picture_of_the_default_size(void **state)
{
    (void)state;
    for (size_t k = 0; k < sizeof OUTPUTS / sizeof OUTPUTS[0]; k++) {
        Image im = run_and_read(&OUTPUTS[k], NULL, test_dir("legend_default"));
        if (im.width != 800 || im.height != 600 + BAND)
            fail_msg("%s %s: %d x %d, wanted 800 x %d", OUTPUTS[k].lesson, OUTPUTS[k].flag,
                     im.width, im.height, 600 + BAND);
        image_free(&im);
    }
}

/* The width and height in a PNG's header (read without decoding: the series'
 * reader takes pictures of up to 16384 rows, legend bands aside). */
static void png_size(const char *path, unsigned *width, unsigned *height)
{
    unsigned char b[24];
    FILE *fp = fopen(path, "rb");
    if (!fp || fread(b, 1, sizeof b, fp) != sizeof b || memcmp(b + 12, "IHDR", 4) != 0)
        fail_msg("%s: no PNG header", path);
    fclose(fp);
    *width = (unsigned)b[16] << 24 | (unsigned)b[17] << 16 | (unsigned)b[18] << 8 | b[19];
    *height = (unsigned)b[20] << 24 | (unsigned)b[21] << 16 | (unsigned)b[22] << 8 | b[23];
}

static void a_picture_of_the_largest_height_keeps_its_legend(void **state)
{
    (void)state;
    const char *dir = test_dir("legend_tallest");
    Path picture = in_dir(dir, "legend.png"), out = in_dir(dir, "out.png");
    unsigned w, h;
    for (size_t k = 0; k < sizeof OUTPUTS / sizeof OUTPUTS[0]; k++) {
        const LegendOutput *o = &OUTPUTS[k];
        const char *args[] = {o->flag, picture.path, "--out", out.path, "--width", "1",
                              "--height", "16384", NULL};
        RunResult r = run_program(o->lesson, args);
        if (r.status != 0)
            fail_msg("%s %s at 1 x 16384: status %d\n%s", o->lesson, o->flag, r.status, r.err);
        run_result_free(&r);
        png_size(picture.path, &w, &h);
        if (h != 16384 + BAND || w < LEGEND_MIN_WIDTH)
            fail_msg("%s %s at 1 x 16384: %u x %u, wanted at least %d x %d", o->lesson, o->flag,
                     w, h, LEGEND_MIN_WIDTH, 16384 + BAND);
    }
    /* The default run writes the skip picture too. */
    const char *tall[] = {"--width", "1", "--height", "16384", NULL};
    RunResult r = run_program_in(dir, "09_hierarchical_z", tall);
    if (r.status != 0)
        fail_msg("09_hierarchical_z --width 1 --height 16384: status %d\n%s", r.status, r.err);
    run_result_free(&r);
    png_size(path_join(dir, "out/09_hierarchical_z_skips.png"), &w, &h);
    expect_count(16384 + BAND, (long)h, "skip picture height, legend included");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_narrow_picture_gets_its_whole_legend_beside_it),
        cmocka_unit_test(the_legend_fits_a_picture_of_the_default_size),
        cmocka_unit_test(a_picture_of_the_largest_height_keeps_its_legend),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
