/* test_program.c: build/bin/08_early_z run end to end. The picture is the
 * same in every z-mode and sort (and lesson 07's on a scene without
 * cutouts); the prepass shades exactly the covered pixels; early-Z with
 * front-to-back sorting shades fewer than early-Z unsorted, which shades
 * fewer than late-Z (the measured counts); a cutout in front of a face is
 * right in every mode and wrong with --bug early-z-with-discard (named
 * pixels); the heat map; bad input. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness/image_io.h"
#include "expect.h"
#include "test_support.h"

#define PROGRAM "08_early_z"

static const char *const MODES[3] = {"late", "early", "prepass"};
static const char *const SORTS[3] = {"none", "front-to-back", "back-to-front"};

typedef struct { long tested, shaded, covered; } Counts;

static Counts counts_of(const char *out)
{
    Counts c = {-1, -1, -1};
    const char *line = strstr(out, ": fragments tested ");
    if (!line || sscanf(line, ": fragments tested %ld, shaded %ld, pixels covered %ld",
                        &c.tested, &c.shaded, &c.covered) != 3)
        fail_msg("no counts line in:\n%s", out);
    return c;
}

/* crowd at 160 x 120 in a mode and sort; the pictures into dir. */
static Counts run_crowd(const char *mode, const char *sort, const char *colour, const char *id,
                        const char *depth)
{
    const char *args[20] = {"--width", "160", "--height", "120", "--z-mode", mode, "--sort", sort,
                            "--out", in_dir(test_dir("l08_runs"), "x.png").path};
    int n = 10;
    const char *extra[3][2] = {{"--colour-out", colour}, {"--id-out", id}, {"--depth-out", depth}};
    for (int k = 0; k < 3; k++)
        if (extra[k][1]) {
            args[n++] = extra[k][0];
            args[n++] = extra[k][1];
        }
    args[n] = NULL;
    char *out = run_ok(PROGRAM, args);
    Counts c = counts_of(out);
    free(out);
    return c;
}

static long differing_pixels(const Image *a, const Image *b)
{
    long n = 0;
    for (int y = 0; y < a->height; y++)
        for (int x = 0; x < a->width; x++) {
            Rgb p = image_get(a, x, y), q = image_get(b, x, y);
            n += p.r != q.r || p.g != q.g || p.b != q.b;
        }
    return n;
}

/* The three modes of one sort give the same ids and colours, exactly. Sorts
 * may differ only where two faces tie (the same stored depth: the first one
 * drawn keeps the pixel), at a few pixels where faces of a box meet. */
static void every_mode_and_sort_gives_the_same_picture(void **state)
{
    (void)state;
    const char *dir = test_dir("l08_same");
    Image first_id = {0};
    float *first_depth = NULL;
    for (int s = 0; s < 3; s++) {
        Image id0 = {0}, colour0 = {0};
        for (int m = 0; m < 3; m++) {
            Path colour = in_dir(dir, "c.png"), id = in_dir(dir, "id.png"),
                 depth = in_dir(dir, "d.pfm");
            run_crowd(MODES[m], SORTS[s], colour.path, id.path, depth.path);
            Image c = read_png(colour.path), i = read_png(id.path);
            if (m == 0) {
                colour0 = c, id0 = i;
            } else {
                expect_count(0, differing_pixels(&colour0, &c), "colour pixels unlike late-Z's");
                expect_count(0, differing_pixels(&id0, &i), "id pixels unlike late-Z's");
                image_free(&c);
                image_free(&i);
            }
            if (s == 0 && m == 0) {
                int w, h;
                Error err;
                assert_true(read_pfm(&first_depth, &w, &h, depth.path, &err));
                first_id = read_png(id.path);
            } else if (m == 0) {
                float *d;
                int w, h;
                Error err;
                assert_true(read_pfm(&d, &w, &h, depth.path, &err));
                long ties = 0;
                for (int y = 0; y < h; y++)
                    for (int x = 0; x < w; x++)
                        if (face_at(&id0, x, y) != face_at(&first_id, x, y)) {
                            size_t k = (size_t)y * (size_t)w + (size_t)x;
                            if (d[k] != first_depth[k])
                                fail_msg("sort %s: pixel %d,%d shows another face at another "
                                         "depth", SORTS[s], x, y);
                            ties++;
                        }
                expect_at_most(4, ties, "pixels where a tie went to another face");
                free(d);
            }
        }
        image_free(&colour0);
        image_free(&id0);
    }
    image_free(&first_id);
    free(first_depth);
}

