/* test_image.c: pictures in and out (common/image.c, common/harness/image_io.c).
 *
 * Every expected byte below is worked out by hand from the format's definition,
 * and raw files are read back with plain stdio, not with the code under test. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <stb_image.h>
#include <stb_image_write.h>

#include "harness/image_io.h"
#include "test_support.h"

/* The whole file, read with stdio: what a viewer would see on disk. */
static size_t raw_bytes(const char *path, uint8_t *buf, size_t cap)
{
    FILE *fp = fopen(path, "rb");
    assert_non_null(fp);
    size_t n = fread(buf, 1, cap, fp);
    fclose(fp);
    return n;
}

static Image new_image(int width, int height)
{
    Image im;
    Error err;
    assert_true(image_init(&im, width, height, &err));
    return im;
}

/* ---- image_init ---- */

static void image_init_accepts_sides_from_1_to_16384(void **state)
{
    (void)state;
    Image im = new_image(1, 1);
    expect_pixel(&im, 0, 0, (Rgb){0, 0, 0}, ""); /* a new image is black */
    image_free(&im);
    assert_null(im.rgb);

    im = new_image(16384, 1);
    expect_count(16384, im.width, "picture width");
    expect_count(1, im.height, "picture height");
    image_set(&im, 16383, 0, (Rgb){1, 2, 3}); /* the last pixel is writable */
    expect_pixel(&im, 16383, 0, (Rgb){1, 2, 3}, "");
    image_free(&im);

    im = new_image(1, 16384);
    expect_count(16384, im.height, "picture height");
    image_free(&im);
}

static void image_init_rejects_sides_outside_1_to_16384(void **state)
{
    (void)state;
    const int bad[][2] = {{0, 5}, {5, 0}, {-1, 1}, {1, -1}, {16385, 1}, {1, 16385},
                          {2147483647, 2147483647}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        Image im;
        Error err;
        char want[ERROR_MSG_MAX];
        snprintf(want, sizeof want, "image size %dx%d is out of range (1 to 16384)",
                 bad[i][0], bad[i][1]);
        assert_false(image_init(&im, bad[i][0], bad[i][1], &err));
        assert_string_equal(err.msg, want);
        assert_null(im.rgb); /* safe to image_free */
        image_free(&im);
    }
}

/* A picture of the largest height keeps the band of its legend under it
 * (legend.h): up to IMAGE_MAX_BAND rows more, and no band beyond that. */
static void a_band_may_take_a_picture_past_16384_rows(void **state)
{
    (void)state;
    Image im;
    Error err;
    assert_true(image_init_with_band(&im, 1, 16384, 64, &err));
    expect_count(16384 + 64, im.height, "picture height, band included");
    image_set(&im, 0, 16384 + 63, (Rgb){1, 2, 3}); /* the band's last row is writable */
    expect_pixel(&im, 0, 16384 + 63, (Rgb){1, 2, 3}, "");
    image_free(&im);
    assert_false(image_init_with_band(&im, 1, 16384, 65, &err));
    assert_string_equal(err.msg, "a band of 65 rows under a picture is out of range (0 to 64)");
    assert_false(image_init_with_band(&im, 1, 16385, 0, &err));
    assert_string_equal(err.msg, "image size 1x16385 is out of range (1 to 16384)");
    assert_null(im.rgb);
}

static void image_fill_sets_every_pixel(void **state)
{
    (void)state;
    Image im = new_image(3, 2);
    image_fill(&im, (Rgb){7, 8, 9});
    for (int y = 0; y < 2; y++)
        for (int x = 0; x < 3; x++)
            expect_pixel(&im, x, y, (Rgb){7, 8, 9}, "");
    image_free(&im);
}

/* ---- PNG ---- */

/* A 3x2 picture whose six pixels all differ, so a swap or flip shows. */
static const Rgb PATTERN[2][3] = {
    {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}},     /* row 0: the top row */
    {{1, 2, 3}, {250, 128, 7}, {255, 255, 255}}, /* row 1: the bottom row */
};

