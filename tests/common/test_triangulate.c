/* test_triangulate.c: Newell's normal and ear clipping (common/harness/triangulate.c).
 *
 * Each polygon's area and shape is worked out by hand in its comment; the
 * triangles must cover exactly that area, wind the way the polygon does, and
 * stay inside it. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include "harness/mesh_build.h"

/* Twice the signed area of a 2-D triangle in the xy plane. */
static double area2(Vec3 a, Vec3 b, Vec3 c)
{
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

static void assert_tri(Tri t, int a, int b, int c)
{
    if (t.c[0] != a || t.c[1] != b || t.c[2] != c)
        fail_msg("triangle (%d, %d, %d), expected (%d, %d, %d)", t.c[0], t.c[1], t.c[2], a, b, c);
}

/* Each corner number is used, no triangle repeats one, and each winds the
 * way the polygon does (counter-clockwise in xy, all of ours). Returns the sum
 * of the triangles' areas. */
static double check_triangles(const Vec3 *p, int n, const Tri *t)
{
    double sum = 0;
    for (int i = 0; i < n - 2; i++) {
        for (int k = 0; k < 3; k++)
            if (t[i].c[k] < 0 || t[i].c[k] >= n)
                fail_msg("triangle %d has corner number %d (polygon of %d)", i, t[i].c[k], n);
        if (t[i].c[0] == t[i].c[1] || t[i].c[1] == t[i].c[2] || t[i].c[0] == t[i].c[2])
            fail_msg("triangle %d repeats a corner", i);
        double a = area2(p[t[i].c[0]], p[t[i].c[1]], p[t[i].c[2]]) / 2;
        if (a < -1e-12)
            fail_msg("triangle %d (%d %d %d) winds backwards: area %g", i, t[i].c[0], t[i].c[1],
                     t[i].c[2], a);
        sum += a;
    }
    return sum;
}

static void normal_of_a_unit_square_is_twice_its_area(void **state)
{
    (void)state;
    /* Newell's normal has length twice the area, along the right-hand normal. */
    const Vec3 sq[4] = {{0, 0, 5}, {1, 0, 5}, {1, 1, 5}, {0, 1, 5}};
    Vec3 n = polygon_normal(sq, 4);
    assert_true(n.x == 0 && n.y == 0 && n.z == 2);
    const Vec3 line[3] = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
    n = polygon_normal(line, 3);
    assert_true(n.x == 0 && n.y == 0 && n.z == 0);
}

static void convex_quad_is_a_fan_from_corner_0(void **state)
{
    (void)state;
    const Vec3 q[4] = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}};
    Tri t[2];
    bool convex = false;
    assert_int_equal(triangulate_polygon(q, 4, t, &convex), 2);
    assert_true(convex);
    assert_tri(t[0], 0, 1, 2);
    assert_tri(t[1], 0, 2, 3);
}

static void triangle_is_itself(void **state)
{
    (void)state;
    const Vec3 p[3] = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}};
    Tri t[1];
    bool convex = false;
    assert_int_equal(triangulate_polygon(p, 3, t, &convex), 1);
    assert_tri(t[0], 0, 1, 2);
    assert_true(convex);
}

/* The L: the unit squares [0,1]x[0,1], [1,2]x[0,1] and [0,1]x[1,2]. */
static bool inside_l(double x, double y)
{
    return (x > 0 && x < 2 && y > 0 && y < 1) || (x > 0 && x < 1 && y > 0 && y < 2);
}

static void l_shaped_hexagon_is_cut_inside_the_l(void **state)
{
    (void)state;
    /*  (0,2) +--+ (1,2)
     *        |  |
     *        |  +--+ (2,1)      corner 3, (1,1), turns right: the L is not convex
     *        |     |
     *  (0,0) +-----+ (2,0)      area = 3 unit squares = 3 */
    const Vec3 l[6] = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
    Tri t[4];
    bool convex = true;
    assert_int_equal(triangulate_polygon(l, 6, t, &convex), 4);
    assert_false(convex);
    assert_true(fabs(check_triangles(l, 6, t) - 3.0) < 1e-12);
    /* Every triangle lies in the L: its centroid and a point near each corner
     * (weights 4/6, 1/6, 1/6) are inside. A triangle across the notch, such
     * as (2,1) (1,2) (0,0), has its centroid at (1,1), outside. */
    for (int i = 0; i < 4; i++) {
        Vec3 a = l[t[i].c[0]], b = l[t[i].c[1]], c = l[t[i].c[2]];
        double w[4][3] = {{1 / 3.0, 1 / 3.0, 1 / 3.0}, {4 / 6.0, 1 / 6.0, 1 / 6.0},
                          {1 / 6.0, 4 / 6.0, 1 / 6.0}, {1 / 6.0, 1 / 6.0, 4 / 6.0}};
        for (int k = 0; k < 4; k++) {
            double x = w[k][0] * a.x + w[k][1] * b.x + w[k][2] * c.x;
            double y = w[k][0] * a.y + w[k][1] * b.y + w[k][2] * c.y;
            if (!inside_l(x, y))
                fail_msg("triangle %d (%d %d %d) leaves the L at (%g, %g)", i, t[i].c[0],
                         t[i].c[1], t[i].c[2], x, y);
        }
    }
}

