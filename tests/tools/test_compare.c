/* test_compare.c: --compare REF.png tells a script whether this run's picture
 * is the reference: exit 0 and "the images match" when it is; exit 3 when it
 * is not, with the number of differing pixels, the largest channel difference,
 * their bounding box, and a diff picture next to --out; exit 1 with a clear
 * message when REF cannot be compared. Lesson 02 draws; the other lessons run
 * the same code (common/harness/compare.c), and test_tool_flags.c runs each of them. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness/compare.h"
#include "harness/image_io.h"
#include "test_support.h"

#define PROGRAM "02_zbuffer"

static void write_png(const Image *im, const char *path)
{
    Error err;
    if (!image_write_png(im, path, &err))
        fail_msg("%s", err.msg);
}

/* Draws the default scene at 40x20 into out, optionally comparing with ref. */
static RunResult draw(const char *out, const char *ref)
{
    const char *args[] = {"--out", out, "--width", "40", "--height", "20",
                          ref ? "--compare" : NULL, ref, NULL};
    return run_program(PROGRAM, args);
}

static void make_reference(const char *ref)
{
    RunResult r = draw(ref, NULL);
    assert_int_equal(r.status, 0);
    run_result_free(&r);
}

static void same_picture_exits_0_and_says_they_match(void **state)
{
    (void)state;
    const char *dir = test_dir("tools_compare_same");
    char ref[512], out[512], diff[512];
    snprintf(ref, sizeof ref, "%s", path_join(dir, "ref.png"));
    snprintf(out, sizeof out, "%s", path_join(dir, "run.png"));
    snprintf(diff, sizeof diff, "%s", path_join(dir, "run.diff.png"));
    make_reference(ref);
    RunResult r = draw(out, ref);
    assert_int_equal(r.status, 0);
    assert_non_null(strstr(r.out, "compare: the images match\n"));
    run_result_free(&r);
    assert_true(file_exists(diff));
}

/* The reference differs from the picture in one pixel, (7,4), by 100 in red
 * only: one pixel differs, the largest channel difference is 100, and the box
 * is that pixel alone. The diff picture shows it magenta. */
static void one_changed_pixel_exits_3_with_count_and_box(void **state)
{
    (void)state;
    const char *dir = test_dir("tools_compare_one");
    char ref[512], out[512], diff[512];
    snprintf(ref, sizeof ref, "%s", path_join(dir, "ref.png"));
    snprintf(out, sizeof out, "%s", path_join(dir, "run.png"));
    snprintf(diff, sizeof diff, "%s", path_join(dir, "run.diff.png"));
    make_reference(ref);
    Image im = read_png(ref);
    Rgb c = image_get(&im, 7, 4);
    c.r = (uint8_t)(c.r >= 128 ? c.r - 100 : c.r + 100);
    image_set(&im, 7, 4, c);
    write_png(&im, ref);
    image_free(&im);

    RunResult r = draw(out, ref);
    assert_int_equal(r.status, 3);
    if (!strstr(r.out, "compare: 1 pixel differs, largest channel difference 100, in box "
                       "(7,4)-(7,4)\n"))
        fail_msg("expected the count, difference and box of pixel (7,4); got:\n%s", r.out);
    run_result_free(&r);

    Image d = read_png(diff);
    Rgb m = image_get(&d, 7, 4), other = image_get(&d, 8, 4);
    assert_true(m.r == 255 && m.g == 0 && m.b == 255);
    assert_false(other.r == 255 && other.g == 0 && other.b == 255);
    image_free(&d);
}

/* A reference that cannot be used stops the run before it draws: no summary
 * says "wrote" of a picture that is then not published, and none is. */
static void expect_nothing_said_written(const RunResult *r, const char *out)
{
    if (strstr(r->out, "wrote"))
        fail_msg("the run failed, yet its summary says it wrote:\n%s", r->out);
    assert_false(file_exists(out));
}

