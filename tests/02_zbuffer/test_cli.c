/* test_cli.c: build/bin/02_zbuffer end to end: its pictures, its outputs, its
 * summary and its errors. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness/file.h"
#include "harness/image_io.h"
#include "harness/scene.h"
#include "harness/shade.h"
#include "test_support.h"

#define PROGRAM "02_zbuffer"
#define GROUP "02_zbuffer"

/* Runs the lesson, expecting success, and reads back the picture it wrote. */
static void render_to_image(const char *const *args, const char *out, Image *im)
{
    free(run_ok(PROGRAM, args));
    *im = read_png(out);
}

/* ---- Expected images ---------------------------------------------------------- */

static void default_render_matches_expected(void **state)
{
    (void)state;
    const char *out = path_join(test_dir("02_default"), "default.png");
    const char *args[] = {"--out", out, NULL};
    Image im;
    render_to_image(args, out, &im);
    expect_count(800, im.width, "picture width"); /* the defaults: 800 x 600, triangles3, flat */
    expect_count(600, im.height, "picture height");
    expect_image(&im, GROUP, "default");
    image_free(&im);
}

/* Every built-in scene, flat and --shade id, at 160 x 120. */
static void every_scene_matches_expected(void **state)
{
    (void)state;
    const char *dir = test_dir("02_scenes");
    const char *shades[2] = {"flat", "id"};
    for (int i = 0; i < scene_count(); i++)
        for (int s = 0; s < 2; s++) {
            char name[96], file[128];
            snprintf(name, sizeof name, "%s_%s", scene_at(i)->name, shades[s]);
            snprintf(file, sizeof file, "%s.png", name);
            const char *out = path_join(dir, file);
            const char *args[] = {"--scene", scene_at(i)->name, "--shade", shades[s],
                                  "--width", "160", "--height", "120", "--out", out, NULL};
            Image im;
            render_to_image(args, out, &im);
            expect_image(&im, GROUP, name);
            image_free(&im);
        }
}

/* The pictures the page shows side by side: the painter on triangles3, and
 * the separate-buffers bug on interpenetrate. */
static void wrong_pictures_match_expected(void **state)
{
    (void)state;
    const char *dir = test_dir("02_wrong");
    const char *painter = path_join(dir, "painter.png");
    const char *a1[] = {"--painter", "--width", "160", "--height", "120", "--out", painter, NULL};
    Image im;
    render_to_image(a1, painter, &im);
    expect_image(&im, GROUP, "triangles3_painter");
    image_free(&im);

    const char *sep = path_join(dir, "separate.png");
    const char *a2[] = {"--scene", "interpenetrate", "--bug", "separate-buffers", "--width",
                        "160", "--height", "120", "--out", sep, NULL};
    render_to_image(a2, sep, &im);
    expect_image(&im, GROUP, "interpenetrate_separate_buffers");
    image_free(&im);
}

/* --bug clear-zero: nothing passes, so the picture is the background alone. */
static void clear_zero_picture_is_background_only(void **state)
{
    (void)state;
    const char *out = path_join(test_dir("02_clear_zero"), "zero.png");
    const char *args[] = {"--bug", "clear-zero", "--width", "40", "--height", "30",
                          "--out", out, NULL};
    Image im;
    render_to_image(args, out, &im);
    for (int y = 0; y < im.height; y++)
        for (int x = 0; x < im.width; x++) {
            Rgb c = image_get(&im, x, y);
            if (c.r != FLAT_BACKGROUND.r || c.g != FLAT_BACKGROUND.g || c.b != FLAT_BACKGROUND.b)
                fail_msg("pixel (%d,%d) is (%d,%d,%d), not the background", x, y, c.r, c.g, c.b);
        }
    image_free(&im);
}

/* ---- Outputs and summary -------------------------------------------------------- */

