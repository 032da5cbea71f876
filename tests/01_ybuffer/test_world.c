/* test_world.c: lesson 01's segments file, --order and segment names. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test_support.h"
#include "world.h"

#define SOURCE "segments.txt"

static void expect_segment(const Segment *s, int x0, int y0, int x1, int y1, int r, int g,
                           int b, int which)
{
    if (s->x0 != x0 || s->y0 != y0 || s->x1 != x1 || s->y1 != y1 || s->colour.r != r ||
        s->colour.g != g || s->colour.b != b)
        fail_msg("segment %d: got %d %d %d %d %d %d %d, expected %d %d %d %d %d %d %d", which,
                 s->x0, s->y0, s->x1, s->y1, s->colour.r, s->colour.g, s->colour.b, x0, y0,
                 x1, y1, r, g, b);
}

static void parse_text(const char *text, Segment **segs, int *count)
{
    Error err;
    if (!parse_segments(text, strlen(text), SOURCE, segs, count, &err))
        fail_msg("parse_segments refused good input: %s", err.msg);
}

/* The line the parser must refuse, and its exact message. */
static void expect_parse_error(const char *text, size_t len, const char *message)
{
    static Segment sentinel;
    Segment *segs = &sentinel; /* must come back NULL */
    int count = -1;
    Error err = {""};
    if (parse_segments(text, len, SOURCE, &segs, &count, &err))
        fail_msg("parse_segments accepted bad input, expected \"%s\"", message);
    assert_string_equal(err.msg, message);
    assert_null(segs);
    expect_count(0, count, "segments");
}

#define EXPECT_PARSE_ERROR(text, message) expect_parse_error((text), strlen(text), (message))

static void segments_file_with_comments_blanks_and_crlf(void **state)
{
    (void)state;
    const char *text = "# the lesson's scene\n"
                       "20 34 744 400 255 0 0\n"
                       "\n"
                       "   \t \n"
                       "  120\t434 444 400 0 255 0   # green, tab separated\r\n"
                       "+330 463 594 200 0 0 255"; /* no final newline */
    Segment *segs;
    int count;
    parse_text(text, &segs, &count);
    expect_count(3, count, "segments");
    expect_segment(&segs[0], 20, 34, 744, 400, 255, 0, 0, 1);
    expect_segment(&segs[1], 120, 434, 444, 400, 0, 255, 0, 2);
    expect_segment(&segs[2], 330, 463, 594, 200, 0, 0, 255, 3);
    free(segs);
}

static void segments_file_accepts_the_limits(void **state)
{
    (void)state;
    Segment *segs;
    int count;
    parse_text("-1000000 1000000 1000000 -1000000 0 255 0\n-5 -7 -5 -7 255 255 255\n"
               "00000000000000000001 -0 +0 0 0 0 0255\n",
               &segs, &count);
    expect_count(3, count, "segments");
    expect_segment(&segs[2], 1, 0, 0, 0, 0, 0, 255, 3); /* leading zeros, signed zeros */
    expect_segment(&segs[0], -1000000, 1000000, 1000000, -1000000, 0, 255, 0, 1);
    expect_segment(&segs[1], -5, -7, -5, -7, 255, 255, 255, 2);
    free(segs);
}

static void empty_and_comment_only_files_have_no_segments(void **state)
{
    (void)state;
    const char *texts[] = {"", "\n\n", "# nothing here\n   # nor here\n"};
    for (size_t i = 0; i < sizeof texts / sizeof texts[0]; i++) {
        Segment *segs;
        int count = -1;
        parse_text(texts[i], &segs, &count);
        expect_count(0, count, "segments");
        free(segs);
    }
}

