/* test_program.c: build/bin/05_clipping run end to end: the default render of
 * the inside scene, its depth picture, the no-clip bug, how many pixels
 * lesson 04's drop rule gets wrong (the number docs/05_clipping.md gives),
 * and how it refuses bad input. */
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

#define PROGRAM "05_clipping"
#define GROUP "05_clipping"

/* The inside scene (42 faces): 4 quads, 8 triangles, lie wholly behind the
 * near plane (the back wall and the back ends of the table, the crate and
 * the beam) and are dropped; every other face is clipped as needed and drawn,
 * so all 480000 pixels are covered. The screen centre looks at the end wall
 * (face 10). */
static void default_run_draws_the_room_to_the_screen_edges(void **state)
{
    (void)state;
    const char *args[] = {NULL};
    const char *dir = test_dir("l05_default"); /* not the student's out/ */
    RunResult r = run_program_in(dir, PROGRAM, args);
    expect_no_message(r.err, PROGRAM);
    expect_count(0, r.status, "exit status");
    expect_line(r.out, "05_clipping: scene inside (42 faces): 76 triangles drawn, "
                       "8 dropped at the near plane\n");
    expect_line(r.out, "average overdraw 1.43 over 480000 covered pixels\n");
    expect_line(r.out, "  wrote out/05_clipping.png\n");
    expect_line(r.out, "  front object: face 10 at d = 15.530 at the screen centre (400,300)\n");
    run_result_free(&r);
    Image im = read_png(path_join(dir, "out/05_clipping.png"));
    expect_count(800, im.width, "picture width");
    expect_count(600, im.height, "picture height");
    expect_image(&im, GROUP, "default_render");
    image_free(&im);
}

static Image render_with(const char *dir, const char *const *flags, const char *name)
{
    const char *args[16] = {"--width", "240", "--height", "180", "--out", NULL};
    int n = 5;
    Path out = in_dir(dir, "picture.png");
    args[n++] = out.path;
    for (int i = 0; flags[i]; i++)
        args[n++] = flags[i];
    args[n] = NULL;
    RunResult r = run_program(PROGRAM, args);
    if (r.status != 0)
        fail_msg("%s: exit status %d: %s", name, r.status, r.err);
    run_result_free(&r);
    return read_png(out.path);
}

static void depth_picture_matches_its_expected_picture(void **state)
{
    (void)state;
    const char *flags[] = {"--shade", "depth", NULL};
    Image im = render_with(test_dir("l05_depth"), flags, "--shade depth");
    expect_image(&im, GROUP, "inside_depth");
    image_free(&im);
}

static void no_clip_bug_matches_its_expected_picture(void **state)
{
    (void)state;
    const char *flags[] = {"--bug", "no-clip", NULL};
    Image im = render_with(test_dir("l05_noclip"), flags, "--bug no-clip");
    expect_image(&im, GROUP, "inside_bug_no_clip");
    image_free(&im);
}

/* docs/05_clipping.md: on the default 800 x 600 picture of inside, lesson
 * 04's rule shows another face (or none) at 332889 pixels: 69% of them. */
static void compare_drop_counts_the_pixels_lesson_04_gets_wrong(void **state)
{
    (void)state;
    const char *dir = test_dir("l05_drop");
    Path out = in_dir(dir, "inside.png"), drop = in_dir(dir, "drop.png");
    const char *args[] = {"--out", out.path, "--compare-drop", drop.path, NULL};
    RunResult r = run_program(PROGRAM, args);
    expect_count(0, r.status, "exit status");
    expect_line(r.out, "  lesson 04's drop rule shows another face at 332889 pixels\n");
    run_result_free(&r);
    Image im = read_png(drop.path);
    long magenta = 0;
    for (int y = 0; y < im.height; y++)
        for (int x = 0; x < im.width; x++) {
            Rgb c = image_get(&im, x, y);
            magenta += c.r == 255 && c.g == 0 && c.b == 255;
        }
    expect_count(332889, magenta, "magenta pixels in the --compare-drop picture");
    image_free(&im);
}

static void bad_command_lines_are_refused_with_status_2(void **state)
{
    (void)state;
    const char *dir = test_dir("l05_bad");
    Path out = in_dir(dir, "never.png");
    const char *bug[] = {"--bug", "negated-w", "--out", out.path, NULL};
    expect_run_refused(PROGRAM, bug, 2, "--bug: 'negated-w' is not one of no-clip", out.path);
    const char *same[] = {"--out", out.path, "--compare-drop", out.path, NULL};
    char message[sizeof out.path + 64];
    snprintf(message, sizeof message, "--out and --compare-drop both name %s", out.path);
    expect_run_refused(PROGRAM, same, 2, message, out.path);
    const char *naive[] = {"--compare-naive", "x.png", "--out", out.path, NULL};
    expect_run_refused(PROGRAM, naive, 2, "unknown flag '--compare-naive' (try --help)",
                       out.path);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(default_run_draws_the_room_to_the_screen_edges),
        cmocka_unit_test(depth_picture_matches_its_expected_picture),
        cmocka_unit_test(no_clip_bug_matches_its_expected_picture),
        cmocka_unit_test(compare_drop_counts_the_pixels_lesson_04_gets_wrong),
        cmocka_unit_test(bad_command_lines_are_refused_with_status_2),
    };
    return cmocka_run_group_tests_name("05_clipping program", tests, NULL, NULL);
}
