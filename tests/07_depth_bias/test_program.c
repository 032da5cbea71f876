/* test_program.c: build/bin/07_depth_bias run end to end on the decals
 * scene: without bias the decals lose a good share of their pixels (the
 * measured number), units alone fix the sign that faces the camera but not
 * the grazing floor lines, the page's recommended bias wins every decal all
 * of its pixels in every format, far too much bias shows the poster through
 * the pillar (named pixels); faces are drawn exactly as lesson 06 draws them
 * when nothing is offset; the four teaching pictures; bad input; a decal of
 * more corners than clip_polygon takes is biased as a quad is. */
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
#include "expect.h"
#include "test_support.h"

#define PROGRAM "07_depth_bias"
#define GROUP "07_depth_bias"

/* The page's recommended bias, standard mapping: one slope and one step
 * toward the camera (reversed: the same with the signs turned). */
#define RECOMMENDED "-1,-1"
#define RECOMMENDED_REVERSED "1,1"
#define TOO_MUCH "-1000,-1000"
#define UNITS_ONLY "0,-2"

/* In decals (the scene's order): face 4 the poster behind the pillar, 6 the
 * third poster on the left wall, 27 the left edge line and 29 the first
 * stripe of the zebra crossing (on the floor, seen at a grazing angle), 40
 * the pillar's face toward the camera. */
#define POSTER_BEHIND_PILLAR 4
#define WALL_POSTER 6
#define EDGE_LINE 27
#define ZEBRA_STRIPE 29
#define PILLAR_FRONT 40

/* Measured at 400 x 300, unorm24, standard: the decals' pixels (the same
 * with any bias: they are defined without it), and those they win without. */
#define DECAL_PIXELS 6306L
#define NO_BIAS_WON 1740L

typedef struct { long won, pixels, beyond; } DecalTotals;

static char *run_decals(const char *offset, const char *format, const char *mapping,
                        const char *id_out, const char *out_png)
{
    const char *dir = test_dir("l07_runs");
    Path out = in_dir(dir, "x.png");
    const char *args[16] = {"--width", "400", "--height", "300", "--polygon-offset", offset,
                            "--depth-format", format, "--depth-mapping", mapping, "--out",
                            out_png ? out_png : out.path};
    int n = 12;
    if (id_out) {
        args[n++] = "--id-out";
        args[n++] = id_out;
    }
    args[n] = NULL;
    return run_ok(PROGRAM, args);
}

static DecalTotals totals_of(const char *out)
{
    DecalTotals t = {-1, -1, -1};
    const char *line = strstr(out, "  decals: win ");
    if (!line || sscanf(line, "  decals: win %ld of their %ld pixels (%*f), and %ld pixels",
                        &t.won, &t.pixels, &t.beyond) != 3)
        fail_msg("no decals line in:\n%s", out);
    observe_value("decal pixels won", t.won);
    observe_value("decal pixels", t.pixels);
    observe_value("pixels won beyond", t.beyond);
    return t;
}

/* The share the summary gives face f: " f: 0.123" after a space. */
static double share_of(const char *out, int face)
{
    char key[32];
    snprintf(key, sizeof key, " %d: ", face);
    const char *at = strstr(out, key);
    double share;
    if (!at || sscanf(at + strlen(key), "%lf", &share) != 1)
        fail_msg("no share for face %d in:\n%s", face, out);
    observe_number("share", share);
    return share;
}

/* Without bias, unorm24: the decals win 2111 of their 6306 pixels, about
 * a third (measured). */
static void without_bias_decals_lose_a_good_share(void **state)
{
    (void)state;
    char *out = run_decals("0,0", "unorm24", "standard", NULL, NULL);
    DecalTotals t = totals_of(out);
    printf("  no bias: %ld of %ld, %ld beyond\n", t.won, t.pixels, t.beyond);
    expect_count(NO_BIAS_WON, t.won, "decal pixels won without bias (measured)");
    expect_count(DECAL_PIXELS, t.pixels, "decal pixels (measured)");
    assert_true(t.won < t.pixels / 2);
    expect_count(0, t.beyond, "pixels won beyond the decals' own");
    free(out);
}

/* Units alone: a poster on the wall is clean; markings on the floor, seen
 * at a grazing angle, still fight (measured: the poster 0.000 without bias
 * and 1.000 with 0,-2; the edge line 0.199 and the stripe 0.611 with it). */
static void units_only_fix_the_posters_not_the_floor(void **state)
{
    (void)state;
    char *none = run_decals("0,0", "unorm24", "standard", NULL, NULL);
    char *out = run_decals(UNITS_ONLY, "unorm24", "standard", NULL, NULL);
    if (!(share_of(none, WALL_POSTER) < 0.5))
        fail_msg("without bias the poster wins %.3f of its pixels: no fight to fix",
                 share_of(none, WALL_POSTER));
    if (share_of(out, WALL_POSTER) != 1.0)
        fail_msg("units only: the poster wins %.3f of its pixels, not all",
                 share_of(out, WALL_POSTER));
    if (!(share_of(out, EDGE_LINE) < 0.5 && share_of(out, ZEBRA_STRIPE) < 0.9))
        fail_msg("units only: an edge line and a stripe win %.3f and %.3f: the grazing floor "
                 "should still fight", share_of(out, EDGE_LINE), share_of(out, ZEBRA_STRIPE));
    free(none);
    free(out);
}