/* city has no cutout: lesson 08 draws lesson 07's picture, ids and colours. */
static void lesson_07s_picture(void **state)
{
    (void)state;
    const char *dir = test_dir("l08_07");
    Path out7 = in_dir(dir, "7.png"), id7 = in_dir(dir, "7id.png");
    Path out8 = in_dir(dir, "8.png"), id8 = in_dir(dir, "8id.png");
    const char *a7[] = {"--scene", "city", "--width", "160", "--height", "120", "--out",
                        out7.path, "--id-out", id7.path, NULL};
    free(run_ok("07_depth_bias", a7));
    for (int m = 0; m < 3; m++) {
        const char *a8[] = {"--scene", "city", "--width", "160", "--height", "120", "--z-mode",
                            MODES[m], "--out", out8.path, "--id-out", id8.path, NULL};
        free(run_ok(PROGRAM, a8));
        Image p7 = read_png(out7.path), p8 = read_png(out8.path);
        Image i7 = read_png(id7.path), i8 = read_png(id8.path);
        expect_drawn(&i8, MODES[m]);
        expect_count(0, differing_pixels(&p7, &p8), "pixels unlike lesson 07's");
        expect_count(0, differing_pixels(&i7, &i8), "id pixels unlike lesson 07's");
        image_free(&p7), image_free(&p8), image_free(&i7), image_free(&i8);
    }
}

/* The prepass shades each covered pixel once: covered counted here from
 * the id picture, not taken from the program. */
static void prepass_shades_exactly_the_covered_pixels(void **state)
{
    (void)state;
    Path id = in_dir(test_dir("l08_prepass"), "id.png");
    for (int s = 0; s < 3; s++) {
        Counts c = run_crowd("prepass", SORTS[s], NULL, id.path, NULL);
        Image im = read_png(id.path);
        long covered = faces_shown(&im);
        long quarter = (long)im.width * im.height / 4; /* the crowd covers more than half */
        image_free(&im);
        expect_at_least(quarter, covered, "pixels covered (from --id-out)");
        expect_count(covered, c.covered, "pixels covered (from --id-out)");
        expect_count(covered, c.shaded, "fragments shaded by the prepass");
    }
}

/* Measured on crowd at 160 x 120: late shades every fragment it tests and
 * the cutouts' discarded ones; early only what passes, fewer when nearer
 * faces come first. */
static void early_z_and_sorting_shade_less(void **state)
{
    (void)state;
    Counts late = run_crowd("late", "none", NULL, NULL, NULL);
    Counts early = run_crowd("early", "none", NULL, NULL, NULL);
    Counts sorted = run_crowd("early", "front-to-back", NULL, NULL, NULL);
    Counts back = run_crowd("early", "back-to-front", NULL, NULL, NULL);
    printf("  shaded: late %ld, early %ld, early front-to-back %ld, back-to-front %ld; "
           "covered %ld\n", late.shaded, early.shaded, sorted.shaded, back.shaded, late.covered);
    assert_true(early.shaded < late.shaded);
    assert_true(sorted.shaded < early.shaded);
    assert_true(back.shaded > early.shaded);
    assert_true(sorted.shaded >= sorted.covered);
    expect_count(late.tested, early.tested, "fragments tested, early as late");
}

/* A cutout quad (group cutout, drawn first) in front of a larger quad. The
 * camera is fitted to the pair and looks at the centre (80, 60) of 160 x 120:
 * (80, 60) lies in a hole (squares of 4 pixels, (80/4 xor 60/4) odd), (84, 60)
 * on the cutout. Face 0 is the cutout, 1 the quad behind. */
static const char CUTOUT_OBJ[] = "g cutout\n"
                                 "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n"
                                 "g back\n"
                                 "v -2 -2 -2\nv 2 -2 -2\nv 2 2 -2\nv -2 2 -2\nf 5 6 7 8\n";

