/* test_program.c: build/bin/04_scanline_inverse_z run end to end: the
 * summary with its front object, the pictures of every built-in scene, the
 * depth file, and how it refuses bad input. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness/image_io.h"
#include "harness/scene.h"
#include "test_support.h"

#define PROGRAM "04_scanline_inverse_z"
#define GROUP "04_scanline_inverse_z"
#define TEXT_MAX 4096

/* ---- the default run ------------------------------------------------------ */

/* The walls scene, eye (0, 1.6, 1) looking at (0, 1.4, -20): the centre
 * pixel looks through the doorway onto the end wall at z = -41, the last of
 * the scene's 98 faces. Along the view axis f = (0, -0.2, -21) / |...| the
 * wall is 42 units away in z, so d = 42 / (21 / sqrt(21^2 + 0.2^2))
 * = 2 sqrt(441.04) = 42.0019 (the half-pixel offset of the pixel centre
 * changes it by about 1e-5 relative). */
static void default_run_draws_the_walls_and_finds_the_front_object(void **state)
{
    (void)state;
    const char *args[] = {NULL};
    const char *dir = test_dir("l04_default"); /* not the student's out/ */
    RunResult r = run_program_in(dir, PROGRAM, args);
    expect_no_message(r.err, PROGRAM);
    expect_count(0, r.status, "exit status");
    expect_line(r.out, "04_scanline_inverse_z: scene walls (98 faces): ");
    expect_line(r.out, "  wrote out/04_scanline_inverse_z.png\n");
    expect_line(r.out, "  front object: face 97 at d = 42.002 at the screen centre (400,300)\n");
    run_result_free(&r);
    Image im = read_png(path_join(dir, "out/04_scanline_inverse_z.png"));
    expect_count(800, im.width, "picture width");
    expect_count(600, im.height, "picture height");
    expect_image(&im, GROUP, "default_render");
    image_free(&im);
}

/* ---- every built-in scene in the three shadings --------------------------- */

static void render_scene(const char *scene, const char *shade, const char *out)
{
    const char *args[] = {"--scene", scene, "--shade", shade, "--width", "240",
                          "--height", "180", "--out", out, NULL};
    RunResult r = run_program(PROGRAM, args);
    if (r.status != 0)
        fail_msg("--scene %s --shade %s: exit status %d: %s", scene, shade, r.status, r.err);
    run_result_free(&r);
}

static void every_scene_matches_its_expected_pictures(void **state)
{
    (void)state;
    const char *dir = test_dir("l04_scenes");
    const char *shades[] = {"flat", "depth", "id"};
    for (int i = 0; i < scene_count(); i++)
        for (int s = 0; s < 3; s++) {
            char name[128];
            snprintf(name, sizeof name, "%s_%s", scene_at(i)->name, shades[s]);
            Path out = in_dir(dir, "scene.png");
            render_scene(scene_at(i)->name, shades[s], out.path);
            Image im = read_png(out.path);
            expect_image(&im, GROUP, name);
            image_free(&im);
        }
}

/* ---- --shade depth: the whole grey range over the depths drawn ---------- */

/* The walls corridor reaches from about 1 to about 42 units. --shade depth
 * gives the nearest drawn pixel (the smallest d of --depth-out) grey 255, the
 * farthest 48, every other pixel 255 - 207 t with t linear in 1/d between
 * them, and the background DEPTH_BACKGROUND; linear in d, most of the
 * corridor would be near-white, linear in 1/d less than half of it is. */