static Image pattern_image(void)
{
    Image im = new_image(3, 2);
    for (int y = 0; y < 2; y++)
        for (int x = 0; x < 3; x++)
            image_set(&im, x, y, PATTERN[y][x]);
    return im;
}

static void png_round_trip_keeps_every_pixel(void **state)
{
    (void)state;
    const char *path = path_join(test_dir("png_round_trip"), "pattern.png");
    Image im = pattern_image();
    Error err;
    assert_true(image_write_png(&im, path, &err));
    Image back;
    if (!image_read_png(&back, path, &err))
        fail_msg("%s", err.msg);
    expect_count(3, back.width, "picture width");
    expect_count(2, back.height, "picture height");
    assert_memory_equal(back.rgb, im.rgb, 3 * 2 * 3);
    image_free(&back);
    image_free(&im);
}

/* Pictures that take every filter of the writer and more than one IDAT
 * chunk: noise (incompressible: over 64 KB of deflated bytes), gradients
 * (Sub, Up, Average, Paeth win rows) and a width of 1; stb_image, another
 * decoder, reads each back pixel for pixel. */
static void png_round_trip_of_noise_and_gradients(void **state)
{
    (void)state;
    const char *path = path_join(test_dir("png_filters"), "p.png");
    const int sizes[][2] = {{300, 200}, {1, 37}, {257, 3}};
    uint32_t seed = 12345;
    for (size_t k = 0; k < sizeof sizes / sizeof sizes[0]; k++)
        for (int kind = 0; kind < 3; kind++) {
            Image im = new_image(sizes[k][0], sizes[k][1]);
            for (int y = 0; y < im.height; y++)
                for (int x = 0; x < im.width; x++) {
                    seed = seed * 1664525u + 1013904223u;
                    Rgb noise = {(uint8_t)(seed >> 24), (uint8_t)(seed >> 16), (uint8_t)(seed >> 8)};
                    Rgb ramp = {(uint8_t)(x * 3), (uint8_t)(y * 5), (uint8_t)(x + y)};
                    image_set(&im, x, y, kind == 0 ? noise : kind == 1 ? ramp : (x + y) % 7 ? ramp : noise);
                }
            Error err;
            assert_true(image_write_png(&im, path, &err));
            int w, h, n;
            unsigned char *px = stbi_load(path, &w, &h, &n, 3);
            assert_non_null(px);
            expect_count(im.width, w, "width read back");
            expect_count(im.height, h, "height read back");
            assert_memory_equal(px, im.rgb, (size_t)w * (size_t)h * 3);
            stbi_image_free(px);
            image_free(&im);
        }
}

static void png_row_0_is_the_top_row_on_disk(void **state)
{
    (void)state;
    const char *path = path_join(test_dir("png_rows"), "pattern.png");
    Image im = pattern_image();
    Error err;
    assert_true(image_write_png(&im, path, &err));
    image_free(&im);

    /* PNG layout: 8-byte signature, then the IHDR chunk (length 4 bytes,
     * "IHDR" 4 bytes) whose data starts at byte 16: width, height big-endian. */
    uint8_t raw[64];
    assert_true(raw_bytes(path, raw, sizeof raw) >= 24);
    const uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    assert_memory_equal(raw, signature, 8);
    assert_memory_equal(raw + 12, "IHDR", 4);
    const uint8_t size[8] = {0, 0, 0, 3, 0, 0, 0, 2}; /* width 3, height 2 */
    assert_memory_equal(raw + 16, size, 8);

    /* A plain decoder gives the rows in file order, first row first: that
     * must be our row 0, the red-green-blue one. */
    int w, h, n;
    unsigned char *px = stbi_load(path, &w, &h, &n, 3);
    assert_non_null(px);
    expect_count(3, w, "width read back");
    expect_count(2, h, "height read back");
    const uint8_t first_row[9] = {255, 0, 0, 0, 255, 0, 0, 0, 255};
    assert_memory_equal(px, first_row, 9);
    const uint8_t second_row[9] = {1, 2, 3, 250, 128, 7, 255, 255, 255};
    assert_memory_equal(px + 9, second_row, 9);
    stbi_image_free(px);
}