/* The recommended bias: every decal wins every one of its pixels, in every
 * format, standard and reversed. */
static void recommended_bias_wins_every_decal_pixel(void **state)
{
    (void)state;
    static const char *const FORMATS[3] = {"unorm16", "unorm24", "float32"};
    for (int f = 0; f < 3; f++)
        for (int m = 0; m < 2; m++) {
            const char *mapping = m ? "reversed" : "standard";
            char *out = run_decals(m ? RECOMMENDED_REVERSED : RECOMMENDED, FORMATS[f], mapping,
                                   NULL, NULL);
            DecalTotals t = totals_of(out);
            printf("  %s %s: %ld of %ld, %ld beyond\n", FORMATS[f], mapping, t.won, t.pixels,
                   t.beyond);
            if (t.won != t.pixels || (f == 1 && t.pixels != DECAL_PIXELS))
                fail_msg("%s %s: the decals win %ld of their %ld pixels", FORMATS[f], mapping,
                         t.won, t.pixels);
            free(out);
        }
}

/* Far too much bias: where the pillar stands 0.25 in front of the first
 * poster, the poster wins. With the recommended bias the pillar does. */
static void too_much_bias_shows_the_poster_through_the_pillar(void **state)
{
    (void)state;
    static const int PIXELS[][2] = {{70, 120}, {70, 140}, {72, 150}};
    const char *dir = test_dir("l07_too_much");
    Path ok = in_dir(dir, "ok.png"), bad = in_dir(dir, "bad.png");
    free(run_decals(RECOMMENDED, "unorm24", "standard", ok.path, NULL));
    char *out = run_decals(TOO_MUCH, "unorm24", "standard", bad.path, NULL);
    Image a = read_png(ok.path), b = read_png(bad.path);
    for (size_t k = 0; k < sizeof PIXELS / sizeof PIXELS[0]; k++) {
        int x = PIXELS[k][0], y = PIXELS[k][1];
        if (face_at(&a, x, y) != PILLAR_FRONT)
            fail_msg("(%d,%d), recommended bias: face %d, not the pillar", x, y, face_at(&a, x, y));
        if (face_at(&b, x, y) != POSTER_BEHIND_PILLAR)
            fail_msg("(%d,%d), too much bias: face %d, not the poster", x, y, face_at(&b, x, y));
    }
    assert_true(totals_of(out).beyond > 300); /* measured: 628 */
    image_free(&a);
    image_free(&b);
    free(out);
}

/* No bias: every built-in scene exactly as lesson 06 draws it at unorm24,
 * standard (the decals' own faces too: o = 0 changes no z_w). */
static void without_bias_lesson_06s_picture(void **state)
{
    (void)state;
    const char *dir = test_dir("l07_agree");
    long differing_total = 0;
    for (int i = 0; i < scene_count(); i++) {
        const char *name = scene_at(i)->name;
        Path a = in_dir(dir, "l06.png"), b = in_dir(dir, "l07.png"), o = in_dir(dir, "x.png");
        const char *args6[] = {"--scene", name, "--width", "320", "--height", "240", "--out",
                               o.path, "--id-out", a.path, NULL};
        const char *args7[] = {"--scene", name, "--width", "320", "--height", "240", "--out",
                               o.path, "--id-out", b.path, NULL};
        free(run_ok("06_depth_precision", args6));
        free(run_ok(PROGRAM, args7));
        Image ia = read_png(a.path), ib = read_png(b.path);
        expect_drawn(&ib, name);
        long differing = 0;
        for (size_t p = 0; p < (size_t)ia.width * (size_t)ia.height * 3; p += 3)
            differing += memcmp(ia.rgb + p, ib.rgb + p, 3) != 0;
        if (differing)
            printf("  %s: %ld pixels differ from lesson 06\n", name, differing);
        differing_total += differing;
        image_free(&ia);
        image_free(&ib);
    }
    expect_count(0, differing_total, "pixels that differ from lesson 06");
}

/* The page's four pictures: no bias, units only, recommended, far too much. */
static void teaching_pictures(void **state)
{
    (void)state;
    static const char *const OFFSETS[4] = {"0,0", UNITS_ONLY, RECOMMENDED, TOO_MUCH};
    static const char *const NAMES[4] = {"no_bias", "units_only", "recommended", "too_much"};
    const char *dir = test_dir("l07_pictures");
    for (int k = 0; k < 4; k++) {
        Path out = in_dir(dir, "picture.png");
        free(run_decals(OFFSETS[k], "unorm24", "standard", NULL, out.path));
        Image im = read_png(out.path);
        expect_image(&im, GROUP, NAMES[k]);
        image_free(&im);
    }
}

