/* test_render.c: the pipeline around the lessons' rasterizers: render.h (faces
 * handed over, dropped, counted; outputs; summary), shade.h (colours) and
 * guard_band.h (clipping huge polygons). The rasterizer here is a stand-in
 * that only records what it was given: the lessons test their own. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "guard_band.h"
#include "harness/render.h"
#include "harness/shade.h"
#include "test_support.h"

/* ---- guard_band ------------------------------------------------------------- */

#define G ((double)GUARD_BAND)

static void polygon_inside_the_band_is_copied(void **state)
{
    (void)state;
    ScreenVertex in[3] = {{-5, 3, 1}, {900, 20, 2}, {40, -1000, 3}}, out[GUARD_BAND_MAX_OUT(3)];
    expect_count(3, guard_band_clip(in, 3, 800, 600, LINEAR_D, out), "corners after clipping");
    assert_memory_equal(in, out, sizeof in);
}

static void polygon_beyond_the_band_is_dropped(void **state)
{
    (void)state;
    ScreenVertex in[3] = {{-3 * G, 0, 1}, {-2 * G, 0, 1}, {-2 * G, 50, 1}};
    ScreenVertex out[GUARD_BAND_MAX_OUT(3)];
    expect_count(0, guard_band_clip(in, 3, 800, 600, LINEAR_D, out), "corners after clipping");
    expect_count(0, guard_band_clip(in, 2, 800, 600, LINEAR_D, out), "corners, n < 3");
}

/* Corner 0 at x = -3G, the others at x = +G: both edges from corner 0 cross
 * x = -G halfway (t = (-G - -3G) / (G - -3G) = 1/2). Depths 1 and 5 give 3 if d
 * is linear, 1 / (1/2 * 1 + 1/2 * 1/5) = 1 / 0.6 if 1/d is. y: 0 and 50. */
static void clip_puts_new_corners_on_the_band_with_the_lessons_depth(void **state)
{
    (void)state;
    ScreenVertex in[3] = {{-3 * G, 0, 1}, {G, 0, 5}, {G, 100, 5}};
    const DepthLinearity modes[2] = {LINEAR_D, LINEAR_INV_D};
    const double want_d[2] = {3.0, 1 / 0.6};
    for (int m = 0; m < 2; m++) {
        ScreenVertex out[GUARD_BAND_MAX_OUT(3)];
        int n = guard_band_clip(in, 3, 800, 600, modes[m], out);
        expect_count(4, n, "corners after clipping");
        int on_band = 0;
        for (int k = 0; k < n; k++) {
            assert_true(guard_band_contains(&out[k], 1, 800, 600));
            if (out[k].x == -G) {
                on_band++;
                assert_true(fabs(out[k].y) < 1e-9 || fabs(out[k].y - 50) < 1e-9);
                assert_true(fabs(out[k].d - want_d[m]) < 1e-12);
            }
        }
        expect_count(2, on_band, "corners on the guard band");
    }
}

static void clip_survives_the_largest_doubles(void **state)
{
    (void)state;
    ScreenVertex in[3] = {{-1.7e308, -1.7e308, 2}, {1.7e308, -1.7e308, 2}, {0, 1.7e308, 2}};
    ScreenVertex out[GUARD_BAND_MAX_OUT(3)];
    int n = guard_band_clip(in, 3, 64, 64, LINEAR_D, out);
    assert_true(n >= 3);
    for (int k = 0; k < n; k++) {
        assert_true(isfinite(out[k].x) && isfinite(out[k].y));
        assert_true(guard_band_contains(&out[k], 1, 64, 64));
        assert_true(fabs(out[k].d - 2) < 1e-9);
    }
}

/* ---- shade ------------------------------------------------------------------- */

static double colour_distance(Rgb a, Rgb b)
{
    double dr = a.r - b.r, dg = a.g - b.g, db = a.b - b.b;
    return sqrt(dr * dr + dg * dg + db * db);
}

/* --shade id is read by eye: any two of the 17 colours differ by at least 60
 * in RGB (most by far more), consecutive faces by at least 120, and every
 * colour stands out from the black background; face 17 starts again. */
