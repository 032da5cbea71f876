/* test_clip.c: lesson 05's clipping, corner by corner.
 *
 * Each polygon is given in clip space and clipped against the near plane
 * (kept: z_c >= -w_c) and the far plane (kept: z_c <= w_c); the corners the
 * clipper must give back are worked out by hand in the comments, in the
 * order Sutherland-Hodgman gives them: for each edge a -> b (starting with
 * the edge from the last corner to the first), the crossing if the edge
 * crosses the plane, then b if it is inside or on the plane.
 *
 * Then faces through the whole pipeline where the divide would go wrong: a
 * face wholly behind the eye, faces through the eye (w = 0 at a corner), and
 * a camera placed exactly on a face. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include "clipping.h"
#include "harness/render.h"
#include "test_support.h"

#define EPS 1e-12

static void expect_corners(const Vec4 *got, int n, const Vec4 *want, int m, const char *what)
{
    observe_value("corners", n);
    for (int i = 0; i < n && i < m; i++) {
        observe_near(got[i].x, want[i].x, EPS);
        observe_near(got[i].y, want[i].y, EPS);
        observe_near(got[i].z, want[i].z, EPS);
        observe_near(got[i].w, want[i].w, EPS);
    }
    if (n != m)
        fail_msg("%s: %d corners, expected %d", what, n, m);
    for (int i = 0; i < n; i++)
        if (fabs(got[i].x - want[i].x) > EPS || fabs(got[i].y - want[i].y) > EPS ||
            fabs(got[i].z - want[i].z) > EPS || fabs(got[i].w - want[i].w) > EPS)
            fail_msg("%s: corner %d is (%g, %g, %g, %g), expected (%g, %g, %g, %g)", what, i,
                     got[i].x, got[i].y, got[i].z, got[i].w, want[i].x, want[i].y, want[i].z,
                     want[i].w);
}

static int clipped(const Vec4 *in, int n, Vec4 *out)
{
    return clip_polygon(in, n, out);
}

/* ---- the plane tests ---------------------------------------------------- */

static void distances_are_zero_on_the_planes_and_positive_inside(void **state)
{
    (void)state;
    assert_true(plane_distance(vec4(0, 0, -2, 2), NEAR_PLANE) == 0); /* z = -w: on near */
    assert_true(plane_distance(vec4(0, 0, 2, 2), FAR_PLANE) == 0);   /* z = w: on far */
    assert_true(plane_distance(vec4(0, 0, 0, 2), NEAR_PLANE) > 0);
    assert_true(plane_distance(vec4(0, 0, 0, 2), FAR_PLANE) > 0);
    assert_true(plane_distance(vec4(0, 0, -3, 2), NEAR_PLANE) < 0); /* in front of near: no */
    assert_true(plane_distance(vec4(0, 0, 3, 2), FAR_PLANE) < 0);
    assert_true(plane_distance(vec4(5, 7, -1, -1), NEAR_PLANE) < 0); /* behind the eye */
}

/* ---- triangles against the near plane ----------------------------------- */

/* A = (0,0,0,1) and B = (2,0,0,1) are inside (z + w = 1); C = (0,2,-3,1) is
 * behind the near plane (z + w = -2).
 *   C -> A comes in: s = 1 / (1 + 2) = 1/3 of the way from A to C:
 *          (0, 2/3, -1, 1); then A
 *   A -> B: B
 *   B -> C goes out: 1/3 of the way from B to C: (4/3, 2/3, -1, 1)
 * A quad. Every corner has w - z >= 1: the far plane keeps it whole. */
static void one_corner_behind_gives_a_quad(void **state)
{
    (void)state;
    Vec4 in[3] = {{0, 0, 0, 1}, {2, 0, 0, 1}, {0, 2, -3, 1}};
    Vec4 out[CLIP_MAX_OUT(3)];
    Vec4 want[4] = {{0, 2.0 / 3, -1, 1}, {0, 0, 0, 1}, {2, 0, 0, 1}, {4.0 / 3, 2.0 / 3, -1, 1}};
    expect_corners(out, clipped(in, 3, out), want, 4, "one corner behind");
}

/* A = (0,0,0,1) inside; B = (2,0,-3,1), C = (0,2,-3,1) behind (z + w = -2).
 *   C -> A comes in: (0, 2/3, -1, 1); then A
 *   A -> B goes out: 1/3 of the way from A to B: (2/3, 0, -1, 1)
 *   B -> C: both behind, nothing
 * A smaller triangle. */