static void shade_depth_spreads_greys_over_the_drawn_depths(void **state)
{
    (void)state;
    const char *dir = test_dir("l04_shade_depth");
    Path out = in_dir(dir, "depth.png"), pfm = in_dir(dir, "depth.pfm");
    const char *args[] = {"--shade", "depth", "--width", "240", "--height", "180",
                          "--out", out.path, "--depth-out", pfm.path, NULL};
    RunResult r = run_program(PROGRAM, args);
    expect_count(0, r.status, "exit status");
    run_result_free(&r);
    Image im = read_png(out.path);
    float *d;
    int w, h;
    Error err;
    if (!read_pfm(&d, &w, &h, pfm.path, &err))
        fail_msg("%s", err.msg);
    double dmin = INFINITY, dmax = 0;
    for (int i = 0; i < w * h; i++)
        if (isfinite(d[i])) {
            dmin = fmin(dmin, d[i]);
            dmax = fmax(dmax, d[i]);
        }
    int lightest = 0, darkest = 255;
    long drawn = 0, near_white = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            float v = d[y * w + x];
            Rgb c = image_get(&im, x, y);
            if (!isfinite(v)) {
                expect_colour(DEPTH_BACKGROUND, c, "background");
                continue;
            }
            double t = (1 / dmin - 1 / (double)v) / (1 / dmin - 1 / dmax);
            int want = (int)lround(255 - 207 * t);
            if (c.r != c.g || c.g != c.b || abs(c.r - want) > 1)
                fail_msg("pixel (%d,%d) at d = %g is (%d,%d,%d), expected grey %d", x, y, v, c.r,
                         c.g, c.b, want);
            lightest = c.r > lightest ? c.r : lightest;
            darkest = c.r < darkest ? c.r : darkest;
            drawn++;
            near_white += c.r >= 230;
        }
    expect_count(255, lightest, "grey of the nearest pixel");
    expect_count(48, darkest, "grey of the farthest pixel");
    if (near_white * 2 > drawn)
        fail_msg("%ld of %ld drawn pixels are near-white (grey >= 230)", near_white, drawn);
    printf("  walls: d from %.3f to %.3f, %ld of %ld drawn pixels near-white\n", dmin, dmax,
           near_white, drawn);
    free(d);
    image_free(&im);
}

/* ---- a quad whose depth is known ------------------------------------------ */

/* A square x, y in [-1, 1] at z = -5, seen from the origin down -Z with
 * fovy 90 on a 100 x 100 screen: x_ndc = x / (d tan 45) = +-0.2, so
 * x_s = (1 +- 0.2) * 50 = 40 .. 60, the same in y: pixels 40..59 in both,
 * 400 of them, all at d = 5. */
#define SQUARE_OBJ "v -1 -1 -5\nv 1 -1 -5\nv 1 1 -5\nv -1 1 -5\nf 1 2 3 4\n"
#define FAR_SQUARE_OBJ "v -1 -1 -20\nv 1 -1 -20\nv 1 1 -20\nv -1 1 -20\nf 1 2 3 4\n"

static RunResult render_square(const char *obj, const char *out, const char *depth_out)
{
    const char *args[] = {"--obj", obj, "--eye", "0,0,0", "--target", "0,0,-1", "--up",
                          "0,1,0", "--fovy", "90", "--near", "1", "--far", "10",
                          "--width", "100", "--height", "100", "--out", out,
                          depth_out ? "--depth-out" : NULL, depth_out, NULL};
    return run_program(PROGRAM, args);
}

/* --depth-out holds view depth d (docs/conventions.md), not the 1/d the buffer
 * stores: 5 on the square, +infinity around it. */
static void depth_out_writes_view_depth_not_its_inverse(void **state)
{
    (void)state;
    const char *dir = test_dir("l04_depth_out");
    Path obj = in_dir(dir, "square.obj"), out = in_dir(dir, "square.png"),
         pfm = in_dir(dir, "square.pfm");
    write_text(obj.path, SQUARE_OBJ);
    RunResult r = render_square(obj.path, out.path, pfm.path);
    expect_count(0, r.status, "exit status");
    expect_line(r.out, "  fragments: 400 tested, 400 passed, 0 failed; ");
    expect_line(r.out, "  front object: face 0 at d = 5.000 at the screen centre (50,50)\n");
    run_result_free(&r);

    float *d;
    int w, h;
    Error err;
    if (!read_pfm(&d, &w, &h, pfm.path, &err))
        fail_msg("%s", err.msg);
    expect_count(100, w, "depth picture width");
    expect_count(100, h, "depth picture height");
    for (int y = 0; y < 100; y++)
        for (int x = 0; x < 100; x++) {
            float v = d[y * 100 + x];
            bool inside = x >= 40 && x < 60 && y >= 40 && y < 60;
            if (inside ? fabsf(v - 5.0f) > 5e-6f : !isinf(v))
                fail_msg("depth at (%d,%d) is %g, expected %s", x, y, v,
                         inside ? "5" : "+infinity");
        }
    free(d);
}

