/* test_vecmath.c: vectors, matrices, look_at and perspective against values
 * worked out by hand in the comments. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <stdio.h>

#include "vecmath.h"

#define TOLERANCE 1e-12

#define expect_near(actual, expected, what)                                             \
    do {                                                                                \
        double a_ = (actual), e_ = (expected);                                          \
        if (!(fabs(a_ - e_) <= TOLERANCE))                                              \
            fail_msg("%s: got %.17g, expected %.17g", (what), a_, e_);                  \
    } while (0)

static void expect_vec3(Vec3 v, double x, double y, double z, const char *what)
{
    char label[128];
    snprintf(label, sizeof label, "%s.x", what);
    expect_near(v.x, x, label);
    snprintf(label, sizeof label, "%s.y", what);
    expect_near(v.y, y, label);
    snprintf(label, sizeof label, "%s.z", what);
    expect_near(v.z, z, label);
}

/* Every entry of m against the 16 values of want, row by row. */
static void expect_matrix(Mat4 m, const double want[4][4], const char *what)
{
    char label[128];
    for (int r = 0; r < 4; r++)
        for (int c = 0; c < 4; c++) {
            snprintf(label, sizeof label, "%s[row %d][col %d]", what, r, c);
            expect_near(m.m[r][c], want[r][c], label);
        }
}

static Vec3 transform_point(Mat4 m, Vec3 p)
{
    Vec4 v = mat4_mul_vec4(m, vec4(p.x, p.y, p.z, 1));
    return vec3(v.x, v.y, v.z);
}

static void cross_follows_right_hand_rule(void **state)
{
    (void)state;
    /* x cross y = z, y cross z = x, z cross x = y; swapping the order flips the sign. */
    expect_vec3(vec3_cross(vec3(1, 0, 0), vec3(0, 1, 0)), 0, 0, 1, "x cross y");
    expect_vec3(vec3_cross(vec3(0, 1, 0), vec3(0, 0, 1)), 1, 0, 0, "y cross z");
    expect_vec3(vec3_cross(vec3(0, 0, 1), vec3(1, 0, 0)), 0, 1, 0, "z cross x");
    expect_vec3(vec3_cross(vec3(0, 1, 0), vec3(1, 0, 0)), 0, 0, -1, "y cross x");
    /* (1,2,3) x (4,5,6) = (2*6 - 3*5, 3*4 - 1*6, 1*5 - 2*4) = (-3, 6, -3) */
    expect_vec3(vec3_cross(vec3(1, 2, 3), vec3(4, 5, 6)), -3, 6, -3, "(1,2,3) x (4,5,6)");
}

static void dot_length_and_sums(void **state)
{
    (void)state;
    /* (1,2,3).(4,-5,6) = 4 - 10 + 18 = 12 */
    expect_near(vec3_dot(vec3(1, 2, 3), vec3(4, -5, 6)), 12, "dot");
    /* |(2,3,6)| = sqrt(4 + 9 + 36) = 7 */
    expect_near(vec3_length(vec3(2, 3, 6)), 7, "length of (2,3,6)");
    expect_vec3(vec3_add(vec3(1, 2, 3), vec3(10, 20, 30)), 11, 22, 33, "add");
    expect_vec3(vec3_sub(vec3(1, 2, 3), vec3(10, 20, 30)), -9, -18, -27, "sub");
    expect_vec3(vec3_scale(vec3(1, -2, 3), -2), -2, 4, -6, "scale");
}

static void normalize_gives_unit_length_and_keeps_zero(void **state)
{
    (void)state;
    /* (2,3,6) / 7 */
    expect_vec3(vec3_normalize(vec3(2, 3, 6)), 2.0 / 7, 3.0 / 7, 6.0 / 7, "normalize (2,3,6)");
    expect_vec3(vec3_normalize(vec3(0, 0, 0)), 0, 0, 0, "normalize of zero");
}

