/* test_camera.c: world -> view -> clip -> NDC -> screen, checked at points whose
 * screen position follows from the frustum's shape alone.
 *
 * The camera of most tests: eye (0,0,5) looking at the origin, up +y, fovy 90,
 * near 1, far 100, a 200 x 100 image (aspect 2). look_at is then a shift by -5
 * in z, so a world point (x, y, 0) is 5 units in front of the eye (d = 5).
 * At that depth the frustum reaches d * tan(45 degrees) = 5 up and down and
 * aspect * 5 = 10 left and right. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>

#include "camera.h"

#define TOLERANCE 1e-9
#define W 200
#define H 100

#define expect_near(actual, expected, what)                                             \
    do {                                                                                \
        double a_ = (actual), e_ = (expected);                                          \
        if (!(fabs(a_ - e_) <= TOLERANCE))                                              \
            fail_msg("%s: got %.17g, expected %.17g", (what), a_, e_);                  \
    } while (0)

static Camera front_camera(void)
{
    Camera c;
    camera_init(&c, vec3(0, 0, 5), vec3(0, 0, 0), vec3(0, 1, 0), 90, 1, 100, W, H);
    return c;
}

static void camera_init_uses_width_over_height_as_aspect(void **state)
{
    (void)state;
    Camera c = front_camera();
    /* f = cot(45 degrees) = 1; proj[0][0] = f / aspect = 1 / (200 / 100) = 0.5 */
    expect_near(c.proj.m[0][0], 0.5, "proj[0][0] = f / aspect");
    expect_near(c.proj.m[1][1], 1, "proj[1][1] = f");
    assert_int_equal(c.width, W);
    assert_int_equal(c.height, H);
    expect_near(c.near, 1, "near");
    expect_near(c.far, 100, "far");
}

static void point_straight_ahead_lands_in_the_image_centre(void **state)
{
    (void)state;
    Camera c = front_camera();
    /* origin: NDC (0, 0) -> x_s = (0 + 1) * 200 / 2 = 100, y_s = (1 - 0) * 100 / 2 = 50 */
    ScreenVertex v = camera_project(&c, vec3(0, 0, 0));
    expect_near(v.x, W / 2.0, "x_s of a point straight ahead");
    expect_near(v.y, H / 2.0, "y_s of a point straight ahead");
    expect_near(v.d, 5, "d of a point 5 units ahead");
}

static void top_edge_of_the_frustum_is_row_zero(void **state)
{
    (void)state;
    Camera c = front_camera();
    /* (0, 5, 0): y_ndc = 5 / 5 = 1 -> y_s = (1 - 1) * 100 / 2 = 0: the top row, y grows down */
    ScreenVertex top = camera_project(&c, vec3(0, 5, 0));
    expect_near(top.y, 0, "y_s on the top edge of the frustum");
    expect_near(top.x, W / 2.0, "x_s on the top edge, centre column");
    /* (0, -5, 0): y_ndc = -1 -> y_s = 2 * 100 / 2 = 100 = H, the bottom edge */
    ScreenVertex bottom = camera_project(&c, vec3(0, -5, 0));
    expect_near(bottom.y, H, "y_s on the bottom edge of the frustum");
    /* (0, -2.5, 0): y_ndc = -0.5 -> y_s = 1.5 * 50 = 75: below the centre */
    ScreenVertex below = camera_project(&c, vec3(0, -2.5, 0));
    expect_near(below.y, 75, "y_s of a point below the centre");
}

static void right_edge_of_the_frustum_is_x_equal_width(void **state)
{
    (void)state;
    Camera c = front_camera();
    /* (10, 0, 0): x_clip = 0.5 * 10 = 5, w = 5 -> x_ndc = 1 -> x_s = 2 * 200 / 2 = 200 = W */
    ScreenVertex right = camera_project(&c, vec3(10, 0, 0));
    expect_near(right.x, W, "x_s on the right edge of the frustum");
    /* (-10, 0, 0): x_ndc = -1 -> x_s = 0 */
    ScreenVertex left = camera_project(&c, vec3(-10, 0, 0));
    expect_near(left.x, 0, "x_s on the left edge of the frustum");
    /* (2.5, 0, 0): x_ndc = 0.5 * 2.5 / 5 = 0.25 -> x_s = 1.25 * 100 = 125 */
    ScreenVertex quarter = camera_project(&c, vec3(2.5, 0, 0));
    expect_near(quarter.x, 125, "x_s a quarter of the way to the right edge");
}

