/* test_program.c: build/bin/06_depth_precision run end to end: the ladder in
 * every format and mapping (its picture, and the fraction of each band where
 * the back plate wins, scored from --id-out as a GPU's picture would be),
 * agreement with lesson 05 at float32 on the other built-in scenes, the
 * precision plot, the labelled ladder (--ladder-out), --far inf, the log
 * mapping, and how it refuses bad input. */
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
#include "harness/ladder.h"
#include "harness/scene.h"
#include "test_support.h"

#define PROGRAM "06_depth_precision"
#define GROUP "06_depth_precision"
#define AGREEMENT_DIFFERING 0L

static const char *const FORMATS[3] = {"unorm16", "unorm24", "float32"};
static const char *const MAPPINGS[2] = {"standard", "reversed"};

/* The depth step at d, near 0.1, far 1000, on paper: one step of z_w over
 * |dz_w/dd| = f n / ((f - n) d^2). unorm: 1 / (2^bits - 1); float32
 * standard: z_w is near 1 past d = 0.2, a step of 2^-24; float32 reversed is
 * not needed here (its steps are below 1e-4 m everywhere up to d = 1000). */
static double paper_step(int format, double d)
{
    double q = format == 0 ? 1 / 65535.0 : 1 / 16777215.0; /* float32 standard ~ unorm24 */
    return q * d * d * (1000 - 0.1) / (1000 * 0.1);
}

static void score_ladder(const char *format, const char *mapping, const char *dir,
                         LadderScore *s, Image *picture)
{
    Path out = in_dir(dir, "ladder.png"), id = in_dir(dir, "ladder_id.png");
    const char *args[] = {"--width", "400", "--height", "300", "--depth-format", format,
                          "--depth-mapping", mapping, "--out", out.path, "--id-out", id.path,
                          NULL};
    free(run_ok(PROGRAM, args));
    Error err;
    if (!ladder_score_id_png(id.path, s, &err))
        fail_msg("%s", err.msg);
    *picture = read_png(out.path);
}

/* Every band draws; where the step is well under the gap (half of it, over
 * the band's +-5% of depth) no pixel of the back plate wins; where it is
 * well over (twice the gap) most do; reversed float32 never lets it win. */
static void ladder_fails_where_the_step_passes_the_gap(void **state)
{
    (void)state;
    const char *dir = test_dir("l06_ladder");
    for (int f = 0; f < 3; f++)
        for (int m = 0; m < 2; m++) {
            LadderScore s;
            Image im;
            score_ladder(FORMATS[f], MAPPINGS[m], dir, &s, &im);
            char name[64];
            snprintf(name, sizeof name, "ladder_%s_%s", FORMATS[f], MAPPINGS[m]);
            expect_image(&im, GROUP, name);
            image_free(&im);
            for (int k = 0; k < LADDER_BANDS; k++) {
                double d = LADDER_DISTANCE[k], wrong = ladder_wrong_fraction(&s, k);
                if (s.front[k] + s.back[k] < 5000)
                    fail_msg("%s: band d = %g covers only %ld pixels", name, d,
                             s.front[k] + s.back[k]);
                bool reversed_float = f == 2 && m == 1;
                if ((reversed_float || paper_step(f, d * 1.06) < LADDER_GAP / 2) && wrong != 0)
                    fail_msg("%s: band d = %g: the back plate wins %.4f of it, step %.3g m is "
                             "under half the gap", name, d, wrong, paper_step(f, d));
                if (!reversed_float && paper_step(f, d * 0.94) > 2 * LADDER_GAP && wrong < 0.5)
                    fail_msg("%s: band d = %g: the back plate wins only %.4f, step %.3g m is "
                             "over twice the gap", name, d, wrong, paper_step(f, d));
            }
        }
}

/* Log in unorm16: the step grows as d, not d^2 (d log(f/n) / 65535 on
 * paper: 0.000141 at d = 1, 0.0422 at d = 300, under the gap), so 16 bits
 * hold every band of the ladder where the standard mapping fails from d = 30. */