static void png_read_converts_grey_to_rgb(void **state)
{
    (void)state;
    const char *path = path_join(test_dir("png_grey"), "grey.png");
    const uint8_t grey[2] = {0, 200};
    assert_true(stbi_write_png(path, 2, 1, 1, grey, 2)); /* one channel */
    Image im;
    Error err;
    assert_true(image_read_png(&im, path, &err));
    expect_pixel(&im, 0, 0, (Rgb){0, 0, 0}, "");
    expect_pixel(&im, 1, 0, (Rgb){200, 200, 200}, "");
    image_free(&im);
}

static void png_read_of_missing_file_names_it(void **state)
{
    (void)state;
    const char *path = path_join(test_dir("png_missing"), "nothing.png");
    Image im;
    Error err;
    assert_false(image_read_png(&im, path, &err));
    char want[ERROR_MSG_MAX];
    snprintf(want, sizeof want, "cannot read %s: No such file or directory", path);
    assert_string_equal(err.msg, want);
    assert_null(im.rgb);
}

static void png_read_of_text_file_fails_naming_it(void **state)
{
    (void)state;
    const char *path = path_join(test_dir("png_text"), "not_a.png");
    FILE *fp = fopen(path, "w");
    assert_non_null(fp);
    fputs("this is not a picture\n", fp);
    fclose(fp);
    Image im;
    Error err;
    assert_false(image_read_png(&im, path, &err));
    char want[ERROR_MSG_MAX];
    snprintf(want, sizeof want, "cannot read %s: not a readable PNG", path);
    assert_memory_equal(err.msg, want, strlen(want)); /* then stb's reason */
    assert_null(im.rgb);
}

static void png_write_into_missing_directory_names_the_path(void **state)
{
    (void)state;
    const char *path = path_join(test_dir("png_missing_dir"), "no/such/dir/x.png");
    Image im = new_image(2, 2);
    Error err;
    assert_false(image_write_png(&im, path, &err));
    char want[ERROR_MSG_MAX];
    snprintf(want, sizeof want, "cannot write %s: No such file or directory", path);
    assert_string_equal(err.msg, want);
    image_free(&im);
}

/* ---- PFM ---- */

/* A 2x3 depth buffer, top row first in memory.
 * float32 bit patterns (sign | 8-bit exponent, bias 127 | 23-bit fraction):
 *   0.25 = 2^-2        -> exponent 125 = 0x7d -> 0x3e800000
 *   1.0  = 2^0         -> exponent 127 = 0x7f -> 0x3f800000
 *   3.0  = 1.5 * 2^1   -> exponent 128, fraction .1b -> 0x40400000
 *   +inf               -> exponent 255, fraction 0   -> 0x7f800000
 *   1.5  = 1.5 * 2^0   -> 0x3fc00000
 *   -2.0 = -1 * 2^1    -> sign 1, exponent 128       -> 0xc0000000 */
static const float DEPTHS[3 * 2] = {
    0.25f, 1.0f,     /* row 0 (top) */
    3.0f, INFINITY,  /* row 1 */
    1.5f, -2.0f,     /* row 2 (bottom) */
};

static void pfm_header_and_bottom_row_first(void **state)
{
    (void)state;
    const char *path = path_join(test_dir("pfm_bytes"), "depth.pfm");
    Error err;
    assert_true(write_pfm(DEPTHS, 2, 3, path, &err));
    uint8_t raw[128];
    size_t n = raw_bytes(path, raw, sizeof raw);
    const char header[] = "Pf\n2 3\n-1.0\n"; /* grey, width height, little-endian */
    size_t header_len = sizeof header - 1;  /* 12 bytes */
    assert_int_equal(n, header_len + 6 * 4);
    assert_memory_equal(raw, header, header_len);
    /* Little-endian: the lowest byte of each bit pattern comes first. */
    const uint8_t pixels[6 * 4] = {
        0x00, 0x00, 0xc0, 0x3f, 0x00, 0x00, 0x00, 0xc0, /* bottom row: 1.5, -2.0 */
        0x00, 0x00, 0x40, 0x40, 0x00, 0x00, 0x80, 0x7f, /* middle row: 3.0, +inf */
        0x00, 0x00, 0x80, 0x3e, 0x00, 0x00, 0x80, 0x3f, /* top row: 0.25, 1.0 */
    };
    assert_memory_equal(raw + header_len, pixels, sizeof pixels);
}