static void l_shape_in_another_plane_keeps_its_winding(void **state)
{
    (void)state;
    /* The same L in the plane y = 3, as (x, 3, z) with z = the L's y. Seen from
     * +y it winds clockwise, so the triangles must too: each triangle's normal
     * points the way the polygon's does (-y). */
    Vec3 l[6] = {{0, 3, 0}, {2, 3, 0}, {2, 3, 1}, {1, 3, 1}, {1, 3, 2}, {0, 3, 2}};
    Tri t[4];
    bool convex = true;
    triangulate_polygon(l, 6, t, &convex);
    assert_false(convex);
    Vec3 n = polygon_normal(l, 6);
    assert_true(n.y < 0);
    double total = 0;
    for (int i = 0; i < 4; i++) {
        Vec3 tri[3] = {l[t[i].c[0]], l[t[i].c[1]], l[t[i].c[2]]};
        Vec3 tn = polygon_normal(tri, 3);
        if (tn.y > 1e-12)
            fail_msg("triangle %d winds against the polygon", i);
        total += -tn.y / 2;
    }
    assert_true(fabs(total - 3.0) < 1e-12);
}

static void five_pointed_star_is_cut_into_eight_triangles(void **state)
{
    (void)state;
    /* Outer corners at radius R = 2, inner ones at r = 0.8, alternating every
     * 36 degrees. The star is 10 triangles (centre, outer, inner) of area
     * R r sin(36 deg) / 2 each: 5 R r sin(36 deg) = 8 sin(36 deg) = 4.70228... */
    Vec3 s[10];
    for (int i = 0; i < 10; i++) {
        double a = i * 36.0 * PI / 180.0;
        double rad = i % 2 ? 0.8 : 2.0;
        s[i] = vec3(rad * cos(a), rad * sin(a), 0);
    }
    Tri t[8];
    bool convex = true;
    assert_int_equal(triangulate_polygon(s, 10, t, &convex), 8);
    assert_false(convex);
    double expected = 8 * sin(36.0 * PI / 180.0);
    double got = check_triangles(s, 10, t);
    if (fabs(got - expected) > 1e-9)
        fail_msg("triangles cover %.12g, the star is %.12g", got, expected);
}

static void repeated_corner_keeps_a_square_convex(void **state)
{
    (void)state;
    /* Corner 1 and 2 are the same point: the square is still convex, its
     * 5 - 2 = 3 triangles still cover its area 1 (one of them flat). */
    const Vec3 q[5] = {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    Tri t[3];
    bool convex = false;
    assert_int_equal(triangulate_polygon(q, 5, t, &convex), 3);
    assert_true(convex);
    assert_true(fabs(check_triangles(q, 5, t) - 1.0) < 1e-12);
}

static void collinear_corners_on_an_edge_stay_convex(void **state)
{
    (void)state;
    /* A 2x2 square with an extra corner halfway along two edges: area 4. */
    const Vec3 q[6] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {0, 1, 0}};
    Tri t[4];
    bool convex = false;
    assert_int_equal(triangulate_polygon(q, 6, t, &convex), 4);
    assert_true(convex);
    assert_true(fabs(check_triangles(q, 6, t) - 4.0) < 1e-12);
}

static void collinear_polygon_gets_a_fan(void **state)
{
    (void)state;
    /* All corners on one line: no plane, no area, but no face is lost either. */
    const Vec3 p[5] = {{0, 0, 0}, {1, 1, 1}, {3, 3, 3}, {2, 2, 2}, {-1, -1, -1}};
    Tri t[3];
    bool convex = true;
    assert_int_equal(triangulate_polygon(p, 5, t, &convex), 3);
    assert_false(convex);
    assert_tri(t[0], 0, 1, 2);
    assert_tri(t[1], 0, 2, 3);
    assert_tri(t[2], 0, 3, 4);
}