static void mat4_mul_is_row_by_column_in_order(void **state)
{
    (void)state;
    /* T = translate(1,2,3), S = scale(2,3,4).
     * T * S scales first, then translates: the diagonal of S, last column (1,2,3).
     * S * T translates first, then scales: last column (2*1, 3*2, 4*3) = (2,6,12). */
    Mat4 t = {{{1, 0, 0, 1}, {0, 1, 0, 2}, {0, 0, 1, 3}, {0, 0, 0, 1}}};
    Mat4 s = {{{2, 0, 0, 0}, {0, 3, 0, 0}, {0, 0, 4, 0}, {0, 0, 0, 1}}};
    const double ts[4][4] = {{2, 0, 0, 1}, {0, 3, 0, 2}, {0, 0, 4, 3}, {0, 0, 0, 1}};
    const double st[4][4] = {{2, 0, 0, 2}, {0, 3, 0, 6}, {0, 0, 4, 12}, {0, 0, 0, 1}};
    expect_matrix(mat4_mul(t, s), ts, "T*S");
    expect_matrix(mat4_mul(s, t), st, "S*T");

    /* A dense pair: A[r][c] = 4r + c + 1, B = the permutation that swaps
     * columns 0 and 3 when multiplied on the right (B[0][3] = B[3][0] = 1,
     * B[1][1] = B[2][2] = 1): A * B is A with its first and last columns swapped. */
    Mat4 a = {{{1, 2, 3, 4}, {5, 6, 7, 8}, {9, 10, 11, 12}, {13, 14, 15, 16}}};
    Mat4 b = {{{0, 0, 0, 1}, {0, 1, 0, 0}, {0, 0, 1, 0}, {1, 0, 0, 0}}};
    const double ab[4][4] = {{4, 2, 3, 1}, {8, 6, 7, 5}, {12, 10, 11, 9}, {16, 14, 15, 13}};
    /* B * A swaps A's first and last rows instead. */
    const double ba[4][4] = {{13, 14, 15, 16}, {5, 6, 7, 8}, {9, 10, 11, 12}, {1, 2, 3, 4}};
    expect_matrix(mat4_mul(a, b), ab, "A*B");
    expect_matrix(mat4_mul(b, a), ba, "B*A");
    expect_matrix(mat4_mul(a, mat4_identity()), (const double(*)[4])a.m, "A*I");
}

static void mat4_mul_vec4_applies_translation_to_points_only(void **state)
{
    (void)state;
    Mat4 t = {{{1, 0, 0, 1}, {0, 1, 0, 2}, {0, 0, 1, 3}, {0, 0, 0, 1}}};
    /* point (1,1,1,1) -> (2,3,4,1); direction (1,1,1,0) -> unchanged */
    Vec4 p = mat4_mul_vec4(t, vec4(1, 1, 1, 1));
    Vec4 d = mat4_mul_vec4(t, vec4(1, 1, 1, 0));
    expect_near(p.x, 2, "point.x");
    expect_near(p.y, 3, "point.y");
    expect_near(p.z, 4, "point.z");
    expect_near(p.w, 1, "point.w");
    expect_near(d.x, 1, "direction.x");
    expect_near(d.w, 0, "direction.w");
}

static void look_at_from_plus_z_is_a_translation(void **state)
{
    (void)state;
    /* eye (0,0,5), target origin, up +y:
     *   f = normalize((0,0,0) - (0,0,5)) = (0,0,-1)
     *   s = normalize(f x up) = (0,0,-1) x (0,1,0) = (0*0 - (-1)*1, (-1)*0 - 0*0, 0) = (1,0,0)
     *   u = s x f = (1,0,0) x (0,0,-1) = (0*(-1) - 0*0, 0*0 - 1*(-1), 0) = (0,1,0)
     * rows s, u, -f = identity; translation (-s.eye, -u.eye, f.eye) = (0, 0, -5). */
    const double want[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, -5}, {0, 0, 0, 1}};
    Mat4 view = look_at(vec3(0, 0, 5), vec3(0, 0, 0), vec3(0, 1, 0));
    expect_matrix(view, want, "look_at from (0,0,5)");
    /* The target is 5 units in front: z_view = -5, d = 5. */
    expect_vec3(transform_point(view, vec3(0, 0, 0)), 0, 0, -5, "target in view space");
}

static void look_at_from_plus_x_turns_the_world(void **state)
{
    (void)state;
    /* eye (5,0,0), target origin, up +y:
     *   f = (-1,0,0)
     *   s = f x up = (-1,0,0) x (0,1,0) = (0*0 - 0*1, 0*0 - (-1)*0, (-1)*1 - 0*0) = (0,0,-1)
     *   u = s x f = (0,0,-1) x (-1,0,0) = (0*0 - (-1)*0, (-1)*(-1) - 0*0, 0*0 - 0*(-1)) = (0,1,0)
     *   rows: s = (0,0,-1), u = (0,1,0), -f = (1,0,0)
     *   translation: -s.eye = 0, -u.eye = 0, f.eye = -5
     * So x_view = -z, y_view = y, z_view = x - 5: world +x (towards the eye)
     * becomes view +z, world -z is the camera's right. */
    const double want[4][4] = {{0, 0, -1, 0}, {0, 1, 0, 0}, {1, 0, 0, -5}, {0, 0, 0, 1}};
    Mat4 view = look_at(vec3(5, 0, 0), vec3(0, 0, 0), vec3(0, 1, 0));
    expect_matrix(view, want, "look_at from (5,0,0)");
    expect_vec3(transform_point(view, vec3(5, 0, 0)), 0, 0, 0, "eye goes to the origin");
    expect_vec3(transform_point(view, vec3(1, 2, 3)), -3, 2, -4, "(1,2,3) in view space");
}