static void two_corners_behind_give_a_triangle(void **state)
{
    (void)state;
    Vec4 in[3] = {{0, 0, 0, 1}, {2, 0, -3, 1}, {0, 2, -3, 1}};
    Vec4 out[CLIP_MAX_OUT(3)];
    Vec4 want[3] = {{0, 2.0 / 3, -1, 1}, {0, 0, 0, 1}, {2.0 / 3, 0, -1, 1}};
    expect_corners(out, clipped(in, 3, out), want, 3, "two corners behind");
}

static void all_corners_behind_give_nothing(void **state)
{
    (void)state;
    Vec4 in[3] = {{0, 0, -3, 1}, {2, 0, -3, 1}, {0, 2, -5, -1}}; /* the last behind the eye */
    Vec4 out[CLIP_MAX_OUT(3)];
    expect_count(0, clipped(in, 3, out), "corners left of a triangle wholly behind");
}

static void no_corner_behind_gives_the_same_triangle(void **state)
{
    (void)state;
    Vec4 in[3] = {{0, 0, 0, 1}, {2, 0, 0.5, 1}, {0, 2, -0.5, 1}};
    Vec4 out[CLIP_MAX_OUT(3)];
    expect_corners(out, clipped(in, 3, out), in, 3, "a triangle between the planes");
}

/* Corners exactly on the near plane (z = -w) are inside: kept, and no
 * crossing is added beside them.
 *   A = (0,0,-1,1) on the plane, B = (2,0,0,1), C = (0,2,0,1) in front: the
 *   same triangle.
 *   A on the plane, B = (2,0,1,1) in front (distance 2), C = (0,2,-3,1)
 *   behind (distance -2): C -> A: A is on the plane, A; A -> B: B; B -> C
 *   goes out halfway: (1, 1, -1, 1). A triangle.
 *   A and B on the plane, C behind: only A and B are left, nothing to draw. */
static void corners_on_the_plane_are_kept(void **state)
{
    (void)state;
    Vec4 out[CLIP_MAX_OUT(3)];
    Vec4 front[3] = {{0, 0, -1, 1}, {2, 0, 0, 1}, {0, 2, 0, 1}};
    expect_corners(out, clipped(front, 3, out), front, 3, "one corner on the plane");

    Vec4 across[3] = {{0, 0, -1, 1}, {2, 0, 1, 1}, {0, 2, -3, 1}};
    Vec4 want[3] = {{0, 0, -1, 1}, {2, 0, 1, 1}, {1, 1, -1, 1}};
    expect_corners(out, clipped(across, 3, out), want, 3, "on the plane, in front, behind");

    Vec4 edge[3] = {{0, 0, -1, 1}, {2, 0, -1, 1}, {0, 2, -3, 1}};
    expect_count(2, clipped(edge, 3, out), "corners left with an edge on the plane");
}

/* ---- an octagon across both planes ------------------------------------- */

/* Eight corners (x, 1, z, 2) with (x, z) = (1,-3) (3,-1) (3,1) (1,3) (-1,3)
 * (-3,1) (-3,-1) (-1,-3): w = 2, so near keeps z >= -2 and far z <= 2.
 * Near (distance z + 2 = -1 1 3 5 5 3 1 -1):
 *   (-1,-3) -> (1,-3) both behind; (1,-3) -> (3,-1) comes in halfway:
 *   (2,-2), then (3,-1), (3,1), (1,3), (-1,3), (-3,1), (-3,-1);
 *   (-3,-1) -> (-1,-3) goes out halfway: (-2,-2).         8 corners.
 * Far (distance 2 - z = 4 3 1 -1 -1 1 3 4 for those 8):
 *   (2,-2), (3,-1), (3,1); (3,1) -> (1,3) goes out halfway: (2,2);
 *   (1,3) -> (-1,3) beyond; (-1,3) -> (-3,1) comes in halfway: (-2,2),
 *   then (-3,1), (-3,-1), (-2,-2).                        8 corners. */
static void octagon_across_near_and_far(void **state)
{
    (void)state;
    const double xz[8][2] = {{1, -3}, {3, -1}, {3, 1}, {1, 3}, {-1, 3}, {-3, 1}, {-3, -1}, {-1, -3}};
    const double want_xz[8][2] = {{2, -2}, {3, -1}, {3, 1}, {2, 2},
                                  {-2, 2}, {-3, 1}, {-3, -1}, {-2, -2}};
    Vec4 in[8], want[8], out[CLIP_MAX_OUT(8)];
    for (int i = 0; i < 8; i++) {
        in[i] = vec4(xz[i][0], 1, xz[i][1], 2);
        want[i] = vec4(want_xz[i][0], 1, want_xz[i][1], 2);
    }
    expect_corners(out, clipped(in, 8, out), want, 8, "octagon across both planes");
}

