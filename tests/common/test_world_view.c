/* test_world_view.c: --world-out's picture (common/harness/world_view.h) puts the eye,
 * the near plane and the faces where the framing says, worked out here by hand.
 *
 * The setup: eye (0, 0, 10) looking at the origin, up +Y, fovy 90, near 1,
 * far 20, a 100 x 100 screen (so the horizontal field of view is 90 too), and
 * one triangle (-2,-2,0) (2,-2,0) (0,2,0), i.e. at view depth d = 10 with view
 * x and y in [-2, 2]. The framing then covers d in [0, 10] (the far plane, at
 * 20 > 1.25 * 10, is left off the panel) and heights in [-2, 2] in both panels
 * (the near plane reaches only +-1). Room: 400 - 2 * 28 = 344 pixels, so the
 * scale is min(344 / 10, 344 / 4) = 34.4 pixels per unit, the content is
 * 137.6 pixels tall (no stretch) and centred:
 *     left = 28 (side) and 404 + 28 = 432 (top),   top = 16 + 28 + (344 - 137.6) / 2 = 147.2
 * so the eye (d = 0, height 0) is at x = 28 / 432, y = 147.2 + 2 * 34.4 = 216,
 * the near plane at x = 28 + 34.4 = 62.4, and the triangle, edge-on in both
 * panels, at x = 28 + 344 = 372 / 776, rows 147.2 to 284.8. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>

#include "camera.h"
#include "harness/mesh_build.h"
#include "harness/shade.h"
#include "test_support.h"
#include "harness/world_view.h"

static void one_triangle(Mesh *m, Camera *c)
{
    mesh_init(m);
    int v[3] = {mesh_add_vertex(m, vec3(-2, -2, 0), NULL), mesh_add_vertex(m, vec3(2, -2, 0), NULL),
                mesh_add_vertex(m, vec3(0, 2, 0), NULL)};
    assert_true(mesh_add_face(m, v, 3, -1, NULL) >= 0);
    camera_init(c, vec3(0, 0, 10), vec3(0, 0, 0), vec3(0, 1, 0), 90, 1, 20, 100, 100);
}

static void picture_has_the_documented_size(void **state)
{
    (void)state;
    Mesh m;
    Camera c;
    one_triangle(&m, &c);
    Image im;
    assert_true(world_view_image(&m, &c, &im, NULL));
    expect_count(804, im.width, "world view width (2 panels of 400 and a gap of 4)");
    expect_count(416, im.height, "world view height (a panel of 400 under a title of 16)");
    expect_count(WORLD_VIEW_WIDTH, im.width, "WORLD_VIEW_WIDTH");
    expect_count(WORLD_VIEW_HEIGHT, im.height, "WORLD_VIEW_HEIGHT");
    image_free(&im);
    mesh_free(&m);
}

static void framing_is_the_one_worked_out_by_hand(void **state)
{
    (void)state;
    Mesh m;
    Camera c;
    one_triangle(&m, &c);
    WorldFrame f = world_frame(&m, &c);
    double x, y;
    world_to_picture(&f, WORLD_SIDE, vec3(0, 0, 0), &x, &y);
    assert_true(fabs(x - 28) < 1e-9 && fabs(y - 216) < 1e-9);
    world_to_picture(&f, WORLD_TOP, vec3(0, 0, 0), &x, &y);
    assert_true(fabs(x - 432) < 1e-9 && fabs(y - 216) < 1e-9);
    world_to_picture(&f, WORLD_SIDE, camera_to_view(&c, vec3(0, 2, 0)), &x, &y);
    assert_true(fabs(x - 372) < 1e-9 && fabs(y - 147.2) < 1e-9);
    expect_count(1, f.stretch[WORLD_SIDE], "side view stretch");
    expect_count(1, f.stretch[WORLD_TOP], "top view stretch");
    mesh_free(&m);
}

static void eye_near_plane_and_face_are_drawn_where_the_framing_says(void **state)
{
    (void)state;
    Mesh m;
    Camera c;
    one_triangle(&m, &c);
    Image im;
    assert_true(world_view_image(&m, &c, &im, NULL));
    expect_pixel(&im, 28, 216, WORLD_EYE_COLOUR, "the eye in the side view");
    expect_pixel(&im, 432, 216, WORLD_EYE_COLOUR, "the eye in the top view");
    expect_pixel(&im, 62, 200, WORLD_NEAR_COLOUR, "the near plane in the side view");
    expect_pixel(&im, 466, 232, WORLD_NEAR_COLOUR, "the near plane in the top view");
    Rgb face = face_base_colour(&m, 0);
    expect_pixel(&im, 372, 216, face, "the triangle, edge-on, in the side view");
    expect_pixel(&im, 372, 150, face, "the triangle's top corner in the side view");
    expect_pixel(&im, 776, 260, face, "the triangle, edge-on, in the top view");
    image_free(&im);
    mesh_free(&m);
}

/* Seen from above, a floor is a filled area in its own colour. */
static void face_seen_from_above_is_filled(void **state)
{
    (void)state;
    Mesh m;
    Camera c;
    mesh_init(&m);
    int v[4] = {mesh_add_vertex(&m, vec3(-2, -1, -2), NULL), mesh_add_vertex(&m, vec3(2, -1, -2), NULL),
                mesh_add_vertex(&m, vec3(2, -1, 2), NULL), mesh_add_vertex(&m, vec3(-2, -1, 2), NULL)};
    assert_true(mesh_add_face(&m, v, 4, -1, NULL) >= 0);
    camera_init(&c, vec3(0, 0, 10), vec3(0, 0, 0), vec3(0, 1, 0), 45, 1, 100, 100, 100);
    WorldFrame f = world_frame(&m, &c);
    double x, y;
    world_to_picture(&f, WORLD_TOP, camera_to_view(&c, vec3(0, -1, 0)), &x, &y);
    Image im;
    assert_true(world_view_image(&m, &c, &im, NULL));
    expect_pixel(&im, (int)x, (int)y, face_base_colour(&m, 0), "the middle of the floor from above");
    image_free(&im);
    mesh_free(&m);
}

/* Far-flung corners and a far plane a trillion units away: a picture, no crash. */
static void extreme_scene_still_gives_a_picture(void **state)
{
    (void)state;
    Mesh m;
    Camera c;
    mesh_init(&m);
    int v[3] = {mesh_add_vertex(&m, vec3(-1e30, 0, -1e30), NULL), mesh_add_vertex(&m, vec3(1e30, 1, -1), NULL),
                mesh_add_vertex(&m, vec3(0, -1e30, 5), NULL)};
    assert_true(mesh_add_face(&m, v, 3, -1, NULL) >= 0);
    camera_init(&c, vec3(0, 0, 10), vec3(0, 0, 0), vec3(0, 1, 0), 179, 1e-6, 1e12, 1, 16384);
    Image im;
    assert_true(world_view_image(&m, &c, &im, NULL));
    expect_count(WORLD_VIEW_WIDTH, im.width, "world view width");
    image_free(&im);
    mesh_free(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(picture_has_the_documented_size),
        cmocka_unit_test(framing_is_the_one_worked_out_by_hand),
        cmocka_unit_test(eye_near_plane_and_face_are_drawn_where_the_framing_says),
        cmocka_unit_test(face_seen_from_above_is_filled),
        cmocka_unit_test(extreme_scene_still_gives_a_picture),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