/* A 16-bit binary PGM as write_pgm16 writes it: "P5\n<w> <h>\n65535\n", big-endian. */
static uint32_t *read_pgm16(const char *path, int *w, int *h)
{
    char *data;
    size_t len;
    Error err;
    if (!read_file(path, 1 << 26, &data, &len, &err))
        fail_msg("%s", err.msg);
    int maxval, used;
    if (sscanf(data, "P5 %d %d %d%n", w, h, &maxval, &used) != 3 || maxval != 65535)
        fail_msg("%s is not a 16-bit PGM", path);
    size_t n = (size_t)*w * (size_t)*h;
    const unsigned char *p = (const unsigned char *)data + used + 1; /* one blank after maxval */
    assert_true((size_t)used + 1 + 2 * n == len);
    uint32_t *v = malloc(n * sizeof *v);
    for (size_t i = 0; i < n; i++)
        v[i] = (uint32_t)p[2 * i] << 8 | p[2 * i + 1];
    free(data);
    return v;
}

/* The summary's numbers agree with the files: fragments tested = the sum of
 * the overdraw picture, covered pixels = its nonzero pixels, tested = passed
 * + failed; the depth file holds +infinity where nothing was drawn and the
 * hand-computed depth 9.489 at pixel (70, 90) (test_zbuffer.c derives it). */
static void summary_agrees_with_the_written_files(void **state)
{
    (void)state;
    const char *dir = test_dir("02_outputs");
    const char *png = path_join(dir, "pic.png"), *pfm = path_join(dir, "sub/depth.pfm"),
               *pgm = path_join(dir, "sub/over.pgm");
    const char *args[] = {"--width", "200", "--height", "150", "--out", png, "--depth-out",
                          pfm, "--overdraw-out", pgm, NULL};
    RunResult r = run_program(PROGRAM, args);
    expect_count(0, r.status, "exit status");

    const char *first = "02_zbuffer: scene triangles3 (3 faces): 3 triangles drawn, "
                        "0 dropped at the near plane\n";
    if (strncmp(r.out, first, strlen(first)) != 0)
        fail_msg("summary starts with:\n%s\nexpected:\n%s", r.out, first);
    unsigned long long tested, passed, failed;
    double average;
    long covered;
    const char *line2 = r.out + strlen(first);
    if (sscanf(line2, "  fragments: %llu tested, %llu passed, %llu failed; average overdraw "
                      "%lf over %ld covered pixels", &tested, &passed, &failed, &average,
               &covered) != 5)
        fail_msg("second line of the summary not understood:\n%s", line2);
    expect_count((long)(passed + failed), (long)tested, "fragments tested (passed + failed)");
    for (int k = 0; k < 3; k++) {
        const char *path = k == 0 ? png : k == 1 ? pfm : pgm;
        char wrote[4200];
        snprintf(wrote, sizeof wrote, "  wrote %s\n", path);
        if (!strstr(r.out, wrote))
            fail_msg("the summary does not say it wrote %s:\n%s", path, r.out);
    }
    run_result_free(&r);

    int w, h;
    uint32_t *over = read_pgm16(pgm, &w, &h);
    expect_count(200, w, "overdraw picture width");
    expect_count(150, h, "overdraw picture height");
    unsigned long long sum = 0;
    long nonzero = 0;
    for (int i = 0; i < w * h; i++) {
        sum += over[i];
        nonzero += over[i] > 0;
    }
    expect_count((long)tested, (long)sum, "fragments in the overdraw picture");
    expect_count(covered, nonzero, "covered pixels in the overdraw picture");
    assert_true(fabs(average - (double)tested / (double)covered) < 0.006);
    free(over);

    float *depth;
    Error err;
    if (!read_pfm(&depth, &w, &h, pfm, &err))
        fail_msg("%s", err.msg);
    assert_true(isinf(depth[0]) && depth[0] > 0); /* corner (0, 0): background */
    assert_true(fabs(depth[90 * 200 + 70] - 9.489) < 1e-3);
    free(depth);
}

/* triangles3's faces 0, 1, 2 are red, green and blue when shaded flat (no
 * material: the flat palette). Every pixel of --id-out names the face whose
 * colour the flat picture shows there, exactly, and black is the background;
 * the summary lists the file among what it wrote. */
static int flat_face(Rgb c)
{
    if (c.r == FLAT_BACKGROUND.r && c.g == FLAT_BACKGROUND.g && c.b == FLAT_BACKGROUND.b)
        return NO_FACE;
    return c.r > c.g && c.r > c.b ? 0 : c.g > c.r && c.g > c.b ? 1 : 2;
}

