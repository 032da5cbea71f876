/* test_font.c: the built-in 5x7 font draws where it says, clips at the
 * image's edges and measures its labels. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "harness/font.h"
#include "test_support.h"

static const Rgb BLACK = {0, 0, 0};
static const Rgb WHITE = {255, 255, 255};

static long lit_pixels(const Image *im)
{
    long n = 0;
    for (int y = 0; y < im->height; y++)
        for (int x = 0; x < im->width; x++)
            n += image_get(im, x, y).r != 0;
    return n;
}

/* 'T' is a top row of five and a stem of six under its middle column. */
static void glyph_T_is_drawn_at_its_top_left_corner(void **state)
{
    (void)state;
    Image im;
    assert_true(image_init(&im, 20, 12, NULL));
    draw_text(&im, 3, 2, "T", WHITE);
    for (int x = 3; x < 8; x++)
        expect_pixel(&im, x, 2, WHITE, "the top bar of T");
    for (int y = 3; y < 9; y++)
        expect_pixel(&im, 5, y, WHITE, "the stem of T");
    expect_pixel(&im, 4, 3, BLACK, "beside the stem");
    expect_count(11, lit_pixels(&im), "pixels of T");
    image_free(&im);
}

static void text_runs_off_every_edge_without_harm(void **state)
{
    (void)state;
    Image im;
    assert_true(image_init(&im, 8, 8, NULL));
    draw_text(&im, -3, -4, "Hello, world!\nnext line", WHITE);
    draw_text(&im, 6, 6, "xyz", WHITE);
    draw_text(&im, 1000000, -1000000, "far", WHITE);
    expect_at_least(1, lit_pixels(&im), "pixels drawn inside the 8x8 image");
    image_free(&im);
}

static void every_printable_character_has_a_glyph(void **state)
{
    (void)state;
    Image im;
    assert_true(image_init(&im, FONT_ADVANCE, FONT_LINE_HEIGHT, NULL));
    for (char c = '!'; c <= '~'; c++) {
        image_fill(&im, BLACK);
        char text[2] = {c, '\0'};
        draw_text(&im, 0, 0, text, WHITE);
        if (lit_pixels(&im) == 0)
            fail_msg("character '%c' draws nothing", c);
    }
    image_free(&im);
}

static void text_is_measured_without_trailing_spacing(void **state)
{
    (void)state;
    expect_count(0, text_width(""), "width of \"\"");
    expect_count(0, text_height(""), "height of \"\"");
    expect_count(FONT_GLYPH_WIDTH, text_width("a"), "width of \"a\"");
    expect_count(FONT_ADVANCE + FONT_GLYPH_WIDTH, text_width("ab"), "width of \"ab\"");
    expect_count(2 * FONT_ADVANCE + FONT_GLYPH_WIDTH, text_width("a\nabc\nb"), "widest line");
    expect_count(FONT_GLYPH_HEIGHT, text_height("abc"), "height of one line");
    expect_count(FONT_LINE_HEIGHT + FONT_GLYPH_HEIGHT, text_height("a\nb"), "height of two lines");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(glyph_T_is_drawn_at_its_top_left_corner),
        cmocka_unit_test(text_runs_off_every_edge_without_harm),
        cmocka_unit_test(every_printable_character_has_a_glyph),
        cmocka_unit_test(text_is_measured_without_trailing_spacing),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