static void pfm_round_trip_keeps_values_and_infinity(void **state)
{
    (void)state;
    const char *path = path_join(test_dir("pfm_round_trip"), "depth.pfm");
    Error err;
    assert_true(write_pfm(DEPTHS, 2, 3, path, &err));
    float *back;
    int w, h;
    if (!read_pfm(&back, &w, &h, path, &err))
        fail_msg("%s", err.msg);
    expect_count(2, w, "width read back");
    expect_count(3, h, "height read back");
    assert_memory_equal(back, DEPTHS, sizeof DEPTHS); /* bit for bit, +inf too */
    free(back);
}

static void write_raw(const char *path, const void *bytes, size_t n)
{
    FILE *fp = fopen(path, "wb");
    assert_non_null(fp);
    assert_int_equal(fwrite(bytes, 1, n, fp), n);
    assert_int_equal(fclose(fp), 0);
}

static void pfm_read_positive_scale_is_big_endian(void **state)
{
    (void)state;
    const char *path = path_join(test_dir("pfm_big_endian"), "be.pfm");
    /* 1 wide, 2 high. File rows: bottom (1.5 = 0x3fc00000) then top (2.0 =
     * 0x40000000), highest byte first because the scale is positive. */
    const char file[] = "Pf\n1 2\n1.0\n\x3f\xc0\x00\x00\x40\x00\x00\x00";
    write_raw(path, file, sizeof file - 1);
    float *v;
    int w, h;
    Error err;
    if (!read_pfm(&v, &w, &h, path, &err))
        fail_msg("%s", err.msg);
    expect_count(1, w, "width read back");
    expect_count(2, h, "height read back");
    assert_true(v[0] == 2.0f); /* top row */
    assert_true(v[1] == 1.5f); /* bottom row */
    free(v);
}

static void pfm_read_rejects_colour_and_short_files(void **state)
{
    (void)state;
    const char *dir = test_dir("pfm_bad");
    struct {
        const char *name, *bytes, *want;
        size_t len;
    } cases[] = {
        {"colour.pfm", "PF\n1 1\n-1.0\n\0\0\0\0\0\0\0\0\0\0\0\0",
         "a colour PFM (\"PF\"); only grey (\"Pf\") is read", 24},
        {"short.pfm", "Pf\n2 2\n-1.0\n\0\0\0\0", /* 4 bytes of the 16 */
         "2x2 floats need 16 bytes of pixels, the file has 4", 16},
        {"pgm.pfm", "P5\n1 1\n255\n\0", "not a PFM file", 12},
        {"huge.pfm", "Pf\n16385 1\n-1.0\n", "image size 16385x1 is out of range", 16},
        {"noscale.pfm", "Pf\n1 1\n\0\0\0\0", "bad PFM header", 11},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const char *path = path_join(dir, cases[i].name);
        write_raw(path, cases[i].bytes, cases[i].len);
        float *v;
        int w, h;
        Error err;
        assert_false(read_pfm(&v, &w, &h, path, &err));
        assert_null(v);
        char want[ERROR_MSG_MAX];
        snprintf(want, sizeof want, "cannot read %s: %s", path, cases[i].want);
        if (strncmp(err.msg, want, strlen(want)) != 0)
            fail_msg("%s: message \"%s\", expected it to start \"%s\"",
                     cases[i].name, err.msg, want);
    }
}

/* ---- PGM ---- */

