/* test_far_planes.c: the near and far planes a run gets.
 *
 * A far plane is finite unless it is --far inf. Lessons 06, 07 and 10
 * stand for --far inf (the reversed mapping's) with a far plane of 1e30 in
 * clip space, and took any far plane that large as infinite: in the
 * standard mapping, z_w = f/(f-n) (1 - n/d) was then NaN, nothing was
 * drawn, and the run said it had succeeded. Now --far 1e30 and --far 1e29
 * draw the same faces, and some. A --near at or beyond that stand-in, with
 * --far inf, used to be refused as "--far: 1e+30 is out of range (far must
 * be greater than near, 1e+30)", a far plane the user never typed: the
 * message now names --near and why.
 *
 * An OBJ seen from an eye given with --eye, without --near or --far, gets
 * its planes fitted to that eye, not to the camera --obj would have chosen:
 * from inside a cube, or 20 units from it, the picture used to be blank,
 * the model outside the planes, and the run exited 0.
 *
 * A small model far from the origin is drawn as it is at the origin: a unit
 * triangle in the plane x = 1e17 used to be drawn by no pixel, the fitted
 * eye rounded into that plane, and the run exited 0. */
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

static void a_near_plane_past_the_stand_in_for_far_inf_is_named(void **state)
{
    (void)state;
    const char *dir = test_dir("far_inf_near");
    Path out = in_dir(dir, "out.png");
    const char *lessons[] = {"06_depth_precision", "07_depth_bias", "10_fast_raster"};
    const char *nears[][2] = {{"1e30", "1e+30"}, {"5e30", "5e+30"}};
    for (size_t k = 0; k < sizeof lessons / sizeof lessons[0]; k++)
        for (int n = 0; n < 2; n++) {
            const char *args[] = {"--depth-mapping", "reversed", "--near", nears[n][0], "--far",
                                  "inf", "--out", out.path, NULL};
            char want[160];
            snprintf(want, sizeof want, "--near: %s is out of range: with --far inf, near must "
                     "be below 1e+30", nears[n][1]);
            expect_run_refused(lessons[k], args, 2, want, out.path);
        }
}

/* --near alone past the far plane the scene gave: the message names --near,
 * which was given, not --far, which was not. */
static void one_plane_past_the_scenes_other_is_named(void **state)
{
    (void)state;
    const char *dir = test_dir("one_plane");
    Path out = in_dir(dir, "out.png");
    const char *near_args[] = {"--scene", "triangles3", "--near", "1e6", "--out", out.path, NULL};
    expect_run_refused("05_clipping", near_args, 2, "--near: 1e+06 is out of range (not before "
                       "the far plane of the scene or model, 100: give --far too)", out.path);
}

/* A cube 2 units wide at the origin. From inside it the face at z = -1
 * (face 0) fills the view; from 20 units away the face at z = +1 (face 1)
 * shows at the centre, and the corners are background. */
static void planes_are_fitted_to_the_eye_given(void **state)
{
    (void)state;
    const char *dir = test_dir("eye_planes");
    Path obj = in_dir(dir, "cube.obj"), ids = in_dir(dir, "ids.png"), out = in_dir(dir, "out.png");
    write_text(obj.path, "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\n"
                         "v -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
                         "f 1 2 3 4\nf 5 6 7 8\nf 1 2 6 5\nf 4 3 7 8\nf 1 4 8 5\nf 2 3 7 6\n");
    const char *lessons[] = {"05_clipping", "10_fast_raster"};
    const char *eyes[][2] = {{"0,0,0", "0,0,-1"}, {"0,0,20", "0,0,0"}};
    const int32_t centre[] = {0, 1}, corner[] = {0, NO_FACE};
    for (size_t k = 0; k < sizeof lessons / sizeof lessons[0]; k++)
        for (int e = 0; e < 2; e++) {
            const char *args[] = {"--obj", obj.path, "--eye", eyes[e][0], "--target", eyes[e][1],
                                  "--width", "64", "--height", "48", "--out", out.path,
                                  "--id-out", ids.path, NULL};
            free(run_ok(lessons[k], args));
            Image im = read_png(ids.path);
            char what[128];
            snprintf(what, sizeof what, "%s from %s, the centre", lessons[k], eyes[e][0]);
            expect_face_at(&im, 32, 24, centre[e], what);
            snprintf(what, sizeof what, "%s from %s, a corner", lessons[k], eyes[e][0]);
            expect_face_at(&im, 0, 0, corner[e], what);
            image_free(&im);
        }
}

/* The face picture of a unit triangle in the plane x = X, framed by --obj. */
static Image triangle_at(const char *lesson, const char *x, const char *dir)
{
    Path obj = in_dir(dir, "far.obj"), ids = in_dir(dir, "ids.png"), out = in_dir(dir, "out.png");
    char text[256];
    snprintf(text, sizeof text, "v %s 0 0\nv %s 1 0\nv %s 0 1\nf 1 2 3\n", x, x, x);
    write_text(obj.path, text);
    const char *args[] = {"--obj", obj.path, "--width", "64", "--height", "48", "--out", out.path,
                          "--id-out", ids.path, NULL};
    free(run_ok(lesson, args));
    return read_png(ids.path);
}

static void a_small_model_far_from_the_origin_is_drawn(void **state)
{
    (void)state;
    const char *dir = test_dir("far_model");
    const char *lessons[] = {"03_perspective_z", "05_clipping", "10_fast_raster"};
    const char *far[] = {"1e16", "1e17", "1e30"};
    for (size_t k = 0; k < sizeof lessons / sizeof lessons[0]; k++) {
        Image near = triangle_at(lessons[k], "0", dir);
        long drawn = 0;
        for (int y = 0; y < near.height; y++)
            for (int x = 0; x < near.width; x++) {
                Rgb p = image_get(&near, x, y);
                drawn += p.r || p.g || p.b;
            }
        if (drawn == 0)
            fail_msg("%s: the triangle at x = 0 drew no pixel", lessons[k]);
        for (size_t f = 0; f < sizeof far / sizeof far[0]; f++) {
            Image a = triangle_at(lessons[k], far[f], dir);
            long differ = 0;
            for (int y = 0; y < a.height; y++)
                for (int x = 0; x < a.width; x++) {
                    Rgb p = image_get(&near, x, y), q = image_get(&a, x, y);
                    differ += p.r != q.r || p.g != q.g || p.b != q.b;
                }
            if (differ != 0)
                fail_msg("%s: the triangle at x = %s differs from the one at x = 0 at %ld of "
                         "its %ld pixels", lessons[k], far[f], differ, drawn);
            image_free(&a);
        }
        image_free(&near);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_far_plane_of_1e30_is_finite_in_the_standard_mapping),
        cmocka_unit_test(a_near_plane_past_the_stand_in_for_far_inf_is_named),
        cmocka_unit_test(planes_are_fitted_to_the_eye_given),
        cmocka_unit_test(one_plane_past_the_scenes_other_is_named),
        cmocka_unit_test(a_small_model_far_from_the_origin_is_drawn),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
