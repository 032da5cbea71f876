/* test_far_planes.c: a far plane is finite unless it is --far inf.
 *
 * Lessons 06, 07 and 10 stand for --far inf (the reversed mapping's) with a
 * far plane of 1e30 in clip space, and took any far plane that large as
 * infinite: in the standard mapping, z_w = f/(f-n) (1 - n/d) was then NaN,
 * nothing was drawn, and the run said it had succeeded. Now --far 1e30 and
 * --far 1e29 draw the same faces, and some. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>

#include "test_support.h"

static Image faces_at(const char *lesson, const char *far, const char *dir)
{
    Path id = in_dir(dir, far), out = in_dir(dir, "out.png");
    const char *args[] = {"--width", "64", "--height", "48", "--far", far, "--out", out.path,
                          "--id-out", id.path, NULL};
    free(run_ok(lesson, args));
    return read_png(id.path);
}

static void a_far_plane_of_1e30_is_finite_in_the_standard_mapping(void **state)
{
    (void)state;
    const char *lessons[] = {"06_depth_precision", "07_depth_bias", "10_fast_raster"};
    for (size_t k = 0; k < sizeof lessons / sizeof lessons[0]; k++) {
        const char *dir = test_dir("far_planes");
        Image a = faces_at(lessons[k], "1e29", dir), b = faces_at(lessons[k], "1e30", dir);
        long drawn = 0, differ = 0;
        for (int y = 0; y < a.height; y++)
            for (int x = 0; x < a.width; x++) {
                Rgb p = image_get(&a, x, y), q = image_get(&b, x, y);
                drawn += p.r || p.g || p.b;
                differ += p.r != q.r || p.g != q.g || p.b != q.b;
            }
        if (drawn == 0 || differ != 0)
            fail_msg("%s: --far 1e29 drew %ld pixels, and --far 1e30 differs at %ld", lessons[k],
                     drawn, differ);
        image_free(&a);
        image_free(&b);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_far_plane_of_1e30_is_finite_in_the_standard_mapping),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