static void shade_id_colours_are_far_apart(void **state)
{
    (void)state;
    Rgb black = {0, 0, 0};
    for (int i = 0; i < ID_PALETTE_SIZE; i++) {
        Rgb a = face_shade_id_colour(i);
        if (colour_distance(a, black) < 150)
            fail_msg("face %d's colour (%d,%d,%d) is too close to the black background", i,
                     a.r, a.g, a.b);
        for (int j = 0; j < i; j++) {
            Rgb b = face_shade_id_colour(j);
            double min = j == i - 1 ? 120 : 60;
            if (colour_distance(a, b) < min)
                fail_msg("faces %d and %d: colours (%d,%d,%d) and (%d,%d,%d) differ by %.1f, "
                         "less than %.0f", j, i, b.r, b.g, b.b, a.r, a.g, a.b,
                         colour_distance(a, b), min);
        }
        expect_colour(a, face_shade_id_colour(i + ID_PALETTE_SIZE), "the palette cycles");
    }
    if (colour_distance(face_shade_id_colour(ID_PALETTE_SIZE - 1),
                        face_shade_id_colour(ID_PALETTE_SIZE)) < 120)
        fail_msg("the last colour and the first (faces 16 and 17) differ by less than 120");
}

static void id_colours_are_face_plus_one_big_endian(void **state)
{
    (void)state;
    Rgb c = face_id_colour(0);
    expect_colour((Rgb){0, 0, 1}, c, "id colour");
    c = face_id_colour(255); /* 256 = 0x000100 */
    expect_colour((Rgb){0, 1, 0}, c, "id colour");
    c = face_id_colour(65535); /* 65536 = 0x010000 */
    expect_colour((Rgb){1, 0, 0}, c, "id colour");
    c = face_id_colour(0x123455); /* 0x123456 */
    expect_colour((Rgb){0x12, 0x34, 0x56}, c, "id colour");
    expect_count(0x123455, id_colour_face(c), "face of the id colour");
    Rgb black = {0, 0, 0};
    expect_count(NO_FACE, id_colour_face(black), "face of black");
}

/* 24 bits number 16777215 faces: the last one is white, and one more would
 * wrap to black, the background. --id-out refuses such a mesh. */
static void id_colours_number_at_most_16777215_faces(void **state)
{
    (void)state;
    Error err;
    Rgb white = {255, 255, 255};
    expect_colour(white, face_id_colour(FACE_ID_MAX_FACES - 1), "id colour of the last face");
    expect_count(FACE_ID_MAX_FACES - 1, id_colour_face(white), "face of white");
    assert_true(face_ids_fit(0, &err));
    assert_true(face_ids_fit(FACE_ID_MAX_FACES, &err));
    assert_false(face_ids_fit(FACE_ID_MAX_FACES + 1, &err));
    assert_string_equal(err.msg, "--id-out: the mesh has 16777216 faces; an id picture numbers "
                                 "faces in 24 bits and tells at most 16777215 apart");
    assert_false(face_ids_fit(INT_MAX, &err));
}

/* A unit square in the plane z = -5, facing the camera at the origin. */
static void square_mesh(Mesh *m, int material)
{
    Error err;
    mesh_init(m);
    const Vec3 p[4] = {{-1, -1, -5}, {1, -1, -5}, {1, 1, -5}, {-1, 1, -5}};
    int idx[4];
    for (int k = 0; k < 4; k++)
        idx[k] = mesh_add_vertex(m, p[k], &err);
    assert_true(mesh_add_face(m, idx, 4, material, &err) >= 0);
}

static Camera origin_camera(int w, int h)
{
    Camera c;
    camera_init(&c, vec3(0, 0, 0), vec3(0, 0, -1), vec3(0, 1, 0), 90, 1, 100, w, h);
    return c;
}

/* Kd (1, 0.5, 0) is (255, 127.5 -> 128, 0). A white face seen straight on has
 * n = (0, 0, +-1) in view space, l = (-0.4, 0.6, 1) / |(-0.4, 0.6, 1)|, |l| =
 * sqrt(0.16 + 0.36 + 1) = 1.232883, so |n . l| = 0.811107 and the colour is
 * 255 * (0.25 + 0.75 * 0.811107) = 255 * 0.858330 = 218.87 -> 219. */