static void pentagram_turns_left_everywhere_but_is_not_convex(void **state)
{
    (void)state;
    /* Corners of a regular pentagon taken every second one: each turn is a
     * left turn, but the outline goes round twice. */
    Vec3 p[5];
    for (int i = 0; i < 5; i++) {
        double a = (i * 2 % 5) * 72.0 * PI / 180.0;
        p[i] = vec3(cos(a), sin(a), 0);
    }
    Tri t[3];
    bool convex = true;
    assert_int_equal(triangulate_polygon(p, 5, t, &convex), 3);
    assert_false(convex);
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++)
            assert_true(t[i].c[k] >= 0 && t[i].c[k] < 5);
}

/* The biggest faces a file may hold: each gets n - 2 triangles that wind the
 * polygon's way and cover its area, within a fraction of a second. */
static void largest_polygons_are_cut_right(void **state)
{
    (void)state;
    int n = MESH_MAX_FACE_VERTICES;
    Vec3 *p = malloc(sizeof *p * (size_t)n);
    Tri *t = malloc(sizeof *t * (size_t)n);
    assert_non_null(p);
    assert_non_null(t);
    bool convex = false;

    /* A circle: convex. */
    for (int i = 0; i < n; i++)
        p[i] = vec3(cos(2 * PI * i / n), sin(2 * PI * i / n), 0);
    assert_int_equal(triangulate_polygon(p, n, t, &convex), n - 2);
    assert_true(convex);
    check_triangles(p, n, t);

    /* A comb: a bar [0, 2T] x [-1, 0] with T teeth [2j+1, 2j+2] x [0, 10] on
     * top, walked counter-clockwise: along the bottom, then right to left over
     * the teeth. 2 + 4T corners; those at the feet of the teeth (2T - 1 of
     * them) turn right. Area: the bar 2T plus T teeth of 10, 12T. */
    int teeth = (n - 2) / 4, k = 0;
    p[k++] = vec3(0, -1, 0);
    p[k++] = vec3(2 * teeth, -1, 0);
    for (int i = teeth - 1; i >= 0; i--) {
        p[k++] = vec3(2 * i + 2, 10, 0);
        p[k++] = vec3(2 * i + 1, 10, 0);
        p[k++] = vec3(2 * i + 1, 0, 0);
        p[k++] = vec3(2 * i, 0, 0);
    }
    assert_int_equal(triangulate_polygon(p, k, t, &convex), k - 2);
    assert_false(convex);
    double area = check_triangles(p, k, t);
    if (fabs(area - 12.0 * teeth) > 1e-6)
        fail_msg("comb triangles cover %g, the comb is %d", area, 12 * teeth);

    /* A spiral band 0.3 wide, 16 turns: out along its outer edge
     * (r = 1.3 + a), back along its inner one (r = 1 + a), a in steps of 0.05.
     * Half its corners turn right and ears are few: the hardest real case. */
    int half = n / 2;
    for (int i = 0; i < half; i++) {
        double a = 0.05 * i;
        p[i] = vec3((1.3 + a) * cos(a), (1.3 + a) * sin(a), 0);
        p[n - 1 - i] = vec3((1 + a) * cos(a), (1 + a) * sin(a), 0);
    }
    assert_int_equal(triangulate_polygon(p, n, t, &convex), n - 2);
    assert_false(convex);
    double shoelace = 0; /* the polygon's area, by the shoelace formula */
    for (int i = 0; i < n; i++)
        shoelace += (p[i].x * p[(i + 1) % n].y - p[(i + 1) % n].x * p[i].y) / 2;
    area = check_triangles(p, n, t);
    if (fabs(area - shoelace) > 1e-6 * shoelace)
        fail_msg("spiral triangles cover %.9g, the spiral is %.9g", area, shoelace);
    free(p);
    free(t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(normal_of_a_unit_square_is_twice_its_area),
        cmocka_unit_test(convex_quad_is_a_fan_from_corner_0),
        cmocka_unit_test(triangle_is_itself),
        cmocka_unit_test(l_shaped_hexagon_is_cut_inside_the_l),
        cmocka_unit_test(l_shape_in_another_plane_keeps_its_winding),
        cmocka_unit_test(five_pointed_star_is_cut_into_eight_triangles),
        cmocka_unit_test(repeated_corner_keeps_a_square_convex),
        cmocka_unit_test(collinear_corners_on_an_edge_stay_convex),
        cmocka_unit_test(collinear_polygon_gets_a_fan),
        cmocka_unit_test(pentagram_turns_left_everywhere_but_is_not_convex),
        cmocka_unit_test(largest_polygons_are_cut_right),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