/* The same square at d = 20, beyond the far plane at 10: every fragment is
 * discarded before the depth test, and the centre shows nothing. */
static void nothing_at_the_centre_is_reported(void **state)
{
    (void)state;
    const char *dir = test_dir("l04_far_square");
    Path obj = in_dir(dir, "far.obj"), out = in_dir(dir, "far.png");
    write_text(obj.path, FAR_SQUARE_OBJ);
    RunResult r = render_square(obj.path, out.path, NULL);
    expect_count(0, r.status, "exit status");
    expect_line(r.out, "  fragments: 0 tested, 0 passed, 0 failed; no pixel covered\n");
    expect_line(r.out, "  front object: nothing at the screen centre (50,50)\n");
    run_result_free(&r);
}

/* ---- lesson 03's flags ------------------------------------------------------ */

/* De Goes' two z-buffers as an OBJ file: a triangle at d = 5 with its apex
 * at the top centre and its base along the bottom of an 8 x 3 screen, and a
 * quad at d = 6 larger than the screen. Camera at the origin looking down -Z,
 * fovy 90: y_ndc = y / d and x_ndc = x / (d * 8/3), so screen (x_s, y_s) at
 * depth d is world x = (x_s / 4 - 1) * d * 8/3, y = (1 - y_s / 1.5) * d. */
#define TWO_BUFFERS_OBJ                                                         \
    "v 0 5 -5\nv 13.333333333333334 -5 -5\nv -13.333333333333334 -5 -5\n" \
    "v -16 6 -6\nv 16 6 -6\nv 16 -6 -6\nv -16 -6 -6\n"                    \
    "f 1 2 3\nf 4 5 6 7\n"

static RunResult render_two_buffers(const char *dir, const char *const *extra)
{
    Path obj = in_dir(dir, "two_buffers.obj"), out = in_dir(dir, "two_buffers.png");
    write_text(obj.path, TWO_BUFFERS_OBJ);
    const char *args[32] = {"--obj", obj.path, "--eye", "0,0,0", "--target", "0,0,-1",
                            "--up", "0,1,0", "--fovy", "90", "--near", "1", "--far", "10",
                            "--width", "8", "--height", "3", "--out", out.path};
    int n = 20;
    for (int k = 0; extra[k]; k++)
        args[n++] = extra[k];
    args[n] = NULL;
    return run_program(PROGRAM, args);
}

/* --ascii prints what the buffer holds, 1/d, in ten steps from the nearest
 * (largest) value 1/5 = 0.2 as 0 to the farthest 1/6 as 9: so the triangle
 * prints as 0s and the quad as 9s, in the shape of De Goes' second map
 * (66655666 / 66555566 / 65555556). --trace 4,1 lists pixel (4,1)'s two
 * fragments: the triangle's 1/d = 0.2 beats the cleared 0, the quad's 1/6
 * (the float 0.16666667) loses to 0.2. */
static void ascii_and_trace_speak_of_inverse_depth(void **state)
{
    (void)state;
    const char *extra[] = {"--ascii", "--trace", "4,1", NULL};
    RunResult r = render_two_buffers(test_dir("l04_two_buffers_text"), extra);
    expect_no_message(r.err, PROGRAM);
    expect_count(0, r.status, "exit status");
    expect_line(r.out, "  fragments: 36 tested, 24 passed, 12 failed; ");
    expect_line(r.out, "trace pixel (4,1): 2 fragments\n");
    expect_line(r.out, "  1. face 0   1/d=0.2          stored=0            passed\n");
    expect_line(r.out, "  2. face 1   1/d=0.16666667   stored=0.2          failed\n");
    expect_line(r.out, "winner: face 0, stored 1/d=0.2\n");
    expect_line(r.out, "0 = nearest (1/d=0.2) .. 9 = farthest (1/d=0.16666667)");
    expect_line(r.out, "\n99900999\n99000099\n90000009\n");
    run_result_free(&r);
}