static void farther_points_move_towards_the_centre(void **state)
{
    (void)state;
    Camera c = front_camera();
    /* (10, 5, -5): d = 10, the frustum there is 20 wide each way and 10 up:
     * x_ndc = 0.5 * 10 / 10 = 0.5 -> x_s = 150; y_ndc = 5 / 10 = 0.5 -> y_s = 25 */
    ScreenVertex v = camera_project(&c, vec3(10, 5, -5));
    expect_near(v.d, 10, "d of a point 10 units ahead");
    expect_near(v.x, 150, "x_s halves with twice the depth");
    expect_near(v.y, 25, "y_s halves its distance to the centre with twice the depth");
}

static void d_is_the_distance_along_the_view_axis(void **state)
{
    (void)state;
    Camera c = front_camera();
    /* (3, -2, 1): z_view = 1 - 5 = -4, so d = 4 whatever x and y are */
    Vec3 view = camera_to_view(&c, vec3(3, -2, 1));
    expect_near(view.x, 3, "x_view");
    expect_near(view.y, -2, "y_view");
    expect_near(view.z, -4, "z_view");
    expect_near(camera_project(&c, vec3(3, -2, 1)).d, 4, "d = -z_view");

    /* A camera at (5,0,0) looking at the origin: the view axis is world -x,
     * so d = 5 - x for any point: (1, 2, 3) -> d = 4. */
    Camera side;
    camera_init(&side, vec3(5, 0, 0), vec3(0, 0, 0), vec3(0, 1, 0), 90, 1, 100, W, H);
    expect_near(camera_project(&side, vec3(1, 2, 3)).d, 4, "d seen from (5,0,0)");
}

static void point_behind_the_camera_has_no_positive_depth(void **state)
{
    (void)state;
    Camera c = front_camera();
    /* (0, 0, 7) is 2 units behind the eye: d = -2; the caller drops it */
    ScreenVertex behind = camera_project(&c, vec3(0, 0, 7));
    assert_true(behind.d <= 0);
    expect_near(behind.d, -2, "d of a point 2 units behind");
    expect_near(behind.x, 0, "x_s is left at 0 behind the eye");
    expect_near(behind.y, 0, "y_s is left at 0 behind the eye");
    /* (1, 1, 5) is in the eye's own plane: d = 0, no division by zero */
    ScreenVertex level = camera_project(&c, vec3(1, 1, 5));
    expect_near(level.d, 0, "d in the eye's plane");
    assert_true(isfinite(level.x) && isfinite(level.y));
}

static void camera_check_accepts_the_front_camera(void **state)
{
    (void)state;
    Error err = {{0}};
    assert_true(camera_check(vec3(0, 0, 5), vec3(0, 0, 0), vec3(0, 1, 0), 90, 1, 100, W, H,
                             &err));
}

static void camera_check_names_what_is_wrong(void **state)
{
    (void)state;
    Error err = {{0}};
    assert_false(camera_check(vec3(1, 2, 3), vec3(1, 2, 3), vec3(0, 1, 0), 90, 1, 100, W, H,
                              &err));
    assert_string_equal(err.msg, "--eye and --target are the same point");
    assert_false(camera_check(vec3(0, 0, 5), vec3(0, 0, 0), vec3(0, 0, 2), 90, 1, 100, W, H,
                              &err));
    assert_string_equal(err.msg, "--up is parallel to the view direction from --eye to --target");
    assert_false(camera_check(vec3(0, 0, 5), vec3(0, 0, 0), vec3(0, 1, 0), 90, 2, 1, W, H,
                              &err));
    assert_string_equal(err.msg, "--far: 1 is out of range (far must be greater than near, 2)");
    assert_false(camera_check(vec3(0, 0, 5), vec3(0, 0, 0), vec3(0, 1, 0), 180, 1, 100, W, H,
                              &err));
    assert_string_equal(err.msg, "--fovy: 180 is out of range (0 < fovy < 180 degrees)");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(camera_init_uses_width_over_height_as_aspect),
        cmocka_unit_test(point_straight_ahead_lands_in_the_image_centre),
        cmocka_unit_test(top_edge_of_the_frustum_is_row_zero),
        cmocka_unit_test(right_edge_of_the_frustum_is_x_equal_width),
        cmocka_unit_test(farther_points_move_towards_the_centre),
        cmocka_unit_test(d_is_the_distance_along_the_view_axis),
        cmocka_unit_test(point_behind_the_camera_has_no_positive_depth),
        cmocka_unit_test(camera_check_accepts_the_front_camera),
        cmocka_unit_test(camera_check_names_what_is_wrong),
    };
    return cmocka_run_group_tests_name("camera", tests, NULL, NULL);
}
