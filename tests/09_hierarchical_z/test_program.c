/* test_program.c: build/bin/09_hierarchical_z run end to end. Its pictures
 * (ids, depth, the shader's colours) are lesson 08's in every built-in
 * scene and z-mode, at any tile size; on city, behind the wall drawn first,
 * nine hidden fragments in ten are never tested (the measured share is
 * printed); the tile picture shows the wall's tiles; bad input. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "expect.h"
#include "harness/image_io.h"
#include "test_support.h"

#define PROGRAM "09_hierarchical_z"
#define GROUP "09_hierarchical_z"

static const char *const SCENES[] = {"triangles3", "interpenetrate", "cubes", "grazing",
                                     "walls", "knot", "inside", "ladder", "decals", "crowd",
                                     "city"};
#define NSCENES ((int)(sizeof SCENES / sizeof SCENES[0]))

/* The bytes of a file, to compare two outputs exactly. */
static char *slurp(const char *path, long *len)
{
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    fseek(f, 0, SEEK_END);
    *len = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *b = malloc((size_t)*len + 1);
    assert_non_null(b);
    assert_true(fread(b, 1, (size_t)*len, f) == (size_t)*len);
    fclose(f);
    return b;
}

static void expect_same_file(const char *a, const char *b, const char *what)
{
    long la, lb;
    char *x = slurp(a, &la), *y = slurp(b, &lb);
    if (la != lb || memcmp(x, y, (size_t)la) != 0)
        fail_msg("%s differs from lesson 08's", what);
    free(x);
    free(y);
}

/* One scene in one z-mode through lessons 08 and 09: lesson 09's picture
 * drawn (expect_drawn), and --id-out, --depth-out and --colour-out byte for
 * byte the same. */
static void same_as_lesson_08(const char *scene, const char *mode, const char *tile)
{
    const char *dir = test_dir("l09_same");
    Path id8 = in_dir(dir, "8.png"), d8 = in_dir(dir, "8.pfm"), c8 = in_dir(dir, "8c.png");
    Path id9 = in_dir(dir, "9.png"), d9 = in_dir(dir, "9.pfm"), c9 = in_dir(dir, "9c.png");
    Path out = in_dir(dir, "x.png");
    const char *a8[] = {"--scene", scene, "--width", "160", "--height", "120", "--z-mode", mode,
                        "--out", out.path, "--id-out", id8.path, "--depth-out", d8.path,
                        "--colour-out", c8.path, NULL};
    const char *a9[] = {"--scene", scene, "--width", "160", "--height", "120", "--z-mode", mode,
                        "--tile", tile, "--out", out.path, "--id-out", id9.path, "--depth-out",
                        d9.path, "--colour-out", c9.path, NULL};
    free(run_ok("08_early_z", a8));
    free(run_ok(PROGRAM, a9));
    Image drawn = read_png(id9.path);
    expect_drawn(&drawn, scene);
    image_free(&drawn);
    expect_same_file(id8.path, id9.path, "--id-out");
    expect_same_file(d8.path, d9.path, "--depth-out");
    expect_same_file(c8.path, c9.path, "--colour-out");
}

static void every_scene_and_mode_draws_lesson_08s_pictures(void **state)
{
    (void)state;
    static const char *const MODES[] = {"late", "early", "prepass"};
    for (int s = 0; s < NSCENES; s++)
        for (int m = 0; m < 3; m++)
            same_as_lesson_08(SCENES[s], MODES[m], "8");
}

static void any_tile_size_draws_lesson_08s_pictures(void **state)
{
    (void)state;
    static const char *const TILES[] = {"1", "3", "16", "64"};
    for (int k = 0; k < 4; k++) {
        same_as_lesson_08("city", "early", TILES[k]);
        same_as_lesson_08("crowd", "prepass", TILES[k]);
        same_as_lesson_08("decals", "late", TILES[k]);
    }
}

typedef struct { long tested, passed, failed; } Fragments;

static Fragments fragments_of(const char *out)
{
    Fragments f = {-1, -1, -1};
    const char *line = strstr(out, "  fragments: ");
    if (!line || sscanf(line, "  fragments: %ld tested, %ld passed, %ld failed", &f.tested,
                        &f.passed, &f.failed) != 3)
        fail_msg("no fragments line in:\n%s", out);
    return f;
}

/* city at 800 x 600: lesson 08's failed fragments are the hidden ones
 * (behind the wall, or behind a building); lesson 09 passes exactly as
 * many and tests fewer: the difference was never tested. */
static void city_never_tests_nine_hidden_fragments_in_ten(void **state)
{
    (void)state;
    Path out = in_dir(test_dir("l09_city"), "x.png");
    const char *args[] = {"--scene", "city", "--out", out.path, NULL};
    char *o8 = run_ok("08_early_z", args), *o9 = run_ok(PROGRAM, args);
    Fragments f8 = fragments_of(o8), f9 = fragments_of(o9);
    double share = (double)(f8.tested - f9.tested) / (double)f8.failed;
    printf("  city: lesson 08 tested %ld (%ld failed), lesson 09 %ld: %.4f of the hidden "
           "fragments never tested\n", f8.tested, f8.failed, f9.tested, share);
    expect_at_least(1, f9.passed, "fragments that passed"); /* else both drew nothing */
    expect_at_least(1, f8.failed, "hidden fragments lesson 08 tested");
    expect_count(f8.passed, f9.passed, "fragments passed, as in lesson 08");
    unsigned long long never = 0;
    const char *line = strstr(o9, "fragments never tested ");
    assert_non_null(line);
    assert_true(sscanf(line, "fragments never tested %llu", &never) == 1);
    expect_count(f8.tested - f9.tested, (long)never, "fragments never tested, as printed");
    if (share < 0.9)
        fail_msg("only %.4f of the hidden fragments were never tested", share);
    free(o8);
    free(o9);
}