/* --steps: the cleared buffer, then one frame per face: 3 pairs for 2 faces. */
static void steps_write_a_frame_per_face(void **state)
{
    (void)state;
    const char *dir = test_dir("l04_two_buffers_steps");
    Path steps = in_dir(dir, "steps");
    const char *extra[] = {"--steps", steps.path, NULL};
    RunResult r = render_two_buffers(dir, extra);
    expect_count(0, r.status, "exit status");
    run_result_free(&r);
    const char *frames[] = {"step_0000.png", "step_0001.png", "step_0002.png",
                            "step_0002_depth.png"};
    for (int k = 0; k < 4; k++)
        if (!file_exists(path_join(steps.path, frames[k])))
            fail_msg("--steps did not write %s", frames[k]);
    assert_false(file_exists(path_join(steps.path, "step_0003.png")));
}

/* ---- bad input ------------------------------------------------------------- */

static void bad_command_lines_are_refused_with_status_2(void **state)
{
    (void)state;
    const char *dir = test_dir("l04_refused");
    Path out = in_dir(dir, "never.png");
    const char *unknown[] = {"--out", out.path, "--bogus", NULL};
    expect_run_refused(PROGRAM, unknown, 2, "unknown flag '--bogus' (try --help)", out.path);
    const char *scene[] = {"--out", out.path, "--scene", "nope", NULL};
    char known[1024] = "--scene: no scene named 'nope' (known: "; /* every scene of scene.c */
    for (int i = 0; i < scene_count(); i++)
        snprintf(known + strlen(known), sizeof known - strlen(known), "%s%s", i ? ", " : "",
                 scene_at(i)->name);
    strcat(known, ")");
    assert_non_null(strstr(known, "(known: triangles3, interpenetrate, cubes, grazing, walls"));
    expect_run_refused(PROGRAM, scene, 2, known, out.path);
    const char *width[] = {"--out", out.path, "--width", "0", NULL};
    expect_run_refused(PROGRAM, width, 2, "--width: 0 is out of range (1 to 16384)", out.path);
    /* The naive comparison is lesson 03's extra (its extras/): not carried here. */
    const char *interp[] = {"--out", out.path, "--depth-interp", "naive", NULL};
    expect_run_refused(PROGRAM, interp, 2, "unknown flag '--depth-interp' (try --help)", out.path);
}

static void missing_obj_fails_with_status_1(void **state)
{
    (void)state;
    const char *dir = test_dir("l04_missing");
    Path out = in_dir(dir, "never.png"), obj = in_dir(dir, "missing.obj");
    const char *args[] = {"--out", out.path, "--obj", obj.path, NULL};
    char message[TEXT_MAX];
    snprintf(message, sizeof message, "cannot read %s: No such file or directory", obj.path);
    expect_run_refused(PROGRAM, args, 1, message, out.path);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(default_run_draws_the_walls_and_finds_the_front_object),
        cmocka_unit_test(every_scene_matches_its_expected_pictures),
        cmocka_unit_test(depth_out_writes_view_depth_not_its_inverse),
        cmocka_unit_test(shade_depth_spreads_greys_over_the_drawn_depths),
        cmocka_unit_test(nothing_at_the_centre_is_reported),
        cmocka_unit_test(ascii_and_trace_speak_of_inverse_depth),
        cmocka_unit_test(steps_write_a_frame_per_face),
        cmocka_unit_test(bad_command_lines_are_refused_with_status_2),
        cmocka_unit_test(missing_obj_fails_with_status_1),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