static void malformed_lines_are_named_by_line_number(void **state)
{
    (void)state;
    EXPECT_PARSE_ERROR("20 34 744 400 255 0 0\n# ok\n1 2 3 4 5\n",
                       "segments.txt:3: expected 7 numbers 'x0 y0 x1 y1 r g b', got 5");
    EXPECT_PARSE_ERROR("1 2 3 4 5 6 7 8\n",
                       "segments.txt:1: expected 7 numbers 'x0 y0 x1 y1 r g b', got 8");
    EXPECT_PARSE_ERROR("1 2 3 4 5 6 # 7\n",
                       "segments.txt:1: expected 7 numbers 'x0 y0 x1 y1 r g b', got 6");
    EXPECT_PARSE_ERROR("\n0 0 1.5 4 1 2 3\n",
                       "segments.txt:2: x1 '1.5' is not an integer "
                       "(coordinates and colours are whole numbers)");
    EXPECT_PARSE_ERROR("0 0 1 4 1 2 blue\n",
                       "segments.txt:1: b 'blue' is not an integer "
                       "(coordinates and colours are whole numbers)");
    EXPECT_PARSE_ERROR("0x10 0 1 4 1 2 3\n",
                       "segments.txt:1: x0 '0x10' is not an integer "
                       "(coordinates and colours are whole numbers)");
    EXPECT_PARSE_ERROR("0 1e3 1 4 1 2 3\n",
                       "segments.txt:1: y0 '1e3' is not an integer "
                       "(coordinates and colours are whole numbers)");
    EXPECT_PARSE_ERROR("0 0 1 - 1 2 3\n",
                       "segments.txt:1: y1 '-' is not an integer "
                       "(coordinates and colours are whole numbers)");
}

static void out_of_range_values_are_refused(void **state)
{
    (void)state;
    EXPECT_PARSE_ERROR("0 0 1 1 255 256 0\n", "segments.txt:1: g 256 is out of range 0..255");
    EXPECT_PARSE_ERROR("0 0 1 1 -1 0 0\n", "segments.txt:1: r -1 is out of range 0..255");
    EXPECT_PARSE_ERROR("0 1000001 1 1 0 0 0\n",
                       "segments.txt:1: y0 1000001 is out of range -1000000..1000000");
    EXPECT_PARSE_ERROR("0 0 -1000001 1 0 0 0\n",
                       "segments.txt:1: x1 -1000001 is out of range -1000000..1000000");
    EXPECT_PARSE_ERROR("99999999999999999999 0 1 1 0 0 0\n",
                       "segments.txt:1: x0 99999999999999999999 is out of range "
                       "-1000000..1000000");
    /* A very long token is cut short in the message. */
    EXPECT_PARSE_ERROR("0 0 1 1 0 0 1234567890123456789012345678901234567890\n",
                       "segments.txt:1: b 123456789012345678901234... is out of range 0..255");
}

static void control_bytes_are_refused_with_their_line(void **state)
{
    (void)state;
    const char text[] = "0 0 1 1 0 0 0\n0 0 1\0 1 0 0 0\n";
    expect_parse_error(text, sizeof text - 1,
                       "segments.txt:2: contains the control byte 0x00 (not a text file?)");
    EXPECT_PARSE_ERROR("# \x1b[31m\n",
                       "segments.txt:1: contains the control byte 0x1b (not a text file?)");
}

static void missing_segments_file_is_an_error(void **state)
{
    (void)state;
    const char *path = path_join(test_dir("world_missing"), "no-such-file.txt");
    Segment *segs;
    int count;
    Error err;
    assert_false(read_segments(path, &segs, &count, &err));
    char want[1024];
    snprintf(want, sizeof want, "cannot read %s: No such file or directory", path);
    assert_string_equal(err.msg, want);
}

static void segments_file_is_read_from_disk(void **state)
{
    (void)state;
    const char *path = path_join(test_dir("world_read"), "two.txt");
    FILE *fp = fopen(path, "w");
    assert_non_null(fp);
    fputs("1 2 3 4 5 6 7\n# comment\n-1 -2 -3 -4 0 0 0\n", fp);
    fclose(fp);
    Segment *segs;
    int count;
    Error err;
    if (!read_segments(path, &segs, &count, &err))
        fail_msg("read_segments: %s", err.msg);
    expect_count(2, count, "segments");
    expect_segment(&segs[0], 1, 2, 3, 4, 5, 6, 7, 1);
    expect_segment(&segs[1], -1, -2, -3, -4, 0, 0, 0, 2);
    free(segs);
}