static void unorm16_log_holds_every_band_of_the_ladder(void **state)
{
    (void)state;
    const char *dir = test_dir("l06_log");
    Path out = in_dir(dir, "ladder.png"), id = in_dir(dir, "ladder_id.png");
    const char *args[] = {"--width", "400", "--height", "300", "--depth-format", "unorm16",
                          "--depth-mapping", "log", "--out", out.path, "--id-out", id.path,
                          NULL};
    char *text = run_ok(PROGRAM, args);
    expect_line(text, "  depth step (unorm16, log, near 0.1, far 1000): d = 1: 0.000141, "
                      "d = 10: 0.00141, d = 100: 0.0141, d = 300: 0.0422\n");
    free(text);
    LadderScore s;
    Error err;
    if (!ladder_score_id_png(id.path, &s, &err))
        fail_msg("%s", err.msg);
    for (int k = 0; k < LADDER_BANDS; k++) {
        if (s.front[k] + s.back[k] < 5000)
            fail_msg("log: band d = %g covers only %ld pixels", LADDER_DISTANCE[k],
                     s.front[k] + s.back[k]);
        expect_count(0, s.back[k], "pixels of a band where the back plate wins");
    }
    Image im = read_png(out.path);
    expect_image(&im, GROUP, "ladder_unorm16_log");
    image_free(&im);
}

/* The default run: unorm24, standard, the ladder; the summary's steps and bands. */
static void default_run_reports_steps_and_bands(void **state)
{
    (void)state;
    const char *args[] = {NULL};
    RunResult r = run_program_in(test_dir("l06_default"), PROGRAM, args); /* not into out/ */
    expect_count(0, r.status, "exit status");
    const char *out = r.out;
    expect_line(out, "06_depth_precision: scene ladder (12 faces)");
    expect_line(out, "  depth step (unorm24, standard, near 0.1, far 1000): d = 1: 5.96e-07, "
                     "d = 10: 5.96e-05, d = 100: 0.00596, d = 300: 0.0536\n");
    expect_line(out, "  back plate wins (gap 0.05): d = 1: 0.000, d = 3: 0.000, d = 10: 0.000, "
                     "d = 30: 0.000, d = 100: 0.000, d = 300: 0.572\n");
    run_result_free(&r);
}

/* Lesson 05's picture, face for face, at float32 (reversed) on every other
 * built-in scene at 320 x 240: measured, not one pixel differs. Their faces
 * are far apart for float32 z_w; a pixel could change only where two faces
 * store the same float32 z_w and lesson 05's float 1/d tells them apart.
 * Not `decals`: its decals lie on their walls, the same depth, and a GPU's
 * float32 planes make them fight (lesson 07); lesson 05's exact 1/d ties. */
static void float32_agrees_with_lesson_05_on_the_built_in_scenes(void **state)
{
    (void)state;
    const char *dir = test_dir("l06_agree");
    long differing_total = 0;
    for (int i = 0; i < scene_count(); i++) {
        const char *name = scene_at(i)->name;
        if (strcmp(name, "ladder") == 0 || scene_at(i)->coplanar)
            continue;
        Path a = in_dir(dir, "l05.png"), b = in_dir(dir, "l06.png"), o = in_dir(dir, "x.png");
        const char *args5[] = {"--scene", name, "--width", "320", "--height", "240", "--out",
                               o.path, "--id-out", a.path, NULL};
        const char *args6[] = {"--scene", name, "--width", "320", "--height", "240", "--out",
                               o.path, "--id-out", b.path, "--depth-format", "float32",
                               "--depth-mapping", "reversed", NULL};
        free(run_ok("05_clipping", args5));
        free(run_ok(PROGRAM, args6));
        Image ia = read_png(a.path), ib = read_png(b.path);
        expect_drawn(&ib, name);
        long differing = 0;
        for (size_t p = 0; p < (size_t)ia.width * (size_t)ia.height * 3; p += 3)
            differing += memcmp(ia.rgb + p, ib.rgb + p, 3) != 0;
        printf("  %s: %ld pixels differ from lesson 05\n", name, differing);
        differing_total += differing;
        image_free(&ia);
        image_free(&ib);
    }
    expect_count(AGREEMENT_DIFFERING, differing_total, "pixels that differ from lesson 05");
}

