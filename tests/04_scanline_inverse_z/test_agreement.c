/* test_agreement.c: lesson 04 sees what lesson 03 sees.
 *
 * Lesson 03 draws triangles with a bounding box and fixed-point edge
 * functions, and interpolates 1/d with barycentric weights; lesson 04 walks
 * whole convex polygons edge by edge and steps 1/d. Both follow one fill rule
 * with the same 8 sub-pixel bits, so they cover the same pixels, and both
 * make 1/d linear on the screen, so they agree on depth up to rounding. Where
 * two faces are almost exactly as near as each other, rounding may pick the
 * other one: that happens only where faces meet, on polygon edges.
 *
 * For every built-in scene (but those whose faces lie on each other by
 * design, SceneInfo.coplanar) and one OBJ mesh (a sphere pierced by a box),
 * both programs write --id-out; the test asserts that lesson 04 drew (at
 * least 1 pixel in 100 shows a face), that at least 99.9% of
 * the pixels show the same face, that every pixel that differs lies on a
 * polygon edge (a pixel next to a pixel of another face, in either picture),
 * and prints the count. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness/mesh_build.h"
#include "harness/scene.h"
#include "harness/shade.h"
#include "test_support.h"

#define LESSON "04_scanline_inverse_z"
#define REFERENCE "03_perspective_z"
#define WIDTH "400"
#define HEIGHT "300"
/* At most 1 pixel in 1000 may show another face. */
#define MAX_DIFFERING_PER_MILLE 1

static Image render_id(const char *program, const char *dir, const char *const *source)
{
    Path out = in_dir(dir, program), picture = in_dir(dir, "picture.png");
    const char *args[16] = {"--id-out", out.path, "--width", WIDTH, "--height", HEIGHT,
                            "--out",    picture.path};
    int n = 8;
    for (int k = 0; source[k]; k++)
        args[n++] = source[k];
    args[n] = NULL;
    free(run_ok(program, args));
    return read_png(out.path);
}

/* A pixel on a polygon edge: one of its 8 neighbours shows another face. */
static bool on_edge(const Image *im, int x, int y)
{
    int32_t f = face_at(im, x, y);
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
            int nx = x + dx, ny = y + dy;
            if (nx >= 0 && ny >= 0 && nx < im->width && ny < im->height &&
                face_at(im, nx, ny) != f)
                return true;
        }
    return false;
}

static void expect_agreement(const char *what, const char *const *source)
{
    const char *dir = test_dir("04_agreement");
    Image ours = render_id(LESSON, dir, source);
    Image ref = render_id(REFERENCE, dir, source);
    expect_drawn(&ours, what);
    expect_count(ref.width, ours.width, "picture width");
    expect_count(ref.height, ours.height, "picture height");
    long total = (long)ours.width * ours.height, differing = 0, off_edge = 0;
    int off_x = -1, off_y = -1;
    for (int y = 0; y < ours.height; y++)
        for (int x = 0; x < ours.width; x++) {
            if (face_at(&ours, x, y) == face_at(&ref, x, y))
                continue;
            differing++;
            if (!on_edge(&ours, x, y) && !on_edge(&ref, x, y) && off_edge++ == 0) {
                off_x = x;
                off_y = y;
            }
        }
    printf("  %-16s %ld of %ld pixels show another face than %s (%.3f%%), %ld off polygon "
           "edges\n", what, differing, total, REFERENCE, 100.0 * (double)differing / (double)total, off_edge);
    if (off_edge)
        fail_msg("%s: pixel (%d,%d) shows face %d here but face %d in %s, away from any edge",
                 what, off_x, off_y, face_at(&ours, off_x, off_y), face_at(&ref, off_x, off_y),
                 REFERENCE);
    if (differing * 1000 > total * MAX_DIFFERING_PER_MILLE)
        fail_msg("%s: %ld of %ld pixels differ, more than %d in 1000", what, differing, total,
                 MAX_DIFFERING_PER_MILLE);
    image_free(&ours);
    image_free(&ref);
}