static void id_out_round_trips_face_indices(void **state)
{
    (void)state;
    const char *dir = test_dir("02_id_out");
    Path flat = in_dir(dir, "flat.png"), ids = in_dir(dir, "ids.png");
    const char *args[] = {"--width", "160", "--height", "120", "--out", flat.path,
                          "--id-out", ids.path, NULL};
    RunResult r = run_program(PROGRAM, args);
    expect_count(0, r.status, "exit status");
    char wrote[4200];
    snprintf(wrote, sizeof wrote, "  wrote %s\n", ids.path);
    if (!strstr(r.out, wrote))
        fail_msg("the summary does not say '%s':\n%s", wrote, r.out);
    run_result_free(&r);

    Image picture = read_png(flat.path), id = read_png(ids.path);
    long count[3] = {0, 0, 0};
    for (int y = 0; y < 120; y++)
        for (int x = 0; x < 160; x++) {
            int want = flat_face(image_get(&picture, x, y));
            int32_t got = face_at(&id, x, y);
            if (got != want)
                fail_msg("pixel (%d,%d): --id-out says face %d, the flat picture shows face %d",
                         x, y, got, want);
            if (got >= 0)
                count[got]++;
        }
    for (int f = 0; f < 3; f++)
        if (count[f] == 0)
            fail_msg("face %d wins no pixel", f);
    image_free(&picture);
    image_free(&id);
}

static double colour_distance(Rgb a, Rgb b)
{
    double dr = a.r - b.r, dg = a.g - b.g, db = a.b - b.b;
    return sqrt(dr * dr + dg * dg + db * db);
}

/* --shade id paints each face in its palette colour (the face read from
 * --id-out of the same run), and triangles3's three faces in colours far
 * apart from each other and from the black background. */
static void shade_id_gives_faces_distinct_colours(void **state)
{
    (void)state;
    const char *dir = test_dir("02_shade_id");
    Path out = in_dir(dir, "shade_id.png"), ids = in_dir(dir, "ids.png");
    const char *args[] = {"--shade", "id", "--width", "160", "--height", "120",
                          "--out", out.path, "--id-out", ids.path, NULL};
    free(run_ok(PROGRAM, args));
    Image picture = read_png(out.path), id = read_png(ids.path);
    for (int y = 0; y < 120; y++)
        for (int x = 0; x < 160; x++) {
            int32_t f = face_at(&id, x, y);
            Rgb want = f == NO_FACE ? ID_BACKGROUND : face_shade_id_colour(f);
            expect_colour(want, image_get(&picture, x, y), "--shade id pixel");
        }
    for (int a = 0; a < 3; a++) {
        if (colour_distance(face_shade_id_colour(a), ID_BACKGROUND) < 150)
            fail_msg("face %d's colour is too close to the background", a);
        for (int b = 0; b < a; b++)
            if (colour_distance(face_shade_id_colour(a), face_shade_id_colour(b)) < 120)
                fail_msg("faces %d and %d have colours too much alike", b, a);
    }
    image_free(&picture);
    image_free(&id);
}

/* An OBJ of one square facing +Z, coloured by its .mtl: --obj frames it, so
 * the centre pixel shows it; --id-out gives it id 1; flat keeps Kd's hue. */
static void obj_file_is_framed_and_coloured(void **state)
{
    (void)state;
    const char *dir = test_dir("02_obj");
    const char *obj = path_join(dir, "square.obj"), *mtl = path_join(dir, "square.mtl");
    FILE *f = fopen(obj, "w");
    assert_non_null(f);
    fputs("mtllib square.mtl\nv 10 10 5\nv 12 10 5\nv 12 12 5\nv 10 12 5\n"
          "usemtl red\nf 1 2 3 4\n", f);
    fclose(f);
    f = fopen(mtl, "w");
    assert_non_null(f);
    fputs("newmtl red\nKd 1 0 0\n", f);
    fclose(f);

    const char *id_png = path_join(dir, "id.png"), *flat_png = path_join(dir, "flat.png");
    const char *a1[] = {"--obj", obj, "--id-out", id_png, "--width", "64", "--height", "48",
                        "--out", path_join(dir, "picture.png"), NULL};
    Image im;
    render_to_image(a1, id_png, &im);
    expect_face_at(&im, 32, 24, 0, "");
    expect_face_at(&im, 0, 0, NO_FACE, "black: nothing there");
    image_free(&im);

    const char *a2[] = {"--obj", obj, "--width", "64", "--height", "48", "--out", flat_png,
                        NULL};
    render_to_image(a2, flat_png, &im);
    Rgb c = image_get(&im, 32, 24);
    expect_colour_that(c, c.r > 64 && c.g == 0 && c.b == 0, "pixel (32, 24)",
                       "the red of material Kd 1 0 0, lit");
    image_free(&im);
}