/* The tile picture of city: the size of the picture plus its legend; the
 * tile at the centre of the wall (pixel 200, 300 of 800 x 600) in one grey
 * all over, brighter than the sky's tiles (the far plane, the depth
 * pictures' background) at the top right. */
static void hiz_picture_shows_the_walls_tiles(void **state)
{
    (void)state;
    const char *dir = test_dir("l09_hiz");
    Path out = in_dir(dir, "x.png"), hiz = in_dir(dir, "hiz.png");
    const char *args[] = {"--scene", "city", "--out", out.path, "--hiz-out", hiz.path, NULL};
    free(run_ok(PROGRAM, args));
    Image im = read_png(hiz.path);
    expect_count(800, im.width, "picture width");
    expect_count(600 + 22, im.height, "picture height, legend included");
    Rgb wall = image_get(&im, 200, 296), sky = image_get(&im, 796, 4);
    for (int y = 296; y < 303; y++)
        for (int x = 200; x < 207; x++) {
            Rgb c = image_get(&im, x, y);
            assert_true(c.r == wall.r && c.g == wall.g && c.b == wall.b);
        }
    assert_true(wall.r == wall.g && wall.g == wall.b && wall.r > 200);
    assert_true(sky.r == DEPTH_BACKGROUND.r && sky.g == DEPTH_BACKGROUND.g &&
                sky.b == DEPTH_BACKGROUND.b);
    image_free(&im);
}

/* The default run (no flag): out/09_hierarchical_z.png, and beside it the
 * same picture with each tile that skipped a triangle tinted. On city the
 * wall's top rows hide nothing (pixel 300, 60: untinted, the picture's own
 * colour) and its middle hides the city (pixel 300, 300: tinted). At 160 x
 * 120 the skip picture is compared with one looked at by eye. */
static void default_run_shows_where_tiles_skipped(void **state)
{
    (void)state;
    const char *dir = test_dir("l09_default");
    const char *none[] = {NULL};
    RunResult r = run_program_in(dir, PROGRAM, none);
    expect_count(0, r.status, "exit status");
    expect_line(r.out, "  wrote out/09_hierarchical_z_skips.png\n");
    run_result_free(&r);
    Image pic = read_png(path_join(dir, "out/09_hierarchical_z.png"));
    Image skips = read_png(path_join(dir, "out/09_hierarchical_z_skips.png"));
    expect_count(800, skips.width, "picture width");
    expect_count(600 + 22, skips.height, "picture height, legend included");
    Rgb a = image_get(&pic, 300, 60), b = image_get(&skips, 300, 60);
    if (a.r != b.r || a.g != b.g || a.b != b.b)
        fail_msg("pixel (300,60), the wall with nothing behind it, is tinted");
    a = image_get(&pic, 300, 300), b = image_get(&skips, 300, 300);
    if (a.r == b.r && a.g == b.g && a.b == b.b)
        fail_msg("pixel (300,300), the wall with the city behind it, is not tinted: no tile "
                 "there skipped a triangle");
    image_free(&pic);
    image_free(&skips);
    Path out = in_dir(dir, "x.png"), skip = in_dir(dir, "skips.png");
    const char *args[] = {"--width", "160", "--height", "120", "--out", out.path, "--skip-out",
                          skip.path, NULL};
    free(run_ok(PROGRAM, args));
    Image im = read_png(skip.path);
    expect_image(&im, GROUP, "skips_city");
    image_free(&im);
}

/* Exact updating reads every tile drawn into again: never a worse bound,
 * so never more fragments tested; crowd's small faces show the difference. */
static void exact_update_tests_no_more_than_conservative(void **state)
{
    (void)state;
    Path out = in_dir(test_dir("l09_exact"), "x.png");
    const char *c[] = {"--scene", "crowd", "--out", out.path, NULL};
    const char *e[] = {"--scene", "crowd", "--hiz-update", "exact", "--out", out.path, NULL};
    char *oc = run_ok(PROGRAM, c), *oe = run_ok(PROGRAM, e);
    Fragments fc = fragments_of(oc), fe = fragments_of(oe);
    printf("  crowd: tested %ld conservative, %ld exact\n", fc.tested, fe.tested);
    assert_true(fe.tested < fc.tested);
    expect_count(fc.passed, fe.passed, "fragments passed");
    free(oc);
    free(oe);
}

static void bad_command_lines_are_refused_with_status_2(void **state)
{
    (void)state;
    const char *dir = test_dir("l09_bad");
    Path out = in_dir(dir, "x.png");
    const char *zero[] = {"--tile", "0", "--out", out.path, NULL};
    expect_run_refused(PROGRAM, zero, 2, "--tile: 0 is out of range (1 to 64)", out.path);
    const char *big[] = {"--tile", "65", "--out", out.path, NULL};
    expect_run_refused(PROGRAM, big, 2, "--tile: 65 is out of range (1 to 64)", out.path);
    const char *word[] = {"--hiz-update", "sometimes", "--out", out.path, NULL};
    expect_run_refused(PROGRAM, word, 2,
                       "--hiz-update: 'sometimes' is not one of conservative, exact", out.path);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_scene_and_mode_draws_lesson_08s_pictures),
        cmocka_unit_test(any_tile_size_draws_lesson_08s_pictures),
        cmocka_unit_test(city_never_tests_nine_hidden_fragments_in_ten),
        cmocka_unit_test(default_run_shows_where_tiles_skipped),
        cmocka_unit_test(hiz_picture_shows_the_walls_tiles),
        cmocka_unit_test(exact_update_tests_no_more_than_conservative),
        cmocka_unit_test(bad_command_lines_are_refused_with_status_2),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