static void default_scene_is_red_green_blue(void **state)
{
    (void)state;
    Segment *segs;
    int count;
    Error err;
    assert_true(default_segments(&segs, &count, &err));
    expect_count(3, count, "segments");
    expect_segment(&segs[0], 20, 34, 744, 400, 255, 0, 0, 1);
    expect_segment(&segs[1], 120, 434, 444, 400, 0, 255, 0, 2);
    expect_segment(&segs[2], 330, 463, 594, 200, 0, 0, 255, 3);
    free(segs);
}

static void order_defaults_to_the_listed_order(void **state)
{
    (void)state;
    int order[3] = {-1, -1, -1};
    Error err;
    assert_true(parse_order(NULL, 3, order, &err));
    assert_int_equal(order[0], 0);
    assert_int_equal(order[1], 1);
    assert_int_equal(order[2], 2);
}

static void order_as_digits_or_with_commas(void **state)
{
    (void)state;
    const char *forms[] = {"312", "3,1,2"};
    for (int f = 0; f < 2; f++) {
        int order[3] = {-1, -1, -1};
        Error err;
        if (!parse_order(forms[f], 3, order, &err))
            fail_msg("--order %s refused: %s", forms[f], err.msg);
        /* 312: the third segment first (index 2), then the first, then the second */
        assert_int_equal(order[0], 2);
        assert_int_equal(order[1], 0);
        assert_int_equal(order[2], 1);
    }
    /* Beyond 9 segments only commas can say it. */
    int order[10];
    Error err;
    assert_true(parse_order("10,9,8,7,6,5,4,3,2,1", 10, order, &err));
    assert_int_equal(order[0], 9);
    assert_int_equal(order[9], 0);
}

static void order_that_is_no_permutation_is_refused(void **state)
{
    (void)state;
    const char *bad[] = {"12", "1234", "112", "012", "31a", "3,1,", ",3,1,2", "3,,1,2",
                         "3,1,4", "", "3 1 2"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        int order[8];
        Error err = {""};
        if (parse_order(bad[i], 3, order, &err))
            fail_msg("--order '%s' accepted for 3 segments", bad[i]);
        char want[256];
        snprintf(want, sizeof want,
                 "--order '%s': expected each of 1..3 exactly once, as digits (e.g. 312) "
                 "or separated by commas",
                 bad[i]);
        assert_string_equal(err.msg, want);
    }
    int order[1];
    Error err;
    assert_false(parse_order("1", 0, order, &err));
    assert_string_equal(err.msg, "--order '1': there are no segments to order");
}

static void plain_colours_have_names(void **state)
{
    (void)state;
    char name[SEGMENT_NAME_MAX];
    segment_name((Rgb){255, 0, 0}, name);
    assert_string_equal(name, "red");
    segment_name((Rgb){0, 0, 255}, name);
    assert_string_equal(name, "blue");
    segment_name((Rgb){0x12, 0xab, 0x05}, name);
    assert_string_equal(name, "#12ab05");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(segments_file_with_comments_blanks_and_crlf),
        cmocka_unit_test(segments_file_accepts_the_limits),
        cmocka_unit_test(empty_and_comment_only_files_have_no_segments),
        cmocka_unit_test(malformed_lines_are_named_by_line_number),
        cmocka_unit_test(out_of_range_values_are_refused),
        cmocka_unit_test(control_bytes_are_refused_with_their_line),
        cmocka_unit_test(missing_segments_file_is_an_error),
        cmocka_unit_test(segments_file_is_read_from_disk),
        cmocka_unit_test(default_scene_is_red_green_blue),
        cmocka_unit_test(order_defaults_to_the_listed_order),
        cmocka_unit_test(order_as_digits_or_with_commas),
        cmocka_unit_test(order_that_is_no_permutation_is_refused),
        cmocka_unit_test(plain_colours_have_names),
    };
    return cmocka_run_group_tests_name("01_ybuffer: segments file and --order", tests, NULL,
                                       NULL);
}