static void precision_plot_is_written(void **state)
{
    (void)state;
    const char *dir = test_dir("l06_plot");
    Path plot = in_dir(dir, "plot.png"), out = in_dir(dir, "x.png");
    const char *args[] = {"--width", "80", "--height", "60", "--out", out.path,
                          "--precision-plot", plot.path, NULL};
    free(run_ok(PROGRAM, args));
    Image im = read_png(plot.path);
    expect_image(&im, GROUP, "precision_plot");
    image_free(&im);
}

/* A near plane of 1e-200: depth steps underflow to 0, which a log axis
 * cannot show; the plot leaves them out and ends (it used to loop for ever). */
static void precision_plot_of_a_tiny_near_plane_ends(void **state)
{
    (void)state;
    const char *dir = test_dir("l06_plot_tiny");
    Path plot = in_dir(dir, "plot.png"), out = in_dir(dir, "x.png");
    const char *args[] = {"--width", "8", "--height", "8", "--near", "1e-200", "--out", out.path,
                          "--precision-plot", plot.path, NULL};
    free(run_ok(PROGRAM, args));
    Image im = read_png(plot.path);
    assert_true(im.width > 100 && im.height > 100);
    image_free(&im);
}

/* --ladder-out: the picture of --out with each band's d beside its plates
 * and a key in a band of 22 rows under it. At the ladder's camera every
 * label lies on the background: no pixel of a plate changes. Only the
 * ladder has bands to label. */
static void ladder_out_labels_the_background_only(void **state)
{
    (void)state;
    const char *dir = test_dir("l06_ladder_out");
    Path out = in_dir(dir, "x.png"), id = in_dir(dir, "id.png"), ladder = in_dir(dir, "l.png");
    const char *args[] = {"--width", "400", "--height", "300", "--depth-format", "unorm16",
                          "--out", out.path, "--id-out", id.path, "--ladder-out", ladder.path,
                          NULL};
    free(run_ok(PROGRAM, args));
    Image plain = read_png(out.path), faces = read_png(id.path), labelled = read_png(ladder.path);
    if (labelled.width != 400 || labelled.height != 300 + 22)
        fail_msg("--ladder-out is %d x %d, wanted 400 x 322", labelled.width, labelled.height);
    long labels = 0;
    for (int y = 0; y < 300; y++)
        for (int x = 0; x < 400; x++) {
            Rgb a = image_get(&plain, x, y), b = image_get(&labelled, x, y);
            Rgb f = image_get(&faces, x, y);
            if (a.r == b.r && a.g == b.g && a.b == b.b)
                continue;
            labels++;
            if (f.r || f.g || f.b)
                fail_msg("--ladder-out: pixel (%d, %d), on a plate, differs from --out", x, y);
        }
    if (labels < 6 * 5 * 7) /* six labels of at least five glyphs' pixels */
        fail_msg("--ladder-out: only %ld pixels differ from --out: no labels?", labels);
    image_free(&plain);
    image_free(&faces);
    image_free(&labelled);
    Path never = in_dir(dir, "never.png");
    const char *cubes[] = {"--scene", "cubes", "--out", out.path, "--ladder-out", never.path,
                           NULL};
    expect_run_refused(PROGRAM, cubes, 2, "--ladder-out labels the ladder's bands: it needs "
                                          "--scene ladder", never.path);
}

/* --far inf with reversed: z_w = n/d, and the ladder is as clean as at far 1000. */
static void far_inf_with_reversed_float32(void **state)
{
    (void)state;
    const char *dir = test_dir("l06_inf");
    Path out = in_dir(dir, "x.png");
    const char *args[] = {"--width", "200", "--height", "150", "--out", out.path,
                          "--depth-format", "float32", "--depth-mapping", "reversed",
                          "--far", "inf", NULL};
    char *text = run_ok(PROGRAM, args);
    expect_line(text, "  depth step (float32, reversed, near 0.1, far inf): d = 1: 7.45e-08");
    expect_line(text, "d = 100: 0.000, d = 300: 0.000\n");
    free(text);
}