/* ---- Errors ------------------------------------------------------------------ */

static void bad_lesson_flags_are_usage_errors(void **state)
{
    (void)state;
    const char *a1[] = {"--bug", "off-by-one", NULL};
    expect_run_error(PROGRAM, a1, 2,
                     "02_zbuffer: error: --bug: 'off-by-one' is not one of separate-buffers, "
                     "clear-zero\n");
    const char *a2[] = {"--painter", "--bug", "clear-zero", NULL};
    expect_run_error(PROGRAM, a2, 2,
                     "02_zbuffer: error: --painter and --bug cannot be used together\n");
    const char *a3[] = {"--bug", NULL};
    expect_run_error(PROGRAM, a3, 2, "02_zbuffer: error: --bug needs a value\n");
    const char *a4[] = {"--ascii", NULL}; /* the default 800x600 is too big to read as text */
    expect_run_error(PROGRAM, a4, 2,
                     "02_zbuffer: error: --ascii: the image is 800x600; --ascii prints at "
                     "most 120x60 (use --width and --height)\n");
    const char *a5[] = {"--painter", "--steps", "frames", NULL}; /* no one depth buffer to show */
    expect_run_error(PROGRAM, a5, 2,
                     "02_zbuffer: error: --steps follows one depth buffer face by face; it "
                     "cannot be used with --painter or --bug separate-buffers\n");
}

static void missing_obj_fails_without_output(void **state)
{
    (void)state;
    const char *dir = test_dir("02_missing");
    const char *out = path_join(dir, "never.png");
    const char *args[] = {"--obj", path_join(dir, "nothing.obj"), "--out", out, NULL};
    char message[1200];
    snprintf(message, sizeof message,
             "02_zbuffer: error: cannot read %s: No such file or directory\n", args[1]);
    expect_run_error(PROGRAM, args, 1, message);
    assert_false(file_exists(out));
}

static void unwritable_output_fails_cleanly(void **state)
{
    (void)state;
    const char *dir = test_dir("02_unwritable");
    const char *blocker = path_join(dir, "file");
    FILE *f = fopen(blocker, "w");
    assert_non_null(f);
    fclose(f);
    /* "file" is a file, so "file/pic.png" cannot be created. */
    const char *args[] = {"--out", path_join(blocker, "pic.png"), "--width", "8", "--height",
                          "8", NULL};
    char message[1200];
    snprintf(message, sizeof message,
             "02_zbuffer: error: cannot create directory %s: a file of that name exists\n",
             blocker);
    expect_run_error(PROGRAM, args, 1, message);
}

static void bad_camera_is_a_usage_error(void **state)
{
    (void)state;
    const char *args[] = {"--near", "5", "--far", "1", NULL};
    expect_run_error(PROGRAM, args, 2,
                     "02_zbuffer: error: --far: 1 is out of range (far must be greater than "
                     "near, 5)\n");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(default_render_matches_expected),
        cmocka_unit_test(every_scene_matches_expected),
        cmocka_unit_test(wrong_pictures_match_expected),
        cmocka_unit_test(clear_zero_picture_is_background_only),
        cmocka_unit_test(summary_agrees_with_the_written_files),
        cmocka_unit_test(obj_file_is_framed_and_coloured),
        cmocka_unit_test(id_out_round_trips_face_indices),
        cmocka_unit_test(shade_id_gives_faces_distinct_colours),
        cmocka_unit_test(bad_lesson_flags_are_usage_errors),
        cmocka_unit_test(missing_obj_fails_without_output),
        cmocka_unit_test(unwritable_output_fails_cleanly),
        cmocka_unit_test(bad_camera_is_a_usage_error),
    };
    return cmocka_run_group_tests_name("02_zbuffer command line", tests, NULL, NULL);
}
