/* test_cli.c: build/bin/03_perspective_z end to end: its pictures (the default
 * render, every scene by face id, a torus knot read from an OBJ file), its
 * summary, its naive rule against lesson 02's program, and its errors. */
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
#include "test_support.h"

#define PROGRAM "03_perspective_z"
#define GROUP "03_perspective_z"

/* ---- Expected images ---------------------------------------------------------- */

/* No flag but --out: grazing, flat, 800 x 600, the perspective rule. */
static void default_render_matches_expected(void **state)
{
    (void)state;
    char out[4096];
    snprintf(out, sizeof out, "%s", path_join(test_dir("03_default"), "default.png"));
    const char *args[] = {"--out", out, NULL};
    free(run_ok(PROGRAM, args));
    Image im = read_png(out);
    expect_count(800, im.width, "picture width");
    expect_count(600, im.height, "picture height");
    expect_image(&im, GROUP, "default");
    image_free(&im);
}

/* Every built-in scene by face id, at 160 x 120. */
static void every_scene_by_face_id_matches_expected(void **state)
{
    (void)state;
    const char *dir = test_dir("03_scenes");
    for (int i = 0; i < scene_count(); i++) {
        char name[96], out[4096];
        snprintf(name, sizeof name, "%s_id", scene_at(i)->name);
        snprintf(out, sizeof out, "%s/%s.png", dir, name);
        const char *args[] = {"--scene", scene_at(i)->name, "--shade", "id", "--width", "160",
                              "--height", "120", "--out", out, NULL};
        free(run_ok(PROGRAM, args));
        Image im = read_png(out);
        expect_image(&im, GROUP, name);
        image_free(&im);
    }
}

/* A model from outside the program: tools/make_obj writes the torus knot
 * (3072 quads, two materials) as OBJ and MTL; the lesson reads it back with
 * --obj, frames it with its fitted camera and shades it flat, at 400 x 300.
 * The picture docs/images/03_knot.png is made the same way, at 800 x 600. */
static void knot_model_from_obj_matches_expected(void **state)
{
    (void)state;
    const char *dir = test_dir("03_knot");
    char obj[4096], out[4096];
    snprintf(obj, sizeof obj, "%s", path_join(dir, "knot.obj"));
    snprintf(out, sizeof out, "%s", path_join(dir, "knot.png"));
    const char *make[] = {"knot", obj, NULL};
    RunResult m = run_tool("make_obj", make);
    if (m.status != 0)
        fail_msg("make_obj knot exited with %d: %s", m.status, m.err);
    run_result_free(&m);
    const char *args[] = {"--obj", obj, "--shade", "flat", "--width", "400", "--height", "300",
                          "--out", out, NULL};
    char *summary = run_ok(PROGRAM, args);
    if (!strstr(summary, "(3072 faces): 6144 triangles drawn, 0 dropped at the near plane"))
        fail_msg("the summary should count 3072 quads, 6144 triangles:\n%s", summary);
    free(summary);
    Image im = read_png(out);
    expect_image(&im, GROUP, "knot_obj");
    image_free(&im);
}

/* ---- The naive rule is lesson 02's ------------------------------------------------- */

/* --depth-interp naive draws exactly what lesson 02 draws: the same faces win
 * the same pixels, at the same depths (both files compared byte for byte). */
static void naive_rule_draws_what_lesson_02_draws(void **state)
{
    (void)state;
    const char *scenes[2] = {"grazing", "cubes"};
    const char *dir = test_dir("03_naive_is_02");
    for (int s = 0; s < 2; s++) {
        char *files[2][2];
        size_t lens[2][2];
        for (int lesson = 0; lesson < 2; lesson++) {
            char png[4096], pfm[4096], picture[4096];
            snprintf(png, sizeof png, "%s/%s_%d.png", dir, scenes[s], lesson);
            snprintf(pfm, sizeof pfm, "%s/%s_%d.pfm", dir, scenes[s], lesson);
            snprintf(picture, sizeof picture, "%s/%s_%d_flat.png", dir, scenes[s], lesson);
            const char *args[20] = {"--scene", scenes[s], "--id-out", png, "--width", "200",
                                    "--height", "150", "--out", picture, "--depth-out", pfm};
            int n = 12;
            if (lesson == 0) { /* lesson 02 has no such flag: it knows one rule */
                args[n++] = "--depth-interp";
                args[n++] = "naive";
            }
            args[n] = NULL;
            free(run_ok(lesson == 0 ? PROGRAM : "02_zbuffer", args));
            Error err;
            for (int k = 0; k < 2; k++)
                if (!read_file(k ? pfm : png, 1 << 24, &files[lesson][k], &lens[lesson][k], &err))
                    fail_msg("%s", err.msg);
        }
        for (int k = 0; k < 2; k++) {
            if (lens[0][k] != lens[1][k] || memcmp(files[0][k], files[1][k], lens[0][k]) != 0)
                fail_msg("%s: the %s of --depth-interp naive differs from lesson 02's", scenes[s],
                         k ? "depth file" : "id picture");
        }
        for (int l = 0; l < 2; l++)
            for (int k = 0; k < 2; k++)
                free(files[l][k]);
    }
}

/* ---- Summary ------------------------------------------------------------------- */