static void flat_colour_is_kd_times_lambert(void **state)
{
    (void)state;
    Mesh m;
    Error err;
    square_mesh(&m, -1);
    int white = mesh_add_material(&m, "white", vec3(1, 1, 1), &err);
    int orange = mesh_add_material(&m, "orange", vec3(1, 0.5, 0), &err);
    assert_true(white >= 0 && orange >= 0);
    m.faces[0].material = orange;
    Rgb base = face_base_colour(&m, 0);
    expect_colour((Rgb){255, 128, 0}, base, "base colour");

    m.faces[0].material = white;
    Camera cam = origin_camera(8, 8);
    Rgb c = face_flat_colour(&m, &cam, 0);
    expect_colour((Rgb){219, 219, 219}, c, "flat colour");
    mesh_free(&m);
}

static void faces_without_material_get_distinct_palette_colours(void **state)
{
    (void)state;
    Mesh m;
    square_mesh(&m, -1);
    Error err;
    int idx[4] = {0, 1, 2, 3};
    assert_true(mesh_add_face(&m, idx, 4, -1, &err) >= 0);
    Rgb a = face_base_colour(&m, 0), b = face_base_colour(&m, 1);
    assert_false(a.r == b.r && a.g == b.g && a.b == b.b);
    mesh_free(&m);
}

/* ---- render ------------------------------------------------------------------ */

/* A stand-in rasterizer: marks the pixel of the face's first corner, and
 * remembers the order of the faces it was given. */
static int drawn_order[16], drawn_count;

static void record_face(Target *t, LessonState *s, const ScreenFace *f, const DrawContext *ctx)
{
    (void)s, (void)ctx;
    drawn_order[drawn_count++] = f->face;
    int x = (int)f->v[0].x, y = (int)f->v[0].y;
    if (x >= 0 && y >= 0 && x < t->width && y < t->height) {
        size_t i = (size_t)y * (size_t)t->width + (size_t)x;
        target_record(t, i, f->face, (float)f->v[0].d, t->depth[i], true);
        t->depth[i] = (float)(1 / f->v[0].d); /* stores 1/d, as lesson 04 does */
        t->face[i] = f->face;
    }
}

static double inverse(const LessonState *s, float stored)
{
    (void)s;
    return 1.0 / stored;
}

static void clear_to_zero(Target *t, LessonState *s)
{
    (void)s;
    for (int i = 0; i < t->width * t->height; i++) {
        t->depth[i] = 0.0f;
        t->face[i] = NO_FACE;
    }
}

static const Rasterizer RECORDER = {
    .clear = clear_to_zero, .draw_face = record_face, .stored_to_depth = inverse};

static int hook_calls;
static bool count_hook(void *data, const Target *t, const ScreenFace *f, Error *err)
{
    (void)data, (void)t, (void)f, (void)err;
    hook_calls++;
    return true;
}

/* Three triangles: face 0 in front (d = 5), face 1 with a corner at d = 0.5
 * (before near = 1), face 2 with a corner behind the eye. */
static void three_face_render(Render *r)
{
    Mesh m;
    Error err;
    mesh_init(&m);
    const Vec3 p[9] = {{0, 0, -5}, {1, 0, -5}, {0, 1, -5},
                       {0, 0, -5}, {1, 0, -5}, {0, 0.1, -0.5},
                       {0, 0, -5}, {1, 0, -5}, {0, 1, 3}};
    for (int k = 0; k < 9; k++)
        assert_true(mesh_add_vertex(&m, p[k], &err) >= 0);
    for (int f = 0; f < 3; f++) {
        int idx[3] = {3 * f, 3 * f + 1, 3 * f + 2};
        assert_true(mesh_add_face(&m, idx, 3, -1, &err) >= 0);
    }
    Camera cam = origin_camera(8, 8);
    assert_true(render_from_mesh(r, &m, &cam, "three faces", &err));
    assert_int_equal(m.nfaces, 0); /* taken over */
}