/* One edge, clipped from either face that shares it, gives the same point. */
static void a_shared_edge_is_cut_at_the_same_point_both_ways(void **state)
{
    (void)state;
    Vec4 p = {0.3, -0.7, 0.1, 0.9}, q = {-1.1, 2.3, -4.7, 0.3}; /* p in front, q behind */
    Vec4 a[3] = {p, q, {5, 5, 0, 1}}, b[3] = {q, p, {-5, 5, 0, 1}};
    Vec4 out_a[CLIP_MAX_OUT(3)], out_b[CLIP_MAX_OUT(3)];
    int na = clipped(a, 3, out_a), nb = clipped(b, 3, out_b);
    expect_count(4, na, "corners of the first face");
    expect_count(4, nb, "corners of the second face");
    /* a: p, crossing(p, q), crossing(third, q), third;
     * b: crossing(third, q), crossing(p, q), p, third. */
    Vec4 xa = out_a[1], xb = out_b[1];
    if (!(xa.x == xb.x && xa.y == xb.y && xa.z == xb.z && xa.w == xb.w))
        fail_msg("the shared edge is cut at (%.17g, %.17g, %.17g, %.17g) in one face and "
                 "(%.17g, %.17g, %.17g, %.17g) in the other", xa.x, xa.y, xa.z, xa.w, xb.x,
                 xb.y, xb.z, xb.w);
    assert_true(fabs(plane_distance(xa, NEAR_PLANE)) < 1e-15);
}

/* The divide and the viewport give what camera_project gives, to the bit. */
static void the_divide_is_the_pipelines(void **state)
{
    (void)state;
    Camera cam;
    camera_init(&cam, vec3(0.3, 1.1, 2), vec3(-0.2, 0.4, -5), vec3(0, 1, 0), 55, 0.3, 80, 317,
                211);
    for (int i = 0; i < 100; i++) {
        Vec3 p = vec3(sin(i * 1.3) * 4, cos(i * 0.7) * 3, -1 - i * 0.37);
        ScreenVertex a = camera_project(&cam, p);
        ScreenVertex b = clip_to_screen(camera_to_clip(&cam, p), 317, 211);
        observe_near(b.x, a.x, 0.0);
        observe_near(b.y, a.y, 0.0);
        observe_near(b.d, a.d, 0.0);
        if (a.x != b.x || a.y != b.y || a.d != b.d)
            fail_msg("point %d: camera_project gives (%.17g, %.17g, %.17g), clip_to_screen "
                     "(%.17g, %.17g, %.17g)", i, a.x, a.y, a.d, b.x, b.y, b.d);
    }
}

/* ---- through the pipeline: where the divide would go wrong -------------- */

enum { W = 40, H = 30 };

/* Faces seen by a camera at eye looking at target (fovy 60, near 1, far 100). */
static void draw_faces(const Vec3 *p, int nfaces, int corners, Vec3 eye, Vec3 target,
                       Render *r, Target *t)
{
    Mesh m;
    Error err;
    mesh_init(&m);
    for (int f = 0; f < nfaces; f++) {
        int idx[4];
        for (int k = 0; k < corners; k++)
            assert_true((idx[k] = mesh_add_vertex(&m, p[f * corners + k], &err)) >= 0);
        assert_true(mesh_add_face(&m, idx, corners, -1, &err) >= 0);
    }
    Camera cam;
    camera_init(&cam, eye, target, vec3(0, 1, 0), 60, 1, 100, W, H);
    assert_true(render_from_mesh(r, &m, &cam, "test faces", &err));
    assert_true(render_target_init(t, &CLIPPING_ZBUFFER, W, H, &err));
    assert_true(render_faces(r, t, &CLIPPING_ZBUFFER, NULL, 0, NULL, NULL, &err));
}

/* Every drawn pixel has a finite depth at or beyond the near plane. */
static long expect_sane_depths(const Target *t, const char *what)
{
    float *d = render_view_depth(t, &CLIPPING_ZBUFFER);
    assert_non_null(d);
    long drawn = 0;
    for (int i = 0; i < W * H; i++) {
        if (t->face[i] == NO_FACE)
            continue;
        drawn++;
        if (!(isfinite(d[i]) && d[i] >= 1 - 1e-4 && d[i] <= 100 * (1 + 1e-4)))
            fail_msg("%s: pixel (%d,%d) has depth %g, not between near and far", what, i % W,
                     i / W, d[i]);
    }
    free(d);
    return drawn;
}

