/* test_coverage.c: lesson 05 covers pixels by the series' fill rule, like
 * lessons 02 to 04 (tests/shared/coverage_suite.inc, with lesson 05's
 * draw_clipped_face: a face made on the screen is drawn as lesson 04 draws it).
 *
 * Then lesson 05's own watertightness test: a jittered grid on the floor,
 * under a camera looking down at it, reaches behind the camera and through
 * the near plane. Through the whole pipeline, every pixel is drawn exactly
 * once: faces the near plane cuts keep their shared edges, because a new
 * corner on a shared edge is worked out from the same inside corner by both
 * faces, and an old corner is divided as the pipeline divides it. */
#include "clipping.h"

#define SUITE_RASTERIZER CLIPPING_ZBUFFER
#include "../shared/coverage_suite.inc"

#include "camera.h"
#include "harness/mesh_build.h"
#include "scanline.h"

static uint64_t lcg_state = 2025;
static double random_unit(void)
{
    lcg_state = lcg_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(lcg_state >> 11) / 9007199254740992.0;
}

enum { COLS = 40, ROWS = 50 };

/* The floor y = 0, x in [-10, 10], z in [-20, 5], as COLS x ROWS quads (or
 * two triangles per quad), inner grid points moved at random in the plane. */
static void floor_grid(Mesh *m, bool triangles)
{
    Error err;
    mesh_init(m);
    for (int j = 0; j <= ROWS; j++)
        for (int i = 0; i <= COLS; i++) {
            bool inner = i > 0 && i < COLS && j > 0 && j < ROWS;
            double jx = inner ? (random_unit() - 0.5) * 0.3 : 0;
            double jz = inner ? (random_unit() - 0.5) * 0.3 : 0;
            assert_true(mesh_add_vertex(m, vec3(-10 + 0.5 * i + jx, 0, 5 - 0.5 * j + jz), &err) >= 0);
        }
    for (int j = 0; j < ROWS; j++)
        for (int i = 0; i < COLS; i++) {
            int a = j * (COLS + 1) + i;
            int quad[4] = {a, a + 1, a + COLS + 2, a + COLS + 1};
            int t0[3] = {quad[0], quad[1], quad[2]}, t1[3] = {quad[0], quad[2], quad[3]};
            if (triangles) {
                assert_true(mesh_add_face(m, t0, 3, -1, &err) >= 0);
                assert_true(mesh_add_face(m, t1, 3, -1, &err) >= 0);
            } else {
                assert_true(mesh_add_face(m, quad, 4, -1, &err) >= 0);
            }
        }
}

/* Eye 0.3 above the floor looking 45 degrees down (fovy 60, near 0.5,
 * 160 x 120). The pixel centre of row y looks along b = 1 - (y + 0.5) / 60 in
 * NDC, and meets the floor at view depth d = 0.3 sqrt(2) / (1 - b tan 30):
 * rows down to 44 see the floor at d > near, rows from 45 on would see it
 * nearer than the near plane. So rows 0-43 are covered exactly once, rows
 * 45-119 not at all (row 44 holds the near plane's own edge), and the faces
 * the near plane cuts cover their part without a gap or a pixel twice. */
#define GRID_NEAR 0.5
static void grid_through_the_near_plane_covers_each_pixel_once(void **state)
{
    (void)state;
    const int w = 160, h = 120;
    for (int triangles = 0; triangles < 2; triangles++) {
        const char *what = triangles ? "triangle grid through the near plane"
                                     : "quad grid through the near plane";
        Mesh m;
        Error err;
        floor_grid(&m, triangles);
        Camera cam;
        camera_init(&cam, vec3(0.1, 0.3, 0.2), vec3(0.1, -0.7, -0.8), vec3(0, 1, 0), 60,
                    GRID_NEAR, 100, w, h);
        Render r;
        assert_true(render_from_mesh(&r, &m, &cam, "floor grid", &err));
        Target t;
        assert_true(render_target_init(&t, &CLIPPING_ZBUFFER, w, h, &err));
        assert_true(render_faces(&r, &t, &CLIPPING_ZBUFFER, NULL, 0, NULL, NULL, &err));
        observe_coverage(&t);
        for (int y = 0; y < h; y++) {
            double b = 1 - (y + 0.5) / 60.0;
            double d = 0.3 * sqrt(2.0) / (1 - b * tan(PI / 6));
            for (int x = 0; x < w && fabs(d - GRID_NEAR) > 1e-3; x++) {
                unsigned want = d > GRID_NEAR ? 1 : 0;
                if (t.overdraw[y * w + x] != want)
                    fail_msg("%s: pixel (%d,%d) drawn %u times, expected %u (the floor is at "
                             "d = %.4f there, the near plane at %.1f)",
                             what, x, y, t.overdraw[y * w + x], want, d, GRID_NEAR);
            }
        }
        long covered = 0;
        for (int i = 0; i < w * h; i++)
            covered += t.overdraw[i] > 0;
        target_free(&t);

        /* Lesson 04's rule drops the faces the near plane cuts: holes. */
        assert_true(render_target_init(&t, &SCANLINE_ZBUFFER, w, h, &err));
        assert_true(render_faces(&r, &t, &SCANLINE_ZBUFFER, NULL, 0, NULL, NULL, &err));
        long covered_04 = 0;
        for (int i = 0; i < w * h; i++)
            covered_04 += t.overdraw[i] > 0;
        expect_at_least(covered_04 + 100, covered, "pixels covered, against lesson 04's rule");
        target_free(&t);
        render_free(&r);
    }
}

int main(void)
{
    const struct CMUnitTest lesson_tests[] = {
        cmocka_unit_test(grid_through_the_near_plane_covers_each_pixel_once),
    };
    int failed = run_coverage_suite("05_clipping coverage");
    failed += cmocka_run_group_tests_name("05_clipping watertight across the near plane",
                                          lesson_tests, NULL, NULL);
    return failed;
}
