/* test_world_out.c: --world-out draws the camera, its frustum and the scene
 * from the side and from above (common/harness/world_view.h) for inside, the lesson's
 * default scene: a room whose floor, walls and objects reach behind the camera
 * and through the near plane. The picture is compared with
 * tests/expected/05_clipping/world_inside.png; the framing itself is checked
 * by hand in tests/common/test_world_view.c. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>

#include "harness/image_io.h"
#include "test_support.h"

#define PROGRAM "05_clipping"

static void world_view_of_the_default_scene_matches_expected(void **state)
{
    (void)state;
    expect_default_world_view(PROGRAM, "world_inside");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(world_view_of_the_default_scene_matches_expected),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