static void face_wholly_behind_the_eye_draws_nothing(void **state)
{
    (void)state;
    Vec3 p[3] = {{-5, -5, 3}, {5, -5, 3}, {0, 5, 3}}; /* z = 3: behind a camera looking down -Z */
    Render r;
    Target t;
    draw_faces(p, 1, 3, vec3(0, 0, 0), vec3(0, 0, -1), &r, &t);
    expect_count(0, expect_sane_depths(&t, "a face behind the eye"), "pixels drawn");
    expect_count(1, r.counts.tris_behind_near, "triangles dropped at the near plane");
    target_free(&t);
    render_free(&r);
}

/* A corner at the eye's own depth (w = 0) beside it, two in front at d = 5:
 * the part from d = 1 on is drawn; the part from the eye to the near plane is
 * cut away. Projected, the triangle's edges from the corner at w = 0 are
 * parallel lines on the screen (their vanishing point is that corner's
 * direction, at infinity): the cut face is a quad reaching the left edge. */
static void corner_at_w_zero_is_clipped_not_divided(void **state)
{
    (void)state;
    Vec3 p[3] = {{-3, 0, 0}, {1, -1, -5}, {1, 1, -5}};
    Render r;
    Target t;
    draw_faces(p, 1, 3, vec3(0, 0, 0), vec3(0, 0, -1), &r, &t);
    long drawn = expect_sane_depths(&t, "a face with a corner at w = 0");
    expect_at_least(20, drawn, "pixels drawn of the face in front of the near plane");
    expect_count(0, r.counts.tris_behind_near, "triangles dropped at the near plane");
    target_free(&t);
    render_free(&r);
}

/* A face whose plane passes through the eye is seen edge on: a line, no area. */
static void face_through_the_eye_draws_nothing(void **state)
{
    (void)state;
    Vec3 p[3] = {{0, 0, 0}, {1, -1, -5}, {-1, -1, -5}}; /* the plane y = z / 5, eye at a corner */
    Render r;
    Target t;
    draw_faces(p, 1, 3, vec3(0, 0, 0), vec3(0, 0, -1), &r, &t);
    expect_count(0, expect_sane_depths(&t, "a face through the eye"), "pixels drawn");
    target_free(&t);
    render_free(&r);
}

/* The eye exactly on a face: in the plane z = 0 facing the camera's view
 * (every corner at w = 0, and the eye inside it), and in the plane x = 0
 * along the view (seen edge on). Neither draws anything; a face in front
 * still draws, whole. */
static void camera_exactly_on_a_face(void **state)
{
    (void)state;
    Vec3 p[12] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0},
                  {0, -1, 1}, {0, -1, -9}, {0, 1, -9}, {0, 1, 1},
                  {-50, -50, -10}, {50, -50, -10}, {50, 50, -10}, {-50, 50, -10}};
    Render r;
    Target t;
    draw_faces(p, 3, 4, vec3(0, 0, 0), vec3(0, 0, -1), &r, &t);
    expect_count(W * H, expect_sane_depths(&t, "a camera on a face"), "pixels drawn");
    for (int i = 0; i < W * H; i++)
        if (t.face[i] != 2 || t.overdraw[i] != 1)
            fail_msg("pixel (%d,%d): face %d drawn %u times; only the wall in front, once",
                     i % W, i / W, t.face[i], t.overdraw[i]);
    target_free(&t);
    render_free(&r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(distances_are_zero_on_the_planes_and_positive_inside),
        cmocka_unit_test(one_corner_behind_gives_a_quad),
        cmocka_unit_test(two_corners_behind_give_a_triangle),
        cmocka_unit_test(all_corners_behind_give_nothing),
        cmocka_unit_test(no_corner_behind_gives_the_same_triangle),
        cmocka_unit_test(corners_on_the_plane_are_kept),
        cmocka_unit_test(octagon_across_near_and_far),
        cmocka_unit_test(a_shared_edge_is_cut_at_the_same_point_both_ways),
        cmocka_unit_test(the_divide_is_the_pipelines),
        cmocka_unit_test(face_wholly_behind_the_eye_draws_nothing),
        cmocka_unit_test(corner_at_w_zero_is_clipped_not_divided),
        cmocka_unit_test(face_through_the_eye_draws_nothing),
        cmocka_unit_test(camera_exactly_on_a_face),
    };
    return cmocka_run_group_tests_name("05_clipping clip", tests, NULL, NULL);
}