static void pgm16_header_big_endian_and_clamped(void **state)
{
    (void)state;
    const char *path = path_join(test_dir("pgm16"), "overdraw.pgm");
    /* 258 = 0x0102; 70000 does not fit 16 bits and is clamped to 65535 = 0xffff. */
    const uint32_t counts[2 * 2] = {1, 258, 65535, 70000};
    Error err;
    assert_true(write_pgm16(counts, 2, 2, path, &err));
    uint8_t raw[64];
    size_t n = raw_bytes(path, raw, sizeof raw);
    const char header[] = "P5\n2 2\n65535\n";
    size_t header_len = sizeof header - 1; /* 13 bytes */
    assert_int_equal(n, header_len + 4 * 2);
    assert_memory_equal(raw, header, header_len);
    /* Top row first (PGM has no flip), high byte first. */
    const uint8_t samples[8] = {0x00, 0x01, 0x01, 0x02, 0xff, 0xff, 0xff, 0xff};
    assert_memory_equal(raw + header_len, samples, 8);
}

/* ---- depth_to_grey ---- */

static void depth_to_grey_near_white_far_dark_background_blue(void **state)
{
    (void)state;
    /* Finite range [2, 4], linear in 1/d: t = (1/2 - 1/d) / (1/2 - 1/4),
     * grey = 255 - 207 t.
     *   d = 2   -> 255 (nearest)
     *   d = 4   -> 48  (farthest)
     *   d = 2.5 -> t = (0.5 - 0.4) / 0.25 = 0.4 -> 255 - 82.8 = 172.2 -> 172
     *   +inf and NaN: nothing drawn -> DEPTH_BACKGROUND */
    const float depth[5] = {2.0f, 4.0f, 2.5f, INFINITY, NAN};
    Image im = new_image(5, 1);
    depth_to_grey(depth, &im);
    expect_pixel(&im, 0, 0, (Rgb){255, 255, 255}, "");
    expect_pixel(&im, 1, 0, (Rgb){48, 48, 48}, "");
    expect_pixel(&im, 2, 0, (Rgb){172, 172, 172}, "");
    Rgb bg = DEPTH_BACKGROUND;
    expect_pixel(&im, 3, 0, bg, "");
    expect_pixel(&im, 4, 0, bg, "");
    image_free(&im);
}

static void depth_to_grey_single_depth_is_white(void **state)
{
    (void)state;
    const float depth[3] = {5.0f, INFINITY, 5.0f}; /* no range: all nearest */
    Image im = new_image(3, 1);
    depth_to_grey(depth, &im);
    expect_pixel(&im, 0, 0, (Rgb){255, 255, 255}, "");
    expect_pixel(&im, 2, 0, (Rgb){255, 255, 255}, "");
    Rgb bg = DEPTH_BACKGROUND;
    expect_pixel(&im, 1, 0, bg, "");
    image_free(&im);
}

static void depth_background_is_no_grey(void **state)
{
    (void)state;
    Rgb bg = DEPTH_BACKGROUND;
    assert_false(bg.r == bg.g && bg.g == bg.b);
}

/* ---- image_compare ---- */

static void image_compare_counts_largest_difference_and_box(void **state)
{
    (void)state;
    const Rgb base = {100, 43, 8};
    Image a = new_image(4, 3), b = new_image(4, 3);
    image_fill(&a, base);
    image_fill(&b, base);
    /* Rows are scanned top to bottom, so the box must not just keep the
     * first and last differing pixels: the leftmost one here is in a later row. */
    image_set(&b, 2, 0, (Rgb){110, 43, 8}); /* red off by 10 */
    image_set(&b, 1, 2, (Rgb){100, 43, 11}); /* blue off by 3 */
    image_set(&b, 0, 1, (Rgb){100, 44, 8}); /* green off by 1 */

    /* Tolerance 2: the first two differ, the third is within tolerance. */
    ImageDiff d;
    Image diff;
    Error err;
    assert_true(image_compare(&a, &b, 2, &d, &diff, &err));
    expect_count(2, d.differing, "differing pixels");
    expect_count(10, d.max_channel_diff, "largest channel difference");
    expect_count(1, d.x0, "x0 of the differing pixels");
    expect_count(0, d.y0, "y0 of the differing pixels");
    expect_count(2, d.x1, "x1 of the differing pixels");
    expect_count(2, d.y1, "y1 of the differing pixels");
    /* Diff picture: differing pixels magenta, the rest b (not a) at a quarter,
     * rounded down: (100, 43, 8) / 4 -> (25, 10, 2); b's (100, 44, 8) at
     * (0, 1) -> (25, 11, 2), where a's would give (25, 10, 2). */
    expect_count(4, diff.width, "picture width");
    expect_count(3, diff.height, "picture height");
    expect_pixel(&diff, 2, 0, (Rgb){255, 0, 255}, "");
    expect_pixel(&diff, 1, 2, (Rgb){255, 0, 255}, "");
    expect_pixel(&diff, 0, 1, (Rgb){25, 11, 2}, "");
    expect_pixel(&diff, 3, 2, (Rgb){25, 10, 2}, "");
    image_free(&diff);

    /* Tolerance 0: all three differ; the box grows to x 0..2. */
    assert_true(image_compare(&a, &b, 0, &d, NULL, &err));
    expect_count(3, d.differing, "differing pixels");
    expect_count(10, d.max_channel_diff, "largest channel difference");
    expect_count(0, d.x0, "x0 of the differing pixels");
    expect_count(0, d.y0, "y0 of the differing pixels");
    expect_count(2, d.x1, "x1 of the differing pixels");
    expect_count(2, d.y1, "y1 of the differing pixels");
    image_free(&a);
    image_free(&b);
}