static void faces_reach_the_rasterizer_in_the_given_order(void **state)
{
    (void)state;
    Render r;
    Target t;
    Error err;
    three_face_render(&r);
    assert_true(render_target_init(&t, &RECORDER, 8, 8, &err));
    drawn_count = 0;
    hook_calls = 0;
    const int order[4] = {0, 2, 1, 0};
    assert_true(render_faces(&r, &t, &RECORDER, order, 4, count_hook, NULL, &err));
    expect_count(2, drawn_count, "faces drawn"); /* faces 1 and 2 dropped */
    assert_int_equal(drawn_order[0], 0);
    assert_int_equal(drawn_order[1], 0);
    expect_count(2, hook_calls, "hook calls");
    expect_count(2, r.counts.faces_drawn, "faces drawn");
    expect_count(2, r.counts.faces_behind_near, "faces behind the near plane");
    assert_true(render_face_dropped(&r, 1) && render_face_dropped(&r, 2));
    assert_false(render_face_dropped(&r, 0));
    target_free(&t);
    render_free(&r);
}

/* The contract of ScreenFace (rasterizer.h), on which lesson 10's set-up
 * rests: each corner on the screen is its clip-space corner divided by
 * camera_divide, to the bit. A stand-in that clips sees every corner. */
static int corners_checked, corners_differ;

static void check_corners(Target *t, LessonState *s, const ScreenFace *f, const DrawContext *ctx)
{
    (void)s, (void)ctx;
    for (int k = 0; f->clip && k < f->n; k++) {
        ScreenVertex divided = camera_divide(f->clip[k], t->width, t->height);
        corners_checked++;
        corners_differ += memcmp(&divided, &f->v[k], sizeof divided) != 0;
    }
}

static const Rasterizer CORNER_CHECKER = {.clear = clear_to_zero, .draw_face = check_corners,
                                          .stored_to_depth = inverse, .clips = true};

static void screen_corners_are_their_clip_corners_divided(void **state)
{
    (void)state;
    Render r;
    Target t;
    Error err;
    three_face_render(&r);
    assert_true(render_target_init(&t, &CORNER_CHECKER, 8, 8, &err));
    corners_checked = corners_differ = 0;
    const int order[3] = {0, 1, 2};
    assert_true(render_faces(&r, &t, &CORNER_CHECKER, order, 3, NULL, NULL, &err));
    expect_count(9, corners_checked, "corners handed over with their clip-space corner");
    expect_count(0, corners_differ, "corners that are not their clip-space corner divided");
    target_free(&t);
    render_free(&r);
}

/* Face 0's first corner (0, 0, -5) projects to the centre (4, 4) of an 8 x 8
 * screen; the stand-in stores 1/5 there, and the view depth reads back 5. */
static void view_depth_converts_and_marks_the_background(void **state)
{
    (void)state;
    Render r;
    Target t;
    Error err;
    three_face_render(&r);
    assert_true(render_target_init(&t, &RECORDER, 8, 8, &err));
    assert_true(render_faces(&r, &t, &RECORDER, NULL, 0, NULL, NULL, &err));
    float *d = render_view_depth(&t, &RECORDER);
    assert_non_null(d);
    assert_true(fabs(d[4 * 8 + 4] - 5.0) < 1e-6);
    assert_true(isinf(d[0]) && d[0] > 0);
    free(d);
    target_free(&t);
    render_free(&r);
}

/* The summary of a 2 x 2 target with overdraw 0, 1, 2, 0: three fragments over
 * two covered pixels, an average of 1.50. */
static void summary_has_the_documented_format(void **state)
{
    (void)state;
    Render r;
    Target t;
    Error err;
    three_face_render(&r);
    assert_true(render_target_init(&t, &RECORDER, 2, 2, &err));
    assert_true(render_faces(&r, &t, &RECORDER, NULL, 0, NULL, NULL, &err));
    t.overdraw[0] = 0, t.overdraw[1] = 1, t.overdraw[2] = 2, t.overdraw[3] = 0;
    t.stats.tested = 3, t.stats.passed = 2, t.stats.failed = 1;
    Options opt = {0};
    opt.out = "x/pic.png";
    opt.depth_out = "d.pfm";
    char buf[1024] = "";
    FILE *f = fmemopen(buf, sizeof buf - 1, "w");
    assert_non_null(f);
    render_print_summary(f, "recorder", &r, &t, &opt);
    fclose(f);
    assert_string_equal(buf,
                        "recorder: three faces (3 faces): 1 triangle drawn, 2 dropped at the "
                        "near plane\n"
                        "  fragments: 3 tested, 2 passed, 1 failed; average overdraw 1.50 over 2 "
                        "covered pixels\n"
                        "  wrote x/pic.png\n"
                        "  wrote d.pfm\n");
    target_free(&t);
    render_free(&r);
}

