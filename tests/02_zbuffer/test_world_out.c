/* test_world_out.c: --world-out draws the camera, its frustum and the scene
 * from the side and from above (common/harness/world_view.h) for triangles3, the
 * lesson's default scene. The picture is compared with
 * tests/expected/02_zbuffer/world_default.png; the framing itself is checked
 * by hand in tests/common/test_world_view.c. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>

#include "harness/file.h"
#include "harness/image_io.h"
#include "test_support.h"

#define PROGRAM "02_zbuffer"

static void world_view_of_the_default_scene_matches_expected(void **state)
{
    (void)state;
    expect_default_world_view(PROGRAM, "world_default");
}

/* An unwritable --world-out is a failure while running (exit 1) that names
 * the path; one that collides with --out is a usage error (exit 2) and writes
 * nothing. */
static void bad_world_out_paths_are_refused(void **state)
{
    (void)state;
    const char *dir = test_dir("02_world_out_bad");
    Path out = in_dir(dir, "out.png"), sub = in_dir(dir, "sub");
    assert_true(make_dirs(sub.path, NULL));
    const char *into_dir[] = {"--out", out.path, "--world-out", sub.path, NULL};
    char msg[TEST_PATH_MAX + 64];
    snprintf(msg, sizeof msg, "%s: error: cannot write %s: Is a directory\n", PROGRAM, sub.path);
    expect_run_error(PROGRAM, into_dir, 1, msg);
    const char *full[] = {"--out", out.path, "--world-out", "/dev/full", NULL};
    snprintf(msg, sizeof msg, "%s: error: cannot write /dev/full: No space left on device\n",
             PROGRAM);
    expect_run_error(PROGRAM, full, 1, msg);
    Path same = in_dir(dir, "same.png");
    const char *collide[] = {"--out", same.path, "--world-out", same.path, NULL};
    snprintf(msg, sizeof msg, "--out and --world-out both name %s", same.path);
    expect_run_refused(PROGRAM, collide, 2, msg, same.path);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(world_view_of_the_default_scene_matches_expected),
        cmocka_unit_test(bad_world_out_paths_are_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