static void every_built_in_scene_agrees_with_lesson_03(void **state)
{
    (void)state;
    for (int i = 0; i < scene_count(); i++) {
        /* decals: a decal and its wall have equal depths; which one a pixel
         * shows depends on each lesson's rounding (lesson 07's subject). */
        if (scene_at(i)->coplanar)
            continue;
        const char *source[] = {"--scene", scene_at(i)->name, NULL};
        expect_agreement(scene_at(i)->name, source);
    }
}

/* A UV sphere of 32 x 16 (planar quads, triangles at the poles) with a box
 * pushed halfway into it: faces meet along shared edges and cross each other
 * along the box's cut. */
#define SPHERE_SLICES 32
#define SPHERE_STACKS 16

static void build_pierced_sphere(Mesh *m)
{
    Error err;
    int top = mesh_add_vertex(m, vec3(0, 1, 0), &err);
    int first = m->nverts;
    for (int j = 1; j < SPHERE_STACKS; j++) {
        double phi = PI * j / SPHERE_STACKS;
        for (int i = 0; i < SPHERE_SLICES; i++) {
            double theta = 2 * PI * i / SPHERE_SLICES;
            assert_true(mesh_add_vertex(m, vec3(sin(phi) * cos(theta), cos(phi),
                                                -sin(phi) * sin(theta)), &err) >= 0);
        }
    }
    int bottom = mesh_add_vertex(m, vec3(0, -1, 0), &err);
    for (int i = 0; i < SPHERE_SLICES; i++) {
        int i1 = (i + 1) % SPHERE_SLICES;
        int cap_top[3] = {top, first + i, first + i1};
        int last = first + (SPHERE_STACKS - 2) * SPHERE_SLICES;
        int cap_bottom[3] = {bottom, last + i1, last + i};
        assert_true(mesh_add_face(m, cap_top, 3, -1, &err) >= 0);
        assert_true(mesh_add_face(m, cap_bottom, 3, -1, &err) >= 0);
        for (int j = 0; j + 1 < SPHERE_STACKS - 1; j++) {
            int a = first + j * SPHERE_SLICES;
            int q[4] = {a + i, a + SPHERE_SLICES + i, a + SPHERE_SLICES + i1, a + i1};
            assert_true(mesh_add_face(m, q, 4, -1, &err) >= 0);
        }
    }
    /* The box: x, y in [0.3, 1.5], z in [-0.4, 0.4]. */
    int b = m->nverts;
    for (int k = 0; k < 8; k++)
        assert_true(mesh_add_vertex(m, vec3(k & 1 ? 1.5 : 0.3, k & 2 ? 1.5 : 0.3,
                                            k & 4 ? 0.4 : -0.4), &err) >= 0);
    const int sides[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (int s = 0; s < 6; s++) {
        int q[4] = {b + sides[s][0], b + sides[s][1], b + sides[s][2], b + sides[s][3]};
        assert_true(mesh_add_face(m, q, 4, -1, &err) >= 0);
    }
}

static void an_obj_mesh_agrees_with_lesson_03(void **state)
{
    (void)state;
    Mesh m;
    Error err;
    mesh_init(&m);
    build_pierced_sphere(&m);
    char obj[4096]; /* path_join's buffer is reused: keep a copy */
    snprintf(obj, sizeof obj, "%s", path_join(test_dir("04_agreement_obj"), "pierced_sphere.obj"));
    if (!mesh_write_obj(&m, obj, &err))
        fail_msg("%s", err.msg);
    mesh_free(&m);
    const char *source[] = {"--obj", obj, "--eye", "1.8,1.6,2.6", "--target", "0.2,0.2,0", NULL};
    expect_agreement("pierced sphere", source);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_built_in_scene_agrees_with_lesson_03),
        cmocka_unit_test(an_obj_mesh_agrees_with_lesson_03),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
