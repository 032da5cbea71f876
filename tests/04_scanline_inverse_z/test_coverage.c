/* test_coverage.c: lesson 04 covers pixels by the series' fill rule, like
 * lessons 02 and 03 (watertight meshes, the top-left rule, order independence,
 * degenerate input): the shared tests of tests/shared/coverage_suite.inc, with
 * lesson 04's draw_face, which draws convex faces whole.
 *
 * Then lesson 04's own watertightness test: a quad grid mesh through the whole
 * pipeline. Two quads that share an edge walk it from the same top corner with
 * the same integer steps, so the span of one ends exactly where the span of
 * the other begins: no gap, no pixel twice. */
#include "scanline.h"

#define SUITE_RASTERIZER SCANLINE_ZBUFFER
#include "../shared/coverage_suite.inc"

#include "camera.h"
#include "harness/mesh_build.h"

static uint64_t lcg_state = 2024;
static double random_unit(void)
{
    lcg_state = lcg_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(lcg_state >> 11) / 9007199254740992.0;
}

/* A flat grid of 60 x 44 quads in 3-D, bigger than the view, seen at a slant
 * through the whole pipeline (camera, projection, render_faces): every pixel
 * of the 160 x 120 screen lies on the grid and is drawn exactly once. Inner
 * grid points are moved at random within the plane. */
static void quad_grid_mesh_in_perspective_covers_each_pixel_once(void **state)
{
    (void)state;
    enum { COLS = 60, ROWS = 44 };
    Mesh m;
    Error err;
    mesh_init(&m);
    for (int j = 0; j <= ROWS; j++)
        for (int i = 0; i <= COLS; i++) {
            bool inner = i > 0 && i < COLS && j > 0 && j < ROWS;
            double jx = inner ? (random_unit() - 0.5) * 0.6 : 0;
            double jy = inner ? (random_unit() - 0.5) * 0.6 : 0;
            assert_true(mesh_add_vertex(&m, vec3(-30 + i + jx, -22 + j + jy, -10), &err) >= 0);
        }
    for (int j = 0; j < ROWS; j++)
        for (int i = 0; i < COLS; i++) {
            int a = j * (COLS + 1) + i;
            int quad[4] = {a, a + 1, a + COLS + 2, a + COLS + 1};
            assert_true(mesh_add_face(&m, quad, 4, -1, &err) >= 0);
        }
    Camera cam;
    camera_init(&cam, vec3(2, 1, 0), vec3(5, 3, -10), vec3(0, 1, 0), 50, 0.5, 100, 160, 120);
    Render r;
    assert_true(render_from_mesh(&r, &m, &cam, "quad grid", &err));
    Target t;
    assert_true(render_target_init(&t, &SCANLINE_ZBUFFER, 160, 120, &err));
    assert_true(render_faces(&r, &t, &SCANLINE_ZBUFFER, NULL, 0, NULL, NULL, &err));
    /* Quads far down the left lie behind the camera and are dropped at the
     * near plane; they are off screen, and the check below sees every pixel. */
    expect_at_least(1001, r.counts.faces_drawn, "faces drawn");
    expect_rectangle_covered_once(&t, 0, 159, 0, 119, "quad grid mesh in perspective");
    target_free(&t);
    render_free(&r);
}

int main(void)
{
    const struct CMUnitTest lesson_tests[] = {
        cmocka_unit_test(quad_grid_mesh_in_perspective_covers_each_pixel_once),
    };
    int failed = run_coverage_suite("04_scanline_inverse_z coverage");
    failed += cmocka_run_group_tests_name("04_scanline_inverse_z watertight mesh", lesson_tests,
                                          NULL, NULL);
    return failed;
}