static void image_compare_of_equal_images_has_no_box(void **state)
{
    (void)state;
    Image a = pattern_image(), b = pattern_image();
    ImageDiff d;
    Error err;
    assert_true(image_compare(&a, &b, 0, &d, NULL, &err));
    expect_count(0, d.differing, "differing pixels");
    expect_count(0, d.max_channel_diff, "largest channel difference");
    expect_count(-1, d.x0, "x0 of the differing pixels");
    expect_count(-1, d.y0, "y0 of the differing pixels");
    expect_count(-1, d.x1, "x1 of the differing pixels");
    expect_count(-1, d.y1, "y1 of the differing pixels");
    image_free(&a);
    image_free(&b);
}

static void image_compare_refuses_different_sizes(void **state)
{
    (void)state;
    Image a = new_image(2, 2), b = new_image(2, 3);
    ImageDiff d;
    Image diff;
    Error err;
    assert_false(image_compare(&a, &b, 0, &d, &diff, &err));
    assert_string_equal(err.msg, "images differ in size: 2x2 and 2x3");
    assert_null(diff.rgb);
    image_free(&a);
    image_free(&b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(image_init_accepts_sides_from_1_to_16384),
        cmocka_unit_test(image_init_rejects_sides_outside_1_to_16384),
        cmocka_unit_test(a_band_may_take_a_picture_past_16384_rows),
        cmocka_unit_test(image_fill_sets_every_pixel),
        cmocka_unit_test(png_round_trip_keeps_every_pixel),
        cmocka_unit_test(png_round_trip_of_noise_and_gradients),
        cmocka_unit_test(png_row_0_is_the_top_row_on_disk),
        cmocka_unit_test(png_read_converts_grey_to_rgb),
        cmocka_unit_test(png_read_of_missing_file_names_it),
        cmocka_unit_test(png_read_of_text_file_fails_naming_it),
        cmocka_unit_test(png_write_into_missing_directory_names_the_path),
        cmocka_unit_test(pfm_header_and_bottom_row_first),
        cmocka_unit_test(pfm_round_trip_keeps_values_and_infinity),
        cmocka_unit_test(pfm_read_positive_scale_is_big_endian),
        cmocka_unit_test(pfm_read_rejects_colour_and_short_files),
        cmocka_unit_test(pgm16_header_big_endian_and_clamped),
        cmocka_unit_test(depth_to_grey_near_white_far_dark_background_blue),
        cmocka_unit_test(depth_to_grey_single_depth_is_white),
        cmocka_unit_test(depth_background_is_no_grey),
        cmocka_unit_test(image_compare_counts_largest_difference_and_box),
        cmocka_unit_test(image_compare_of_equal_images_has_no_box),
        cmocka_unit_test(image_compare_refuses_different_sizes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