static void different_sizes_fail_with_both_sizes(void **state)
{
    (void)state;
    const char *dir = test_dir("tools_compare_size");
    char ref[512], out[512];
    snprintf(ref, sizeof ref, "%s", path_join(dir, "small.png"));
    snprintf(out, sizeof out, "%s", path_join(dir, "run.png"));
    Image im;
    Error err;
    assert_true(image_init(&im, 20, 10, &err));
    write_png(&im, ref);
    image_free(&im);
    RunResult r = draw(out, ref);
    assert_int_equal(r.status, 1);
    char want[1200];
    snprintf(want, sizeof want,
             "02_zbuffer: error: --compare: %s is 20x10 but the picture is 40x20\n", ref);
    assert_string_equal(r.err, want);
    expect_nothing_said_written(&r, out);
    run_result_free(&r);
}

static void missing_reference_fails_with_its_name(void **state)
{
    (void)state;
    const char *dir = test_dir("tools_compare_missing");
    char ref[512], out[512];
    snprintf(ref, sizeof ref, "%s", path_join(dir, "nowhere.png"));
    snprintf(out, sizeof out, "%s", path_join(dir, "run.png"));
    RunResult r = draw(out, ref);
    assert_int_equal(r.status, 1);
    char want[1200];
    snprintf(want, sizeof want,
             "02_zbuffer: error: --compare: cannot read %s: No such file or directory\n", ref);
    assert_string_equal(r.err, want);
    expect_nothing_said_written(&r, out);
    run_result_free(&r);
}

/* --out and the diff picture replace their files as the run ends, after REF
 * is read: naming one file twice would destroy the reference. */
static void reference_that_out_would_overwrite_is_refused(void **state)
{
    (void)state;
    const char *dir = test_dir("tools_compare_self");
    char ref[512];
    snprintf(ref, sizeof ref, "%s", path_join(dir, "ref.png"));
    RunResult r = draw(ref, ref);
    assert_int_equal(r.status, 2);
    char want[1200];
    snprintf(want, sizeof want, "02_zbuffer: error: --compare and --out both name %s\n", ref);
    assert_string_equal(r.err, want);
    run_result_free(&r);
    assert_false(file_exists(ref));

    /* The diff picture of out.png is out.diff.png: that may not be REF either. */
    char out[512], diff[512];
    snprintf(out, sizeof out, "%s", path_join(dir, "out.png"));
    snprintf(diff, sizeof diff, "%s", path_join(dir, "out.diff.png"));
    r = draw(out, diff);
    assert_int_equal(r.status, 2);
    snprintf(want, sizeof want,
             "02_zbuffer: error: --compare names %s, where the diff picture of --out goes\n",
             diff);
    assert_string_equal(r.err, want);
    run_result_free(&r);
    assert_false(file_exists(out));
}

static void diff_picture_is_named_after_out(void **state)
{
    (void)state;
    char buf[64];
    assert_true(compare_diff_path("out/02_zbuffer.png", buf, sizeof buf));
    assert_string_equal(buf, "out/02_zbuffer.diff.png");
    assert_true(compare_diff_path("picture", buf, sizeof buf));
    assert_string_equal(buf, "picture.diff.png");
    assert_true(compare_diff_path(".png", buf, sizeof buf)); /* no name before the suffix */
    assert_string_equal(buf, ".png.diff.png");
    assert_false(compare_diff_path("a_rather_long_name.png", buf, 8));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(same_picture_exits_0_and_says_they_match),
        cmocka_unit_test(one_changed_pixel_exits_3_with_count_and_box),
        cmocka_unit_test(different_sizes_fail_with_both_sizes),
        cmocka_unit_test(missing_reference_fails_with_its_name),
        cmocka_unit_test(reference_that_out_would_overwrite_is_refused),
        cmocka_unit_test(diff_picture_is_named_after_out),
    };
    return cmocka_run_group_tests_name("tools: --compare", tests, NULL, NULL);
}