static void summary_names_the_rule_and_the_comparison(void **state)
{
    (void)state;
    const char *dir = test_dir("03_summary");
    char out[4096], cmp[4096];
    snprintf(out, sizeof out, "%s", path_join(dir, "pic.png"));
    snprintf(cmp, sizeof cmp, "%s", path_join(dir, "cmp.png"));
    const char *first = "03_perspective_z: scene grazing (2 faces): 4 triangles drawn, "
                        "0 dropped at the near plane\n";

    const char *a1[] = {"--width", "80", "--height", "60", "--out", out, NULL};
    char *s = run_ok(PROGRAM, a1);
    if (strncmp(s, first, strlen(first)) != 0)
        fail_msg("summary starts with:\n%s\nexpected:\n%s", s, first);
    assert_null(strstr(s, "naive"));
    free(s);

    const char *a2[] = {"--width", "80", "--height", "60", "--out", out, "--depth-interp",
                        "naive", NULL};
    s = run_ok(PROGRAM, a2);
    assert_non_null(strstr(s, "  depth-interp naive: d was interpolated linearly on the "
                              "screen, as in lesson 02\n"));
    free(s);

    const char *a3[] = {"--width", "80", "--height", "60", "--out", out, "--bug", "negated-w",
                        NULL};
    s = run_ok(PROGRAM, a3);
    assert_non_null(strstr(s, "  bug negated-w: the buffer held -d, so the farthest surface "
                              "won each pixel\n"));
    free(s);

    /* The comparison draws the scene twice more; the summary still counts the
     * main render once: 4 triangles. */
    const char *a4[] = {"--width", "80", "--height", "60", "--out", out, "--compare-naive", cmp,
                        NULL};
    s = run_ok(PROGRAM, a4);
    if (strncmp(s, first, strlen(first)) != 0)
        fail_msg("with --compare-naive the summary starts with:\n%s\nexpected:\n%s", s, first);
    char wrote[4200];
    snprintf(wrote, sizeof wrote, "  wrote %s\n", cmp);
    assert_non_null(strstr(s, "  the naive rule shows another face at "));
    assert_non_null(strstr(s, wrote));
    free(s);
    assert_true(file_exists(cmp));
}

/* ---- Errors ------------------------------------------------------------------ */

static void bad_lesson_flags_are_usage_errors(void **state)
{
    (void)state;
    const char *a1[] = {"--depth-interp", "linear", NULL};
    expect_run_error(PROGRAM, a1, 2,
                     "03_perspective_z: error: --depth-interp: 'linear' is not one of "
                     "perspective, naive\n");
    const char *a2[] = {"--bug", "clear-zero", NULL}; /* lesson 02's bugs stay in lesson 02 */
    expect_run_error(PROGRAM, a2, 2,
                     "03_perspective_z: error: --bug: 'clear-zero' is not one of "
                     "negated-w\n");
    const char *a3[] = {"--painter", NULL};
    expect_run_error(PROGRAM, a3, 2,
                     "03_perspective_z: error: unknown flag '--painter' (try --help)\n");
    const char *a4[] = {"--depth-interp", "naive", "--bug", "negated-w", NULL};
    expect_run_error(PROGRAM, a4, 2,
                     "03_perspective_z: error: --bug and --depth-interp naive cannot be "
                     "used together\n");
    const char *a5[] = {"--compare-naive", NULL};
    expect_run_error(PROGRAM, a5, 2, "03_perspective_z: error: --compare-naive needs a value\n");
    const char *a7[] = {"--out", "same.png", "--compare-naive", "same.png", NULL};
    expect_run_error(PROGRAM, a7, 2,
                     "03_perspective_z: error: --out and --compare-naive both name "
                     "same.png\n");
    const char *a6[] = {"--depth-interp", "naive", "--depth-interp", "naive", NULL};
    expect_run_error(PROGRAM, a6, 2, "03_perspective_z: error: --depth-interp given twice\n");
}

/* --compare-naive into a path that cannot be made: status 1, one line, and
 * no comparison picture. */
static void unwritable_comparison_fails_cleanly(void **state)
{
    (void)state;
    const char *dir = test_dir("03_unwritable");
    char blocker[4096], cmp[4200], out[4096];
    snprintf(blocker, sizeof blocker, "%s", path_join(dir, "file"));
    snprintf(out, sizeof out, "%s", path_join(dir, "pic.png"));
    FILE *f = fopen(blocker, "w");
    assert_non_null(f);
    fclose(f);
    snprintf(cmp, sizeof cmp, "%s/cmp.png", blocker); /* "file" is a file: no directory */
    const char *args[] = {"--width", "8", "--height", "8", "--out", out, "--compare-naive", cmp,
                          NULL};
    char message[9000];
    snprintf(message, sizeof message,
             "03_perspective_z: error: cannot create directory %s: a file of that name exists\n",
             blocker);
    expect_run_error(PROGRAM, args, 1, message);
    assert_false(file_exists(cmp));
}

static void missing_obj_fails_without_output(void **state)
{
    (void)state;
    const char *dir = test_dir("03_missing");
    char out[4096], obj[4096];
    snprintf(out, sizeof out, "%s", path_join(dir, "never.png"));
    snprintf(obj, sizeof obj, "%s", path_join(dir, "nothing.obj"));
    const char *args[] = {"--obj", obj, "--out", out, NULL};
    char message[9000];
    snprintf(message, sizeof message,
             "03_perspective_z: error: cannot read %s: No such file or directory\n", obj);
    expect_run_error(PROGRAM, args, 1, message);
    assert_false(file_exists(out));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(default_render_matches_expected),
        cmocka_unit_test(every_scene_by_face_id_matches_expected),
        cmocka_unit_test(knot_model_from_obj_matches_expected),
        cmocka_unit_test(naive_rule_draws_what_lesson_02_draws),
        cmocka_unit_test(summary_names_the_rule_and_the_comparison),
        cmocka_unit_test(bad_lesson_flags_are_usage_errors),
        cmocka_unit_test(unwritable_comparison_fails_cleanly),
        cmocka_unit_test(missing_obj_fails_without_output),
    };
    return cmocka_run_group_tests_name("03_perspective_z command line", tests, NULL, NULL);
}
