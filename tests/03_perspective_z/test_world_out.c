/* test_world_out.c: --world-out draws the camera, its frustum and the scene
 * from the side and from above (common/harness/world_view.h) for grazing, the lesson's
 * default scene: two strips at a grazing angle, stretched vertically to read.
 * The picture is compared with tests/expected/03_perspective_z/world_grazing.png;
 * the framing itself is checked by hand in tests/common/test_world_view.c. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>

#include "harness/image_io.h"
#include "test_support.h"

#define PROGRAM "03_perspective_z"

static void world_view_of_the_default_scene_matches_expected(void **state)
{
    (void)state;
    expect_default_world_view(PROGRAM, "world_grazing");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(world_view_of_the_default_scene_matches_expected),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