static void run_cutout(const char *mode, const char *bug, const char *id)
{
    const char *dir = test_dir("l08_cutout_run");
    Path obj = in_dir(dir, "cutout.obj"), out = in_dir(dir, "x.png");
    write_text(obj.path, CUTOUT_OBJ);
    const char *args[16] = {"--obj", obj.path, "--width", "160", "--height", "120", "--z-mode", mode,
                            "--out", out.path, "--id-out", id};
    if (bug) {
        args[12] = "--bug";
        args[13] = bug;
    }
    free(run_ok(PROGRAM, args));
}

static void cutout_in_front_is_right_in_every_mode(void **state)
{
    (void)state;
    Path id = in_dir(test_dir("l08_cutout"), "id.png");
    for (int m = 0; m < 3; m++) {
        run_cutout(MODES[m], NULL, id.path);
        Image im = read_png(id.path);
        expect_face_at(&im, 80, 60, 1, "the quad behind, through a hole");
        expect_face_at(&im, 84, 60, 0, "the cutout");
        image_free(&im);
    }
}

static void early_z_with_discard_shows_holes_that_hide(void **state)
{
    (void)state;
    Path id = in_dir(test_dir("l08_cutout"), "id.png");
    run_cutout("early", "early-z-with-discard", id.path);
    Image im = read_png(id.path);
    expect_face_at(&im, 80, 60, -1, "nothing: the hole's depth hides the quad behind");
    expect_face_at(&im, 84, 60, 0, "the cutout");
    image_free(&im);
}

/* The prepass's heat map: every covered pixel shaded once (the colour of 1),
 * the rest 0, and the legend band under the picture. */
static void prepass_heat_map_is_all_ones(void **state)
{
    (void)state;
    const char *dir = test_dir("l08_heat");
    Path heat = in_dir(dir, "heat.png"), id = in_dir(dir, "id.png");
    const char *args[] = {"--width", "160", "--height", "120", "--z-mode", "prepass", "--out",
                          in_dir(dir, "x.png").path, "--id-out", id.path, "--shade-count-out",
                          heat.path, NULL};
    free(run_ok(PROGRAM, args));
    Image h = read_png(heat.path), i = read_png(id.path);
    assert_true(h.width >= 160); /* wider when its legend needs it (harness/legend.h) */
    assert_true(h.height > 120); /* the legend */
    Rgb once = {40, 90, 200}, never = {0, 0, 0};
    for (int y = 0; y < 120; y++)
        for (int x = 0; x < 160; x++)
            expect_pixel(&h, x, y, face_at(&i, x, y) == -1 ? never : once, "times shaded");
    expect_at_least(160 * 120 / 4, faces_shown(&i),
                    "pixels covered: the crowd covers more than half");
    image_free(&h);
    image_free(&i);
}

static void bad_command_lines_are_refused_with_status_2(void **state)
{
    (void)state;
    Path out = in_dir(test_dir("l08_bad"), "x.png");
    const char *mode[] = {"--z-mode", "never", "--out", out.path, NULL};
    expect_run_refused(PROGRAM, mode, 2, "--z-mode: 'never' is not one of late, early, prepass",
                       out.path);
    const char *sort[] = {"--sort", "random", "--out", out.path, NULL};
    expect_run_refused(PROGRAM, sort, 2,
                       "--sort: 'random' is not one of none, front-to-back, back-to-front",
                       out.path);
    const char *bug[] = {"--bug", "no-clip", "--out", out.path, NULL};
    expect_run_refused(PROGRAM, bug, 2, "--bug: 'no-clip' is not one of early-z-with-discard",
                       out.path);
    const char *none[] = {"--z-mode", NULL};
    expect_run_error(PROGRAM, none, 2, "08_early_z: error: --z-mode needs a value\n");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_mode_and_sort_gives_the_same_picture),
        cmocka_unit_test(lesson_07s_picture),
        cmocka_unit_test(prepass_shades_exactly_the_covered_pixels),
        cmocka_unit_test(early_z_and_sorting_shade_less),
        cmocka_unit_test(cutout_in_front_is_right_in_every_mode),
        cmocka_unit_test(early_z_with_discard_shows_holes_that_hide),
        cmocka_unit_test(prepass_heat_map_is_all_ones),
        cmocka_unit_test(bad_command_lines_are_refused_with_status_2),
    };
    return cmocka_run_group_tests_name("08_early_z program", tests, NULL, NULL);
}