static void look_at_keeps_up_in_the_view_plane_when_tilted(void **state)
{
    (void)state;
    /* eye (0,0,5), target origin, up (1,1,0) (not perpendicular to f is fine):
     *   f = (0,0,-1); f x up = (0*0 - (-1)*1, (-1)*1 - 0*0, 0) = (1,-1,0)
     *   s = (1,-1,0)/sqrt2; u = s x f = ((-1)(-1) - 0, 0 - 1*(-1), 0)/sqrt2 = (1,1,0)/sqrt2
     * The world point (1,1,0) lies straight up on screen: x_view 0, y_view sqrt2. */
    Mat4 view = look_at(vec3(0, 0, 5), vec3(0, 0, 0), vec3(1, 1, 0));
    expect_vec3(transform_point(view, vec3(1, 1, 0)), 0, sqrt(2.0), -5, "(1,1,0) in view space");
}

static void perspective_matches_glu_entries(void **state)
{
    (void)state;
    /* fovy 90, aspect 2, near 1, far 3:
     *   f = cot(45 degrees) = 1
     *   [0][0] = f / aspect = 0.5, [1][1] = f = 1
     *   [2][2] = (far + near) / (near - far) = 4 / -2 = -2
     *   [2][3] = 2 * far * near / (near - far) = 6 / -2 = -3
     *   [3][2] = -1 */
    const double want[4][4] = {{0.5, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, -2, -3}, {0, 0, -1, 0}};
    expect_matrix(perspective(90, 2, 1, 3), want, "perspective(90, 2, 1, 3)");
}

static void perspective_maps_near_to_minus_one_and_far_to_plus_one(void **state)
{
    (void)state;
    Mat4 p = perspective(90, 2, 1, 3);
    /* near plane, z_view = -1: z_clip = -2*(-1) - 3 = -1, w = 1 -> z_ndc = -1 */
    Vec4 n = mat4_mul_vec4(p, vec4(0, 0, -1, 1));
    expect_near(n.w, 1, "w_clip on the near plane (= d)");
    expect_near(n.z / n.w, -1, "z_ndc on the near plane");
    /* far plane, z_view = -3: z_clip = -2*(-3) - 3 = 3, w = 3 -> z_ndc = +1 */
    Vec4 f = mat4_mul_vec4(p, vec4(0, 0, -3, 1));
    expect_near(f.w, 3, "w_clip on the far plane (= d)");
    expect_near(f.z / f.w, 1, "z_ndc on the far plane");
    /* the corner of the near plane: half height near*tan(45) = 1, half width 2
     * -> (x_ndc, y_ndc) = (1, 1) */
    Vec4 c = mat4_mul_vec4(p, vec4(2, 1, -1, 1));
    expect_near(c.x / c.w, 1, "x_ndc at the near plane's right edge");
    expect_near(c.y / c.w, 1, "y_ndc at the near plane's top edge");
}

static void perspective_of_60_degrees(void **state)
{
    (void)state;
    /* fovy 60: f = cot(30 degrees) = sqrt(3) */
    Mat4 p = perspective(60, 1, 0.5, 10);
    expect_near(p.m[1][1], sqrt(3.0), "f for fovy 60");
    expect_near(p.m[0][0], sqrt(3.0), "f / aspect for aspect 1");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(cross_follows_right_hand_rule),
        cmocka_unit_test(dot_length_and_sums),
        cmocka_unit_test(normalize_gives_unit_length_and_keeps_zero),
        cmocka_unit_test(mat4_mul_is_row_by_column_in_order),
        cmocka_unit_test(mat4_mul_vec4_applies_translation_to_points_only),
        cmocka_unit_test(look_at_from_plus_z_is_a_translation),
        cmocka_unit_test(look_at_from_plus_x_turns_the_world),
        cmocka_unit_test(look_at_keeps_up_in_the_view_plane_when_tilted),
        cmocka_unit_test(perspective_matches_glu_entries),
        cmocka_unit_test(perspective_maps_near_to_minus_one_and_far_to_plus_one),
        cmocka_unit_test(perspective_of_60_degrees),
    };
    return cmocka_run_group_tests_name("vecmath", tests, NULL, NULL);
}