static void bad_command_lines_are_refused_with_status_2(void **state)
{
    (void)state;
    const char *dir = test_dir("l07_bad");
    Path out = in_dir(dir, "never.png");
    const char *one[] = {"--polygon-offset", "1", "--out", out.path, NULL};
    expect_run_refused(PROGRAM, one, 2, "--polygon-offset: '1' is not two numbers FACTOR,UNITS",
                       out.path);
    const char *nan[] = {"--polygon-offset", "1,nan", "--out", out.path, NULL};
    expect_run_refused(PROGRAM, nan, 2, "--polygon-offset (UNITS): 'nan' is not a finite number",
                       out.path);
    const char *three[] = {"--polygon-offset", "1,2,3", "--out", out.path, NULL};
    expect_run_refused(PROGRAM, three, 2,
                       "--polygon-offset (UNITS): '2,3' is not a finite number", out.path);
    /* A number of 70 digits is one number: a finite one, taken. */
    const char *digits70 = "1111111111111111111111111111111111111111111111111111111111111111111111";
    char long_offset[96];
    snprintf(long_offset, sizeof long_offset, "%s,1", digits70);
    const char *taken[] = {"--polygon-offset", long_offset, "--width", "16", "--height", "12",
                           "--out", out.path, NULL};
    free(run_ok(PROGRAM, taken));
    remove(out.path);
    const char *word[] = {"--polygon-offset", "a,1", "--out", out.path, NULL};
    expect_run_refused(PROGRAM, word, 2,
                       "--polygon-offset (FACTOR): 'a' is not a finite number", out.path);
    const char *inf[] = {"--offset-clamp", "inf", "--out", out.path, NULL};
    expect_run_refused(PROGRAM, inf, 2, "--offset-clamp: 'inf' is not a finite number",
                       out.path);
    const char *fmt[] = {"--depth-format", "unorm32", "--out", out.path, NULL};
    expect_run_refused(PROGRAM, fmt, 2,
                       "--depth-format: 'unorm32' is not one of unorm16, unorm24, float32",
                       out.path);
    /* Lesson 06's log depth has no plane of z_w for the bias to use. */
    const char *log_depth[] = {"--depth-mapping", "log", "--out", out.path, NULL};
    expect_run_refused(PROGRAM, log_depth, 2,
                       "--depth-mapping log is lesson 06's: a depth written per fragment has no "
                       "plane to offset or to test early; here standard or reversed", out.path);
    const char *none[] = {"--polygon-offset", NULL};
    expect_run_error(PROGRAM, none, 2, "07_depth_bias: error: --polygon-offset needs a value\n");
}

/* A decal of 100 corners (more than clip_polygon takes: it is clipped as its
 * triangles) on a square drawn before it: with the recommended bias every
 * fragment of it wins. Its bias used to be 0, and 479 of them lost. */
#define TURN 6.283185307179586 /* 2 pi */

static void a_decal_of_many_corners_is_biased_too(void **state)
{
    (void)state;
    const char *dir = test_dir("07_many_corners");
    Path obj = in_dir(dir, "disc.obj"), out = in_dir(dir, "out.png");
    char text[8192];
    int used = snprintf(text, sizeof text, "v -2 -2 0\nv 2 -2 0\nv 2 2 0\nv -2 2 0\nf 1 2 3 4\n");
    for (int i = 0; i < 100; i++)
        used += snprintf(text + used, sizeof text - (size_t)used, "v %.17g %.17g 0\n",
                         cos(TURN * i / 100), sin(TURN * i / 100));
    used += snprintf(text + used, sizeof text - (size_t)used, "g decal\nf");
    for (int i = 0; i < 100; i++)
        used += snprintf(text + used, sizeof text - (size_t)used, " %d", 5 + i);
    snprintf(text + used, sizeof text - (size_t)used, "\n");
    write_text(obj.path, text);
    const char *args[] = {"--obj", obj.path, "--eye", "0.5,0.3,5", "--target", "0,0,0",
                          "--polygon-offset", RECOMMENDED, "--width", "64", "--height", "48",
                          "--out", out.path, NULL};
    char *summary = run_ok(PROGRAM, args);
    long tested = -1, passed = -1, failed = -1;
    const char *line = strstr(summary, "fragments: ");
    if (!line || sscanf(line, "fragments: %ld tested, %ld passed, %ld failed", &tested, &passed,
                        &failed) != 3)
        fail_msg("no fragments line in:\n%s", summary);
    expect_count(3045, tested, "fragments tested, the base and the decal of 100 corners");
    expect_count(0, failed, "fragments of the decal of 100 corners lost to its base");
    free(summary);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(without_bias_decals_lose_a_good_share),
        cmocka_unit_test(units_only_fix_the_posters_not_the_floor),
        cmocka_unit_test(recommended_bias_wins_every_decal_pixel),
        cmocka_unit_test(a_decal_of_many_corners_is_biased_too),
        cmocka_unit_test(too_much_bias_shows_the_poster_through_the_pillar),
        cmocka_unit_test(without_bias_lesson_06s_picture),
        cmocka_unit_test(teaching_pictures),
        cmocka_unit_test(bad_command_lines_are_refused_with_status_2),
    };
    return cmocka_run_group_tests_name("07_depth_bias program", tests, NULL, NULL);
}