/* --far 200: the band at d = 300 lies beyond the far plane. It drew no
 * pixel, so it has no share of back-plate pixels, not a share of 0. */
static void a_band_beyond_the_far_plane_is_not_drawn_and_says_so(void **state)
{
    (void)state;
    const char *dir = test_dir("l06_far_200");
    Path out = in_dir(dir, "x.png");
    const char *args[] = {"--width", "200", "--height", "150", "--out", out.path, "--far", "200",
                          NULL};
    char *text = run_ok(PROGRAM, args);
    expect_line(text, "d = 100: 0.000, d = 300: not drawn\n");
    free(text);
}

static void bad_command_lines_are_refused_with_status_2(void **state)
{
    (void)state;
    const char *dir = test_dir("l06_bad");
    Path out = in_dir(dir, "never.png");
    const char *fmt[] = {"--depth-format", "unorm32", "--out", out.path, NULL};
    expect_run_refused(PROGRAM, fmt, 2,
                       "--depth-format: 'unorm32' is not one of unorm16, unorm24, float32",
                       out.path);
    const char *map[] = {"--depth-mapping", "linear", "--out", out.path, NULL};
    expect_run_refused(PROGRAM, map, 2,
                       "--depth-mapping: 'linear' is not one of standard, reversed, log", out.path);
    const char *inf[] = {"--far", "inf", "--out", out.path, NULL};
    expect_run_refused(PROGRAM, inf, 2, "--far inf needs --depth-mapping reversed (standard "
                                        "divides by far - near, log by log(far / near))", out.path);
    const char *log_inf[] = {"--far", "inf", "--depth-mapping", "log", "--out", out.path, NULL};
    expect_run_refused(PROGRAM, log_inf, 2, "--far inf needs --depth-mapping reversed (standard "
                                            "divides by far - near, log by log(far / near))",
                       out.path);
    const char *nan[] = {"--far", "nan", "--depth-mapping", "reversed", "--out", out.path, NULL};
    expect_run_refused(PROGRAM, nan, 2, "--far: 'nan' is not a finite number", out.path);
    const char *neg[] = {"--far", "-inf", "--depth-mapping", "reversed", "--out", out.path, NULL};
    expect_run_refused(PROGRAM, neg, 2, "--far: '-inf' is not a finite number", out.path);
    const char *same[] = {"--out", out.path, "--precision-plot", out.path, NULL};
    char message[sizeof out.path + 64];
    snprintf(message, sizeof message, "--out and --precision-plot both name %s", out.path);
    expect_run_refused(PROGRAM, same, 2, message, out.path);
    const char *none[] = {"--depth-format", NULL};
    expect_run_error(PROGRAM, none, 2, "06_depth_precision: error: --depth-format needs a value\n");
    /* Lesson 05 takes no reversed mapping: inf stays refused there. */
    const char *l05[] = {"--far", "inf", "--out", out.path, NULL};
    expect_run_refused("05_clipping", l05, 2, "--far: 'inf' is not a finite number", out.path);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(ladder_fails_where_the_step_passes_the_gap),
        cmocka_unit_test(unorm16_log_holds_every_band_of_the_ladder),
        cmocka_unit_test(default_run_reports_steps_and_bands),
        cmocka_unit_test(float32_agrees_with_lesson_05_on_the_built_in_scenes),
        cmocka_unit_test(precision_plot_is_written),
        cmocka_unit_test(precision_plot_of_a_tiny_near_plane_ends),
        cmocka_unit_test(ladder_out_labels_the_background_only),
        cmocka_unit_test(far_inf_with_reversed_float32),
        cmocka_unit_test(a_band_beyond_the_far_plane_is_not_drawn_and_says_so),
        cmocka_unit_test(bad_command_lines_are_refused_with_status_2),
    };
    return cmocka_run_group_tests_name("06_depth_precision program", tests, NULL, NULL);
}