static void outputs_are_written_into_new_directories(void **state)
{
    (void)state;
    Render r;
    Target t;
    Error err;
    three_face_render(&r);
    assert_true(render_target_init(&t, &RECORDER, 8, 8, &err));
    assert_true(render_faces(&r, &t, &RECORDER, NULL, 0, NULL, NULL, &err));
    const char *dir = test_dir("render_outputs");
    char png[512], pfm[512], pgm[512], ids[512];
    snprintf(png, sizeof png, "%s/a/b/pic.png", dir);
    snprintf(ids, sizeof ids, "%s/d/ids.png", dir);
    snprintf(pfm, sizeof pfm, "%s/c/depth.pfm", dir);
    snprintf(pgm, sizeof pgm, "%s/over.pgm", dir);
    Options opt = {0};
    opt.out = png;
    opt.depth_out = pfm;
    opt.overdraw_out = pgm;
    opt.id_out = ids;
    opt.shade = SHADE_FLAT;
    if (!render_write(&r, &t, &RECORDER, &opt, &err))
        fail_msg("render_write: %s", err.msg);
    Image im;
    assert_true(file_exists(png));
    assert_true(image_read_png(&im, ids, &err));
    expect_face_at(&im, 4, 4, 0, "");
    expect_face_at(&im, 0, 0, NO_FACE, "");
    image_free(&im);
    assert_true(file_exists(pfm) && file_exists(pgm));

    /* A path through a regular file cannot be made: false, a message, no file. */
    char bad[600];
    snprintf(bad, sizeof bad, "%s/nested/x.png", pgm);
    opt.out = bad;
    opt.depth_out = opt.overdraw_out = opt.id_out = NULL;
    assert_false(render_write(&r, &t, &RECORDER, &opt, &err));
    assert_true(strlen(err.msg) > 0);
    assert_false(file_exists(bad));
    target_free(&t);
    render_free(&r);
}

/* A box from (0, 0, 0) to (2, 2, 2): centre (1, 1, 1), radius sqrt(3). The
 * fitted camera looks at the centre from far enough, and near and far hold it. */
static void obj_camera_is_fitted_to_the_bounds(void **state)
{
    (void)state;
    Mesh m;
    Error err;
    mesh_init(&m);
    for (int i = 0; i < 8; i++)
        assert_true(mesh_add_vertex(&m, vec3(2.0 * (i & 1), 2.0 * (i >> 1 & 1), 2.0 * (i >> 2)),
                                    &err) >= 0);
    SceneInfo s = render_fit_camera(&m, 400, 300);
    assert_true(fabs(s.target.x - 1) < 1e-12 && fabs(s.target.y - 1) < 1e-12 &&
                fabs(s.target.z - 1) < 1e-12);
    double dist = vec3_length(vec3_sub(s.eye, s.target)), radius = sqrt(3.0);
    assert_true(dist * sin(s.fovy / 2 * PI / 180) > radius); /* sphere in view */
    assert_true(s.near > 0 && s.near < dist - radius);
    assert_true(s.far > dist + radius);
    mesh_free(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(polygon_inside_the_band_is_copied),
        cmocka_unit_test(polygon_beyond_the_band_is_dropped),
        cmocka_unit_test(clip_puts_new_corners_on_the_band_with_the_lessons_depth),
        cmocka_unit_test(clip_survives_the_largest_doubles),
        cmocka_unit_test(id_colours_are_face_plus_one_big_endian),
        cmocka_unit_test(id_colours_number_at_most_16777215_faces),
        cmocka_unit_test(shade_id_colours_are_far_apart),
        cmocka_unit_test(flat_colour_is_kd_times_lambert),
        cmocka_unit_test(faces_without_material_get_distinct_palette_colours),
        cmocka_unit_test(faces_reach_the_rasterizer_in_the_given_order),
        cmocka_unit_test(screen_corners_are_their_clip_corners_divided),
        cmocka_unit_test(view_depth_converts_and_marks_the_background),
        cmocka_unit_test(summary_has_the_documented_format),
        cmocka_unit_test(outputs_are_written_into_new_directories),
        cmocka_unit_test(obj_camera_is_fitted_to_the_bounds),
    };
    return cmocka_run_group_tests_name("render", tests, NULL, NULL);
}
